// The slide's sentence a part misses, for each review or fail the grader gives: found by the
// reason's audit id (grader/core/audits/index.js, where each audit names the sentence it checks),
// never by its words; and our step that does it right.
import { AUDITS } from '../grader/core/audits/index.js';
import { NOT_GRADED } from '../grader/core/verdict.js';

/** Our own step for a part, relative to the check page. */
export const stepLink = (part) => `../${part}/`;

/**
 * A part's findings ({ id, level, reason }, as report.json and the check page have them). A result
 * written before reasons carried ids (no `findings`) has its reasons read as findings without one
 * (no slide): their levels from the words FAIL: and REVIEW:, and the first reason of a part the
 * grader failed or did not grade is why (reasons that passed come after every FAIL: and REVIEW:).
 */
export function findingsOfResult(r) {
  if (r.findings) return r.findings;
  const graderVerdict = r.grader ? r.grader.verdict : r.verdict;
  return (r.reasons || []).map((reason, k) => {
    const m = /^(FAIL|REVIEW): /.exec(reason);
    const first = k === 0 && (graderVerdict === 'fail' || graderVerdict === NOT_GRADED) ? graderVerdict : 'pass';
    return { id: null, level: m ? m[1].toLowerCase() : first, reason };
  });
}

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
    if (!out.some((o) => o.slide === audit.slide)) out.push({ reason: f.reason, slide: audit.slide, note: audit.note, id: f.id });
  }
  return out;
}
