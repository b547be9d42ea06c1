// Verdicts and reasons: the checks a part's judging said (each { level, reason }) become one
// verdict (pass, review, fail) and the reasons a teacher reads, worst first. Plain data.
import { MILLION } from './units.js';

/**
 * The verdict of a part the browser it was graded in could not run (WebGPU in Firefox ESR), or that
 * ran past the rubric's bound on the wall clock while it drew (too slow on this machine): neither
 * pass, review nor fail.
 */
export const NOT_GRADED = 'not graded here';

/** What the words of a part past a bound say was judged, unless a mistake was found before it. */
const NOTHING_JUDGED = 'nothing was judged';

/** Why a part past the rubric's wall-clock bound while `doing` was not judged. */
export const tooSlowWords = (rubric, doing, judged = NOTHING_JUDGED) => `too slow on this machine: the rubric's bound of ${rubric.timeoutSeconds} s ran out while ${doing}; ${judged} (what was done is listed under what the grader did; grade it again on a faster machine, or with a larger timeoutSeconds)`;

/** Why a part whose own work passed the rubric's gatherWork (a count: the same on every machine) is not judged. */
export const tooHeavyWords = (rubric, doing, work, judged = NOTHING_JUDGED) => {
  const { drawCallWork, gatherWork } = rubric.thresholds;
  return `too heavy to grade: the page's own work over the grading (${(work / MILLION).toFixed(0)} million vertices, draw calls at ${drawCallWork} each) passed the rubric's budget of ${(gatherWork / MILLION).toFixed(0)} million (gatherWork) while ${doing}; ${judged} (what was done is listed under what the grader did; grade it with a larger gatherWork, or at a level the sphere needs)`;
};

/**
 * A list of checks with the rubric's cost of a mistake: sayAs(id) gives the audit `id`'s
 * say('pass' | 'review' | 'fail' | 'mistake', reason), each check { id, level, reason }. A
 * 'mistake' (the page draws but misses a point of the slide's step) costs the rubric's
 * mistakeVerdict: review by default (a careful reader calls such a part partial).
 */
export function checkList(rubric) {
  const checks = [];
  const sayAs = (id) => (level, reason) =>
    checks.push({ id, level: level === 'mistake' ? rubric.mistakeVerdict || 'review' : level, reason });
  return { checks, sayAs };
}

/** fail if anything failed (or the part could not be judged: `fail`), else review if any check asks for it, else pass. */
export function verdictOf(checks, fail) {
  if (fail) return 'fail';
  if (checks.some((c) => c.level === 'fail')) return 'fail';
  if (checks.some((c) => c.level === 'review')) return 'review';
  return 'pass';
}

/**
 * The reasons in the order a teacher reads them, each with its audit's id and its level ({ id,
 * level, reason }): why it could not be judged (level fail, the audit `failId`), then FAIL: …,
 * REVIEW: …, then what passed; then page errors (level note), which change no verdict. (How long
 * a part took is never a reason: it depends on the machine; the report shows it beside the part.)
 */
export function findingsOf({ fail, failId, checks = [], pageErrors = [] }) {
  const out = [];
  if (fail) out.push({ id: failId, level: 'fail', reason: fail });
  for (const lvl of ['fail', 'review', 'pass']) {
    for (const c of checks) {
      if (c.level === lvl) {
        out.push({ id: c.id, level: lvl, reason: lvl === 'pass' ? c.reason : `${lvl.toUpperCase()}: ${c.reason}` });
      }
    }
  }
  if (!fail && pageErrors.length) out.push({ id: 'page-errors', level: 'note', reason: `the page reported errors: ${pageErrors[0]}` });
  return out;
}

/** The reasons' words alone, in findingsOf's order. */
export const reasonsOf = (judged) => findingsOf(judged).map((f) => f.reason);
