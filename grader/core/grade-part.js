// Gathering and judging one part in a row (Lighthouse's -GA): the artifact gathered from the page
// (gather/), then audited (audit.js). For the command's Playwright run and for the check page.
import { gatherPart, addTime, addStep, timed } from './gather/index.js';
import { auditPart } from './audit.js';
import { rolesInWords } from './computed/roles.js';

export { addTime, addStep, timed };

/**
 * Grades one opened part: { artifact, fail, checks, actions, controls, numbers, images, api, canvas,
 * timing, steps, busy, tooSlow }. `images` are the pictures a report shows (first, judged, coarse,
 * highlightPlace, leastS); `artifact` ({ facts, images }) is everything gathered.
 */
export async function gradePart(page, { part, rubric, progress, deadline, timing = {}, steps = {} }) {
  const artifact = await gatherPart(page, { part, rubric, progress, deadline, timing, steps });
  const t0 = Date.now();
  const j = judged(artifact, rubric);
  addStep(steps, JUDGING, Date.now() - t0);
  return { ...j, timing, steps, busy: timing.tick ? timing.tick.ms : 0 };
}

/** The step of a part's time spent judging what was gathered (`steps`, beside the gathering's). */
export const JUDGING = 'judging';

/** An artifact's audit in the shape a report reads (`audits`: the units run, audits/list.js's by default). */
export function judged(artifact, rubric, { audits } = {}) {
  const { facts, images } = artifact;
  const a = auditPart(artifact, rubric, audits ? { audits } : {});
  const shown = {};
  for (const [k, name] of Object.entries(a.shown)) if (images[name]) shown[k] = images[name];
  return {
    artifact,
    fail: a.fail,
    failId: a.failId,
    checks: a.checks,
    numbers: a.numbers,
    tooSlow: a.tooSlow,
    tooHeavy: a.tooHeavy,
    notGraded: a.notGraded || null,
    notGradedId: a.notGradedId,
    images: shown,
    shown: a.shown,
    actions: facts.actions,
    controls: rolesInWords(facts, rubric.thresholds),
    api: facts.api,
    canvas: facts.canvas,
  };
}
