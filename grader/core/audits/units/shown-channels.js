// The audit unit 'shown-channels' (What the page reads back is what the browser shows): Compares
// the canvas read back with a screenshot of it as the browser shows it, at the first frame and at
// the end.
import { unit } from '../unit.js';
import { PERCENT } from '../../units.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'shown-channels': { title: 'What the page reads back is what the browser shows', slide: null, failureTitle: 'What the page reads back is not what the browser shows', description: 'Compares the canvas read back with a screenshot of it as the browser shows it, at the first frame and at the end.', reads: ['facts.shown'] },
};

/**
 * Says review where the channels differ (the browser's picture shown to the teacher); returns true
 * when they differed at the first frame, where a read-back that shows nothing is then no reason to
 * fail the part.
 */
export function auditShown({ facts, thresholds, sayAs, imagesShown }) {
  const say = sayAs('shown-channels');
  // the comparisons (the first frame's, the last picture's) that differ beyond the engine's rounding
  const off = (facts.shown || []).filter((d) => d.compared && d.share > thresholds.shownDifferShare);
  for (const d of off) {
    const when = d.at === 'first' ? 'at the first frame' : 'at the end';
    say('review', `what the page reads back differs from what the browser shows, ${when}: ${Math.round(PERCENT * d.share)}% of the canvas's opaque pixels in view (another canvas or an element laid over it, or a CSS filter on it?); the browser's picture is shown: a teacher looks`);
    if (d.image) imagesShown[`shown${d.at === 'first' ? 'First' : 'Last'}`] = d.image;
  }
  return off.some((d) => d.at === 'first');
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'shown-channels', auditShown);
