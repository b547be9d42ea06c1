// A part's result (what report.json says of it, and the check page's card) from its audit: the
// verdict, the reasons in the order a teacher reads them, the numbers, the pictures shown. One pure
// function for a part just gathered (node/harness.js, grade-firefox.js), a part re-judged from its
// saved artifact (--audit-only) and a part checked on the check page (check/runner.js), so they
// cannot drift apart. A part not judged here (the browser could not run it, or it was too slow or
// too heavy) gets no verdict of pass, review or fail: the grader's NOT_GRADED, the check page's
// NOT_CHECKED (check/not-checked.js), one idea in each place's own word.
import { verdictOf, findingsOf, NOT_GRADED } from './verdict.js';

/**
 * `result`'s reasons set from `findings` ({ id, level, reason }): `reasons` their words (what a
 * teacher reads, labels and comparisons match), `findings` each with its audit's id and level (what
 * the check page, the feedback pages and grades.csv go by).
 */
export const withFindings = (result, findings) =>
  Object.assign(result, { reasons: findings.map((f) => f.reason), findings });

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

/** Does a finding ask for something: a fail, a review, or why a part was not graded here? */
export const asks = (f) => f.level === 'fail' || f.level === 'review' || f.level === NOT_GRADED;

/** The findings of a part's result that ask for something. */
export const asking = (r) => findingsOfResult(r).filter(asks);

/** The verdict and its reasons from a part's judging ({ fail, failId, checks }) and the page's errors. */
export function judgement(judged, errors = []) {
  const findings = findingsOf({
    fail: judged.fail,
    failId: judged.failId,
    checks: judged.checks,
    pageErrors: errors.filter((e) => /page error/.test(e)),
  });
  return withFindings({ verdict: verdictOf(judged.checks, judged.fail) }, findings);
}

/**
 * `result` given no verdict here: `verdict` (not pass, review nor fail), `reason` (said by the
 * audit `id`) first, what was seen kept below in `seen`'s words (level 'seen': no verdict, no slide).
 */
export function notJudgedHere(result, verdict, reason, seen, id) {
  const kept = (result.findings || []).map((f) => ({ id: f.id, level: 'seen', reason: seen(f.reason) }));
  return withFindings(Object.assign(result, { verdict }), [{ id, level: verdict, reason }, ...kept]);
}

/** A judged part's status, as report.json says it: failed, too slow, too heavy, not graded here or ok. */
export function statusOf(judged) {
  const slow = judged.tooHeavy ? 'too heavy' : 'too slow';
  if (judged.notGraded) return judged.tooSlow ? slow : NOT_GRADED;
  return judged.fail ? 'failed' : judged.tooSlow ? slow : 'ok';
}

/**
 * Sets `result`'s judging from `judged` (grade-part.js's judged(): fail, checks, numbers, images
 * by name, actions, controls, api, canvas). `files` maps a picture's name to its path relative to
 * the report (the artifact's files).
 */
export function applyAudit(result, judged, files = {}) {
  Object.assign(result, {
    api: judged.api ?? null,
    canvas: judged.canvas,
    controls: judged.controls || {},
    numbers: judged.numbers || {},
    actions: [...(judged.actions || [])],
  });
  Object.assign(result, judgement(judged, result.errors || []));
  result.status = statusOf(judged);
  if (judged.notGraded) {
    // the browser could not run it (WebGPU in Firefox ESR): no verdict; what was seen stays below
    notJudgedHere(result, NOT_GRADED, judged.notGraded, (r) => `(seen here: ${r})`, judged.notGradedId || 'not-graded');
  }
  result.pass = result.verdict === 'pass';
  const kept = result.images || {};
  result.images = {};
  for (const [k, name] of Object.entries(judged.shown || {})) if (files[name]) result.images[k] = files[name];
  for (const k of ['reference', 'diff']) if (kept[k]) result.images[k] = kept[k];
  return result;
}
