// Judging a gathered part: pure functions from its artifact ({ facts, images }) and the rubric to
// findings ({ id, level, reason }: each said by the audit `id`, audits/index.js), numbers, and the
// pictures a teacher should see. The audits are declared units (audits/unit.js), one point of the
// slides a module (grader/core/audits/), run in the order of audits/list.js, a teacher's reading
// order; the verdict and its reasons come from the findings only (verdict.js). No browser:
// `npm run grade -- --audit-only` re-judges a class from its saved artifacts.
import { checkList } from './verdict.js';
import { auditMeta } from './audits/index.js';
import { AUDIT_LIST } from './audits/list.js';

/**
 * { fail, failId, checks, numbers, shown, notGraded } for one part's artifact: `fail` (a reason,
 * said by the audit `failId`) when the part could not be judged at all, `checks` the findings, `shown` the artifact's picture names a
 * report shows (first, judged, coarse, highlightPlace, leastS); `notGraded` (a reason) when the
 * browser it was gathered in could not run it (WebGPU in Firefox ESR): then no verdict stands,
 * whatever the findings (core/part-result.js). The audits are the units of `audits` (audits/list.js),
 * run in its order; each says its findings under the ids it declares.
 */
export function auditPart({ facts, images }, rubric, { audits = AUDIT_LIST } = {}) {
  const list = checkList(rubric);
  const { checks } = list;
  const thresholds = rubric.thresholds;
  const part = facts.part;
  const must = new Set((rubric.parts[part] || {}).must || []);
  const numbers = {};
  const shown = {};
  if (images.first) shown.first = 'first';
  const litStep = must.has('diffuse') || must.has('highlight');
  const declared = new Map(audits.flatMap((u) => Object.entries(u.meta)));
  // an audit says its findings under an id it declares (audits/index.js, or a unit of the list)
  const sayAs = (id) => list.sayAs(declared.has(id) ? id : auditMeta(id).id);
  const context = {
    facts,
    images,
    thresholds,
    rubric,
    part,
    must,
    litStep,
    sayAs,
    numbers,
    imagesShown: shown,
    notGraded: null,
  };
  const results = {};
  let ended = { fail: null, failId: null };
  for (const u of audits) {
    const r = u.run(context, results);
    if (r && r.end) {
      ended = r.end;
      break;
    }
    results[u.id] = r;
  }
  return {
    fail: ended.fail,
    failId: ended.failId,
    checks,
    numbers,
    shown,
    tooSlow: facts.tooSlow || null,
    tooHeavy: facts.tooHeavy ?? null,
    ...(context.notGraded ? { notGraded: context.notGraded.reason, notGradedId: context.notGraded.id } : {}),
  };
}
