// Judging a gathered part: pure functions from its artifact ({ facts, images }) and the rubric to
// findings ({ id, level, reason }: each said by the audit `id`, audits/index.js), numbers, and the
// pictures a teacher should see. One audit a point of the slides (grader/core/audits/), run in the
// order a teacher reads them; the verdict and its reasons come from the findings only
// (verdict.js). No browser: `npm run grade -- --audit-only` re-judges a class from its saved
// artifacts.
import { analyse } from './measure.js';
import { checkList, NOT_GRADED, tooSlowWords, tooHeavyWords } from './verdict.js';
import { litView } from './computed/views.js';
import { sphereView, shadingOf, viewFits } from './computed/evidence.js';
import { exactLighting } from './computed/lighting.js';
import { auditFirstFrame, notGradedHere, STOP } from './audits/first-frame.js';
import { auditMeta } from './audits/index.js';
import { tooSlow } from './audits/page.js';
import { auditShown } from './audits/channels.js';
import { auditLevelControls, auditHeavyLevel, auditSphere } from './audits/sphere.js';
import { auditNormals, auditPerspective, auditNormalsNotLight, auditDepthCulling } from './audits/normals.js';
import { auditDiffuse, auditPointLight, auditUnclipped, auditBrightened } from './audits/diffuse.js';
import { auditOrbitStopsAgain, auditOrbit, auditNotStopped } from './audits/orbit.js';
import { auditHighlight, auditPlaceFarther } from './audits/highlight.js';
import { auditSliders } from './audits/sliders.js';
import { auditSurfaceFit } from './audits/surface.js';
import { auditLeastShininess, auditPerFragment } from './audits/shading.js';
import { auditWinding, auditClosed, auditAllRound, auditPerFace, auditGrowth, auditLoopsMultiply, auditPictureNotGeometry } from './audits/geometry.js';

/**
 * { fail, failId, checks, numbers, shown, notGraded } for one part's artifact: `fail` (a reason,
 * said by the audit `failId`) when the part could not be judged at all, `checks` the findings, `shown` the artifact's picture names a
 * report shows (first, judged, coarse, highlightPlace, leastS); `notGraded` (a reason) when the
 * browser it was gathered in could not run it (WebGPU in Firefox ESR): then no verdict stands,
 * whatever the findings (core/part-result.js).
 */
export function auditPart({ facts, images }, rubric) {
  const list = checkList(rubric);
  const { checks } = list;
  // an audit says its findings under its own id, one its module declares (audits/index.js)
  const sayAs = (id) => list.sayAs(auditMeta(id).id);
  const T = rubric.thresholds;
  const part = facts.part;
  const must = new Set((rubric.parts[part] || {}).must || []);
  const numbers = {};
  const shown = {};
  if (images.first) shown.first = 'first';
  const C = { facts, images, T, rubric, part, must, sayAs, numbers, imagesShown: shown };
  let notGraded = notGradedHere(C), notGradedId = 'not-graded';
  const result = (fail, failId = fail ? 'first-frame' : null) => ({ fail, failId, checks, numbers, shown, tooSlow: facts.tooSlow || null, tooHeavy: facts.tooHeavy ?? null, ...(notGraded ? { notGraded, notGradedId } : {}) });
  // a page that replaced what the grader reads through may show one thing and hand the grader another
  if (facts.tampered) sayAs('tamper')('review', `the page replaced or probed what the grader reads it through: ${facts.tampered.join(', ')} (a hand-in must not change the browser's own functions or the grader's, nor draw otherwise under a test driver): what it showed may not be what the grader saw, a teacher looks`);
  if (facts.tooSlow) {
    // nothing judged: where the bound ran out depends on the machine, the verdict must not; a page
    // that draws is not broken for being slow: not graded here (the rubric's tooSlowVerdict)
    const slow = tooSlow(rubric, facts.tooHeavy != null ? tooHeavyWords(rubric, facts.tooSlow, facts.tooHeavy) : tooSlowWords(rubric, facts.tooSlow));
    if (slow.level === NOT_GRADED) [notGraded, notGradedId] = [slow.reason, slow.id];
    else sayAs(slow.id)(slow.level, slow.reason);
    return result(null);
  }
  const firstDiffers = auditShown(C);
  const fail = auditFirstFrame(C);
  if (fail === STOP) return result(null);
  // what the grader read is not what a student sees: the review stands, nothing is failed on it
  if (fail) return result(firstDiffers ? null : fail);
  if (!facts.ladder) return result('the grader stopped before the level ladder', 'level-ladder');
  auditHeavyLevel(C);
  auditOrbitStopsAgain(C);
  if (facts.blankAtHigherLevel) sayAs('level-ladder')('mistake', 'the picture goes blank at a higher level: judged at the last level that drew');
  shown.judged = facts.facesImage || facts.judged;
  auditLevelControls(C);
  const img = images[facts.judged];
  const raw = analyse(img, T);
  if (raw.blank) return result('the picture went blank after the controls were used', 'sphere');
  const { an, circleArc } = sphereView(img, T);
  const judged = { img, an, raw, circleArc };
  auditSphere(C, judged, facts.ladder.map((l) => l.roundness), analyse(images.first, T).roundness);
  auditClosed(C);
  auditAllRound(C);
  auditGrowth(C);
  auditLoopsMultiply(C);
  auditPictureNotGeometry(C, judged);
  auditPerspective(C, auditNormals(C, judged));
  auditPerFace(C);
  auditDepthCulling(C);
  auditWinding(C);
  // a lit step that shows WP04P1's colours has no shading to judge: its colours are not lighting
  // the lighting fitted on the page's own surface (its normals and positions as it drew them): evidence in the numbers
  const litStep = must.has('diffuse') || must.has('highlight');
  const exact = litStep ? exactLighting(facts, images, judged, T) : null;
  if (exact) numbers.surfaceFit = exact.why ? { why: exact.why } : { samples: exact.samples, diffuse: exact.diffuse, slide: exact.slide, best: exact.best, variants: exact.variants.slice(0, 8) };
  auditSurfaceFit(C, exact);
  const shaded = litStep && !auditNormalsNotLight(C, judged);
  // a picture that clipped to white was read again with the page's own sliders lowered, one too
  // dim with its light raised (gather/visible.js)
  const shadeImg = facts.shadingImage ? images[facts.shadingImage] : img;
  const shading = shaded ? shadingOf(shadeImg, an, T) : null;
  if (shaded) auditUnclipped(C);
  if (shaded) auditBrightened(C);
  // the lit views kept along the orbit: their sparse fits (the orbit's), and full fits (the highlight's)
  const lit = !shaded ? [] : facts.views.map((v) => ({ ...litView(images[v.image], T), orbiting: v.orbiting, image: v.image, camera: v.camera })).filter((v) => v.lit);
  if (shaded) auditDiffuse(C, shading, lit);
  auditOrbit(C, lit);
  if (shaded) auditPointLight(C, shading);
  const later = shaded ? auditHighlight(C, shading, viewFits(lit.map((v) => ({ img: images[v.image] })), T)) : null;
  auditSliders(C, judged, shading);
  if (must.has('highlight')) auditLeastShininess(C, { ...judged, img: shadeImg }, shading);
  auditPerFragment(C, judged, shading);
  if (later) auditPlaceFarther(C, later);
  auditNotStopped(C);
  return result(null);
}
