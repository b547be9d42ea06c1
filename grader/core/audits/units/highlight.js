// The audit unit 'highlight' (A specular highlight): Looks for a rise above the diffuse model,
// with ks and s raised by the page's own sliders where needed.
import { highlightEvidence } from '../../computed/evidence.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { litViewFits } from '../../computed/evidence.js';
import { unit } from '../unit.js';
import { PERCENT } from '../../units.js';
import { META as META_HIGHLIGHT_PLACE, judgedSurface } from './highlight-place.js';
import { judgePlaceOn, sayCoarse } from '../highlight.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  highlight: { title: 'A specular highlight', slide: SLIDE.highlight, failureTitle: 'No specular highlight', description: 'Looks for a rise above the diffuse model, with ks and s raised by the page\'s own sliders where needed.', reads: ['images.judged', 'facts.views', 'facts.raised', 'facts.surface', 'facts.stopped', 'facts.judgedVertices'] },
};

/**
 * Whether a highlight shows, and where it is placed. Returns the place to judge at the end (the
 * gatherer looked farther along the orbit for it), or null.
 */
export function auditHighlight(context, shading, views) {
  const { facts, images, thresholds, must, sayAs, numbers } = context;
  const say = sayAs('highlight');
  if (!must.has('highlight') || !shading.fit) return null;
  const fit = shading.judgedFit;
  const { seen, place, coarse } = highlightEvidence(shading, views, facts.raised, images, thresholds);
  numbers.highlightViews = 1 + views.length;
  if (seen) say('pass', `a specular highlight in ${seen.where} (up to ${fmt(PERCENT * seen.fit.highlightPeak, 0)}% of the way from the diffuse fit to white, ${fmt(seen.fit.highlightRise, 2)} above it)`);
  let later = null;
  if (seen && !shading.nearModel) {
    if (!place && !coarse) sayAs('highlight-place')('pass', 'note: the highlight\'s place is not judged: it shows only with s lowered to 10 by the page\'s own slider, which makes it too broad to place');
    else if (facts.placeFarther) later = place || { coarser: seen.coarser };
    else if (place) judgePlaceOn(context, place, judgedSurface(facts, place));
    else sayCoarse(context, seen.coarser);
  }
  if (!seen) say('mistake', `no specular highlight: nothing brighter than the diffuse fit (${fmt(fit.highlightPeak)}) in ${1 + views.length} views (the judged one${views.length ? ' and the lit ones along the orbit' : ''})`);
  return later;
}

/** The unit (audits/list.js runs it in its order). */
// the highlight read on the judged picture and on the lit views' full fits; its result (the place
// nearer the viewer) is read again farther along (highlight-place)
export const UNIT = unit({ ...META, ...META_HIGHLIGHT_PLACE }, 'highlight', (context, { shading, 'lit-views': lit }) => {
  if (!shading.shaded) return null;
  const views = litViewFits(lit, context.facts, context.images, context.thresholds);
  return auditHighlight(context, shading.shading, views);
},
  { also: ['highlight-place'], uses: ['shading', 'lit-views'] });
