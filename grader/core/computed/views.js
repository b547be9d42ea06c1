// A view of the sphere read for its shading: is it lit (a clear spread of brightness, or a clean
// diffuse fit with a clear diffuse term), and its diffuse fit. Pure: the gatherers use it to decide
// how long to sample the orbit, the audits to judge the views kept.
import { analyse, samples, shadeFit } from '../measure.js';
import { memo } from './memo.js';
import { HALF_TURN } from '../units.js';

/**
 * { an, fit, lit } for a picture: `fit` over a sparse fitSamples samples. A light from the eye's side
 * spreads brightness little over the disc (n·w_i from 0.5 to 1 in the samples): a clean fit with
 * a clear diffuse term is lit too. A silhouette too coarse to read shading from is never lit.
 */
export const litView = memo((img, thresholds) => {
  const an = analyse(img, thresholds);
  if (an.blank) return { an, fit: null, lit: false };
  const fit = shadeFit(samples(img, an, thresholds, { max: thresholds.fitSamples }), thresholds);
  const lit = !!fit && an.roundness < thresholds.orbitCoarseRoundness && (fit.spread >= thresholds.clearlyLitSpread ||
    (fit.spread >= thresholds.evenSpread && fit.r2 >= thresholds.diffuseR2 && fit.diffuse >= thresholds.diffuseMin));
  return { an, fit, lit };
});

/** A picture's diffuse fit over all its samples. */
export const fullFit = memo((img, thresholds) => {
  const an = analyse(img, thresholds);
  return an.blank ? null : shadeFit(samples(img, an, thresholds), thresholds);
});

/** The light's angle from the viewer (+z), in degrees. */
export const lightAngle = (f) => (HALF_TURN / Math.PI) * Math.acos(Math.max(-1, Math.min(1, f.light[2])));
