// P4/P5: the specular highlight above a model of the diffuse brightness: how far it rises, where
// it sits against the half vector, and whether it is seen at all.
import { luminance } from './samples.js';
import { HALF_TURN } from '../units.js';

/** A guard against dividing by (nearly) zero. */
const GUARD = 1e-6;

/**
 * The highlight above a model of the diffuse brightness (`predict(n)`): the largest rise of a
 * pixel over it as a share of the headroom to white there (`peak`: a highlight on a bright diffuse
 * patch saturates at 1 and cannot rise far), the largest rise itself (`rise`), and how many pixels
 * rise clearly (`bright`).
 */
export function highlightOf(pts, predict, thresholds) {
  const margin = thresholds.highlightMargin;
  let peak = 0, rise = 0, bright = 0;
  const rises = new Float64Array(pts.length);
  for (let i = 0; i < pts.length; i++) {
    const s = pts[i];
    const pred = predict(s.n);
    const r = luminance(s.c) - pred;
    rises[i] = r;
    if (r < thresholds.highlightMinRise) continue;
    const share = Math.min(1, r / Math.max(thresholds.highlightHeadroom, 1 - pred));
    peak = Math.max(peak, share);
    rise = Math.max(rise, r);
    if (r > margin || share > thresholds.highlightBrightShare) bright++;
  }
  // where it is: the mean normal of the pixels that rise most (highlightPlaceRise of the largest rise or more)
  let normal = null;
  if (rise > 0) {
    const m = [0, 0, 0];
    for (let i = 0; i < pts.length; i++) {
      if (rises[i] >= thresholds.highlightPlaceRise * rise) {
        for (let k = 0; k < 3; k++) {
          m[k] += pts[i].n[k] * rises[i];
        }
      }
    }
    const len = Math.hypot(...m);
    if (len > 0) normal = m.map((v) => v / len);
  }
  return { peak, rise, bright, normal };
}

/**
 * How far (degrees) a highlight sits from where the Phong and Blinn-Phong models put it: at the
 * normal halfway between the direction to the light and the direction to the viewer (w_h =
 * normalize(w_i + w_o), w_o = +z toward the viewer; a perspective camera moves it a few degrees).
 * `toViewer` 0: how far from the light itself (w_i).
 */
export function highlightOffset(highlightNormal, light, toViewer = 1) {
  if (!highlightNormal || !light) return null;
  const h = [light[0], light[1], light[2] + toViewer];
  const len = Math.hypot(...h);
  if (len < GUARD) return null; // the light straight behind: no half vector
  const c = (highlightNormal[0] * h[0] + highlightNormal[1] * h[1] + highlightNormal[2] * h[2]) / len;
  return (HALF_TURN / Math.PI) * Math.acos(Math.max(-1, Math.min(1, c)));
}

/**
 * Is there a specular highlight above a fit (diffuseFit's, or a point-light model's)? Either it
 * rises far toward white (highlightPeak), or it stands clearly out of the fit's own noise: a
 * rise of highlightClearRise or more, highlightNoise times the fit's RMS, over a few pixels (a
 * small or tinted highlight on a clean fit; a page with no specular term has neither).
 */
export function highlightSeen(fit, thresholds) {
  if (fit.highlightPeak >= thresholds.highlightPeak) return true;
  return (
    fit.highlightRise >= thresholds.highlightClearRise &&
    fit.highlightRise >= thresholds.highlightNoise * fit.rms &&
    fit.highlightShare > 0
  );
}
