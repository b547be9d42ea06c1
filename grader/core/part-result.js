// A part's result (what report.json says of it, and the check page's card) from its audit: the
// verdict, the reasons in the order a teacher reads them, the numbers, the pictures shown. One pure
// function for a part just gathered (node/harness.js, grade-firefox.js), a part re-judged from its
// saved artifact (--audit-only) and a part checked on the check page (check/runner.js), so they
// cannot drift apart. A part not judged here (the browser could not run it, or it was too slow or
// too heavy) gets no verdict of pass, review or fail: the grader's NOT_GRADED, the check page's
// NOT_CHECKED (check/not-checked.js), one idea in each place's own word.
import { verdictOf, reasonsOf, NOT_GRADED } from './verdict.js';

/** The verdict and its reasons from a part's judging ({ fail, checks }) and the page's errors. */
export function judgement(judged, errors = []) {
  return {
    verdict: verdictOf(judged.checks, judged.fail),
    reasons: reasonsOf({ fail: judged.fail, checks: judged.checks, pageErrors: errors.filter((e) => /page error/.test(e)) }),
  };
}

/** `result` given no verdict here: `verdict` (not pass, review nor fail), `reason` first, what was seen kept below in `seen`'s words. */
export function notJudgedHere(result, verdict, reason, seen) {
  return Object.assign(result, { verdict, reasons: [reason, ...result.reasons.map(seen)] });
}

/**
 * Sets `result`'s judging from `judged` (grade-part.js's judged(): fail, checks, numbers, images
 * by name, actions, controls, api, canvas). `files` maps a picture's name to its path relative to
 * the report (the artifact's files).
 */
export function applyAudit(result, judged, files = {}) {
  Object.assign(result, { api: judged.api ?? null, canvas: judged.canvas, controls: judged.controls || {}, numbers: judged.numbers || {}, actions: [...(judged.actions || [])] });
  Object.assign(result, judgement(judged, result.errors || []));
  const slow = judged.tooHeavy ? 'too heavy' : 'too slow';
  result.status = judged.fail ? 'failed' : judged.tooSlow ? slow : 'ok';
  if (judged.notGraded) {
    // the browser could not run it (WebGPU in Firefox ESR): no verdict; what was seen stays below
    notJudgedHere(result, NOT_GRADED, judged.notGraded, (r) => `(seen here: ${r})`);
    result.status = judged.tooSlow ? slow : NOT_GRADED;
  }
  result.pass = result.verdict === 'pass';
  const kept = result.images || {};
  result.images = {};
  for (const [k, name] of Object.entries(judged.shown || {})) if (files[name]) result.images[k] = files[name];
  for (const k of ['reference', 'diff']) if (kept[k]) result.images[k] = kept[k];
  return result;
}
