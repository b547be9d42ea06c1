// A part's result (what report.json says of it) from its audit: the verdict, the reasons in the
// order a teacher reads them, the numbers, the pictures shown (files of its artifact). The same
// for a part just gathered (harness.js) and for a part re-judged from its saved artifact
// (--audit-only), so the two cannot drift apart. A part the browser could not run (WebGPU in
// Firefox ESR) gets the verdict "not graded here", never a fail.
import { verdictOf, reasonsOf, NOT_GRADED } from '../core/verdict.js';

/**
 * Sets `result`'s judging from `judged` (grade-part.js's judged(): fail, checks, numbers, images
 * by name, actions, controls, api, canvas). `files` maps a picture's name to its path relative to
 * the report (the artifact's files).
 */
export function applyAudit(result, judged, files = {}) {
  Object.assign(result, { api: judged.api ?? null, canvas: judged.canvas, controls: judged.controls || {}, numbers: judged.numbers || {}, actions: [...(judged.actions || [])] });
  result.verdict = verdictOf(judged.checks, judged.fail);
  result.reasons = reasonsOf({ fail: judged.fail, checks: judged.checks, pageErrors: (result.errors || []).filter((e) => /page error/.test(e)) });
  const slow = judged.tooHeavy ? 'too heavy' : 'too slow';
  result.status = judged.fail ? 'failed' : judged.tooSlow ? slow : 'ok';
  if (judged.notGraded) {
    // the browser could not run it (WebGPU in Firefox ESR): no verdict; what was seen stays below
    result.verdict = NOT_GRADED;
    result.status = judged.tooSlow ? slow : NOT_GRADED;
    result.reasons = [judged.notGraded, ...result.reasons.map((r) => `(seen here: ${r})`)];
  }
  result.pass = result.verdict === 'pass';
  const kept = result.images || {};
  result.images = {};
  for (const [k, name] of Object.entries(judged.shown || {})) if (files[name]) result.images[k] = files[name];
  for (const k of ['reference', 'diff']) if (kept[k]) result.images[k] = kept[k];
  return result;
}
