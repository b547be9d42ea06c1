// The slide's sentence a part misses, for each review or fail the grader gives: found by the
// reason's audit id (audits/index.js, where each audit names the sentence it checks), never by its
// words. The check page and the feedback pages both quote them.
import { AUDITS } from './index.js';

/**
 * The slide's sentences behind a part's reviews and fails (`findings`: { id, level, reason }):
 * [{ reason, slide, note?, id }], one per different sentence. A part not judged here misses none;
 * an audit about the page rather than the step (its slide null) names none.
 */
export function missedSlides(findings) {
  const out = [];
  for (const f of findings) {
    if (f.level !== 'fail' && f.level !== 'review') continue;
    const audit = AUDITS[f.id];
    if (!audit || !audit.slide) continue;
    if (!out.some((o) => o.slide === audit.slide)) {
      out.push({ reason: f.reason, slide: audit.slide, note: audit.note, id: f.id });
    }
  }
  return out;
}
