// The audit unit 'highlight-place' (The highlight at w_h, halfway between the light and the
// viewer): Measures the highlight's place against where n = w_h, halfway between the light and
// the viewer, in the judged view and farther along the orbit.
import { fullFit } from '../../computed/views.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { judgePlace } from '../highlight.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'highlight-place': { title: 'The highlight at w_h, halfway between the light and the viewer', slide: SLIDE.eye, failureTitle: 'The highlight is not at w_h', description: 'Measures the highlight\'s place against where n = w_h, halfway between the light and the viewer, in the judged view and farther along the orbit.', reads: ['facts.views', 'facts.raised', 'facts.placeFarther'] },
};

/** The highlight's place, judged in the view the gatherer found farther along the orbit, else where it was seen (`near`). */
export function auditPlaceFarther(context, near) {
  const name = context.facts.placeFarther.image;
  if (!name) return judgePlace(context, near);
  const img = context.images[name];
  context.imagesShown.highlightPlace = name;
  judgePlace(context, { fit: fullFit(img, context.thresholds), where: 'a view along the orbit' });
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'highlight-place',
  (context, { highlight }) => (highlight ? auditPlaceFarther(context, highlight) : null), { uses: ['highlight'] });
