// The audit unit 'highlight-place' (The highlight at w_h, halfway between the light and the
// viewer): Measures the highlight's place against where n = w_h, halfway between the light and
// the viewer, in the judged view and farther along the orbit.
import { fullFit } from '../../computed/views.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { judgePlaceOn, sayCoarse } from '../highlight.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'highlight-place': { title: 'The highlight at w_h, halfway between the light and the viewer', slide: SLIDE.eye, failureTitle: 'The highlight is not at w_h', description: 'Measures the highlight\'s place against where n = w_h, halfway between the light and the viewer, in the judged view and farther along the orbit; where the page\'s own surface was read in that view (farther along, or the judged view standing still), its fit decides (a w_o misread past the margin: a mistake; the slide\'s w_o within surfaceResidual: the place is right), else the picture\'s; a view taken at a coarser level than the judged one is not read for the place (per vertex, a coarse mesh moves a highlight).', reads: ['facts.views', 'facts.raised', 'facts.placeFarther', 'facts.surface', 'facts.stopped', 'facts.judgedVertices'] },
};

/** The highlight's place, judged in the view the gatherer found farther along the orbit, else where it was seen (`near`). */
export function auditPlaceFarther(context, near) {
  const { facts, images, thresholds } = context;
  const name = facts.placeFarther.image;
  if (!name && !near.fit) return sayCoarse(context, near.coarser);
  if (!name) return judgePlaceOn(context, near, judgedSurface(facts, near));
  const img = images[name];
  context.imagesShown.highlightPlace = name;
  judgePlaceOn(context, { fit: fullFit(img, thresholds), where: 'a view along the orbit', img }, facts.placeFarther.surface);
}

/**
 * The judged view's surface (facts.surface) where `place` is a picture of that view (the judged
 * one, or with the page's sliders set) and the view stood still (the orbit stopped): else null.
 */
export const judgedSurface = (facts, place) => (place.atJudged && facts.stopped ? facts.surface : null);

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'highlight-place',
  (context, { highlight }) => (highlight ? auditPlaceFarther(context, highlight) : null), { uses: ['highlight'] });
