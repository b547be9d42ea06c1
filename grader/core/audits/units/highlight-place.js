// The audit unit 'highlight-place' (The highlight at w_h, halfway between the light and the
// viewer): Measures the highlight's place against where n = w_h, halfway between the light and
// the viewer, in the judged view and farther along the orbit.
import { fullFit } from '../../computed/views.js';
import { exactLighting } from '../../computed/lighting.js';
import { analyse } from '../../measure.js';
import { VIEW_WORDS } from './surface-fit.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { judgePlace } from '../highlight.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'highlight-place': { title: 'The highlight at w_h, halfway between the light and the viewer', slide: SLIDE.eye, failureTitle: 'The highlight is not at w_h', description: 'Measures the highlight\'s place against where n = w_h, halfway between the light and the viewer, in the judged view and farther along the orbit; in the view farther along, where the page\'s own surface was read there, its fit decides (a w_o misread past the margin: a mistake; the slide\'s w_o within surfaceResidual: the place is right), else the picture\'s.', reads: ['facts.views', 'facts.raised', 'facts.placeFarther'] },
};

/** The highlight's place, judged in the view the gatherer found farther along the orbit, else where it was seen (`near`). */
export function auditPlaceFarther(context, near) {
  const { facts, images, thresholds } = context;
  const name = facts.placeFarther.image;
  if (!name) return judgePlace(context, near);
  const img = images[name];
  context.imagesShown.highlightPlace = name;
  const where = 'a view along the orbit';
  const exact = facts.placeFarther.surface
    ? exactLighting(facts, images, { img, an: analyse(img, thresholds) }, thresholds, facts.placeFarther.surface)
    : null;
  if (placeOnSurface(context, exact, where)) return;
  judgePlace(context, { fit: fullFit(img, thresholds), where });
}

/**
 * The highlight's place read on the page's own surface in that view (its normals and positions as
 * it drew them: the light and the highlight fitted there, computed/lighting.js): a w_o misread that
 * explains the picture better by the rubric's margin is a mistake; the slide's w_o explaining it
 * within surfaceResidual (Phong or Blinn-Phong, the normal colour in the material or not) places
 * the highlight where the slide puts it. Says it and returns true; false where the surface decides
 * nothing (not read, or no fit explains the picture: the picture's fit decides, as on the outline).
 */
function placeOnSurface({ sayAs, numbers, thresholds }, exact, where) {
  if (!exact || exact.why || !exact.slide) return false;
  const { best } = exact;
  numbers.placeSurfaceFit = { slide: exact.slide, best: { name: best.name, rms: best.rms } };
  const say = sayAs('highlight-place');
  if (best.view && best.view !== 'the slide') {
    say('mistake', `the highlight is not where the slide puts it: on the page's own surface in ${where}, ${VIEW_WORDS[best.view]} explains the picture with a residual of ${best.rms.toFixed(3)}, the slide's formula with ${exact.slide.rms.toFixed(3)} (w_o = normalize(e − p), from the point to the eye, in the space of n and w_i)`);
    return true;
  }
  if (best.rms > thresholds.surfaceResidual || !best.form) return false;
  say('pass', `the highlight sits where the slide's ${best.form === 'phong' ? 'Phong' : 'Blinn-Phong'} model with w_o = normalize(e − p) puts it, read on the page's own surface in ${where} (its normals and positions as it drew them): a residual of ${best.rms.toFixed(3)}${best.tint ? ', with the normal colour in the material' : ''}`);
  return true;
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'highlight-place',
  (context, { highlight }) => (highlight ? auditPlaceFarther(context, highlight) : null), { uses: ['highlight'] });
