// P5: per vertex against per fragment, read on the page's own surface at a coarse level. The
// slides: Phong shading evaluates the model "for each fragment" with the interpolated normal
// normalised there; Gouraud shading evaluates it at the vertices and interpolates the colour, so
// on large triangles "highlights in particular" follow the triangles. The coarse level's surface
// (facts.coarseSurface: each pixel's interpolated normal and position, as the page drew them) with
// the judged fit's light, form, w_o and normal colour fixed (measure/surface-terms.js) says how far
// the model evaluated per pixel explains the coarse picture: per fragment, as well as it explains
// the judged picture; per vertex, not.
import { surfaceOf } from './surface.js';
import { surfaceSeen } from './lighting.js';
import { modelResidual } from '../measure/surface-terms.js';
import { analyse } from '../measure.js';

/**
 * The coarse level's reading ({ rms, judgedRms, level }) where the coarse picture `coarse` (ladder
 * level `at`) has its surface and the judged fit (`exact`: computed/lighting.js's, made on the
 * picture `judged`) explains the judged picture (its best: the slide's model, or a misreading
 * named elsewhere); { why } where the surface cannot say; null where it was not read.
 */
export function coarseReading({ facts, images, thresholds }, { exact, judged: judgedImg }, at, coarse) {
  const cs = facts.coarseSurface;
  if (!cs || !coarse) return null;
  if (cs.level !== at) return { why: 'the surface was read at another level than the one compared' };
  if (!exact || exact.why) return { why: exact ? exact.why : 'the judged picture\'s surface was not read' };
  const { best } = exact;
  if (!best || best.rms > thresholds.surfaceResidual) return { why: `the slide's model leaves a residual of ${best ? best.rms.toFixed(3) : '?'} on the judged picture's surface` };
  const s = surfaceSeen(images, { img: coarse, an: analyse(coarse, thresholds) }, thresholds, cs.surface);
  if (s.why) return { why: `at the coarse level, ${s.why}` };
  const judged = modelResidual(surfaceOf(facts.surface, images, thresholds), judgedImg, best, thresholds);
  const rms = modelResidual(s, coarse, best, thresholds);
  if (rms === null || judged === null) return { why: 'too few of the coarse surface\'s pixels to read the model on' };
  return { rms, judgedRms: judged, level: at };
}
