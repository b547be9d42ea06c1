// P3–P5: does the light stay in the world while the camera orbits, read on the page's own surface.
// Two views have their surface: the first lit view along the orbit (gather/orbit.js, read before
// the next frame) and the judged view, once the orbit stood still; on each the slide's model is
// fitted (measure/surface-fit.js) with its light w_i in the model's space, the space of the page's
// normals. The camera of each view comes from the page's own P·V·M (computed/surface.js). A light
// that stays in the world keeps its w_i there; a light given in the eye's space turns with the
// camera, to where the first view's light, held in the eye's space, is seen from the second camera.
// Which of the two the second view's fitted light is nearer to says where the light is; how far
// apart they are says whether the camera turned enough to tell.
import { exactLighting } from './lighting.js';
import { degreesBetween } from './surface.js';
import { analyse } from '../measure.js';
import { dot, unit } from '../measure/vectors.js';

/** A direction fixed in the eye's space of camera `a`, in the model's space as camera `b` sees it. */
export function carried(v, a, b) {
  const e = [dot(a.right, v), dot(a.up, v), dot(a.back, v)];
  return unit([0, 1, 2].map((k) => e[0] * b.right[k] + e[1] * b.up[k] + e[2] * b.back[k]));
}

/**
 * The light's space read on the first lit view's surface and the judged view's (`exact`: the
 * surface-fit unit's, computed/lighting.js): { turn (how far the fitted w_i turned in the model's
 * space), eyeTurn (how far a light in the eye's space would have turned there), fromEye (how far the
 * judged view's fit is from that), cameraTurn, rms: [both fits' residuals] } in degrees; { why }
 * where the surfaces cannot say; null where no lit view's surface was read.
 */
export function lightSpaceOnSurface({ facts, images, thresholds }, exact) {
  const v = (facts.views || []).find((x) => x.orbiting && x.surface);
  if (!v) return null;
  if (!exact || exact.why) return { why: exact ? exact.why : 'the judged view\'s surface was not read' };
  const img = images[v.image];
  if (!img) return { why: 'the lit view\'s picture is missing' };
  const a = exactLighting(facts, images, { img, an: analyse(img, thresholds) }, thresholds, v.surface);
  if (a.why) return { why: `in the lit view along the orbit, ${a.why}` };
  const loose = [a, exact].find((f) => f.best.rms > thresholds.surfaceResidual);
  if (loose) return { why: `the slide's model leaves a residual of ${loose.best.rms.toFixed(3)} in ${loose === a ? 'the lit view along the orbit' : 'the judged view'}` };
  const b = exact, eyeLight = carried(a.best.wi, a.camera, b.camera);
  return {
    turn: degreesBetween(a.best.wi, b.best.wi),
    eyeTurn: degreesBetween(a.best.wi, eyeLight),
    fromEye: degreesBetween(b.best.wi, eyeLight),
    cameraTurn: degreesBetween(a.camera.back, b.camera.back),
    rms: [a.best.rms, b.best.rms],
  };
}
