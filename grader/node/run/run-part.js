// One part of the plan graded in a browser, the same in either engine: opened (an opener of
// playwright-page.js or firefox-page.js: served by serve-submission.js's rules, time frozen,
// instrumented), gathered and audited (grader/core/grade-part.js), its artifact saved
// (artifacts.js) and its result (core/part-result.js), our reference drawn beside it. Chromium's
// harness runs it as one Playwright test a part (harness.js), Firefox's as a plain Node loop
// (grade-firefox.js).
import { writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { writeArtifact } from './artifacts.js';
import { drawReference } from './reference.js';
import { hrefOf } from '../../files/layout.js';
import { applyAudit, withFindings } from '../../core/part-result.js';
import {
  missingPage, timedOut, stoppedAtFirstFrame, tooSlow, linkedPage, notOpened, asFail, troubleWith, browserFailure,
} from '../../core/audits/page.js';
import { tooSlowWords } from '../../core/verdict.js';
import { deadlineOf } from '../../core/deadline.js';
import { FIRST_FRAME } from '../../core/gather/index.js';
import { gradePart, addTime, addStep } from '../../core/grade-part.js';

// the part's phases around its gathering and judging, as steps (result.steps)
const PHASE_STEPS = { open: 'opening the page', write: 'writing the artifact', close: 'closing the page' };
/** The step of a part gathered again with every frame drawn (its skipped frames could have shown: unseen-frames.js). */
export const EVERY_FRAME_STEP = 'gathering again with every frame drawn';

// the message of an error thrown because Playwright's time bound closed the part's page (the result stays 'timeout')
const CLOSED = /Test ended|Target page, context or browser has been closed/;

/**
 * What stays if the time bound stops the part at the gathering's step `what`: past its first frame
 * the page draws, and a page that draws is too slow here, not broken (the rubric's tooSlowVerdict).
 */
const progressOf = (result, rubric, save) => (what) => {
  if (what === FIRST_FRAME) withFindings(result, [stoppedAtFirstFrame(rubric, what)]);
  else {
    const slow = tooSlow(rubric, tooSlowWords(rubric, what));
    withFindings(Object.assign(result, { verdict: slow.level, status: 'too slow' }), [slow]);
  }
  save(result);
};

/** Did the browser fail itself while `graded` was gathered (its renderer crashed: gather/index.js keeps what came before)? */
const failedItself = (graded) => !!(graded.artifact && graded.artifact.facts && graded.artifact.facts.browserFailed);

/** `graded` with the browser that failed itself while gathering named in its reason (the judging in core/ does not know it). */
function namedBrowser(graded, browserVersion) {
  if (failedItself(graded) && graded.notGradedId === 'browser-failed') {
    graded.notGraded = browserFailure({ message: graded.artifact.facts.browserFailed.message }, browserVersion).reason;
  }
  return graded;
}

/**
 * The part gathered and judged on `opened`'s page (`gather`: gradePart), and, where draws of frames
 * left undone could have shown (grader/browser/unseen-frames.js), gathered again on a page of
 * openers.everyFrame with every frame drawn (`open`: the part opened by an opener), so that what is
 * gathered never depends on the skipping. { graded, opener }: the opener whose page is open now.
 */
export async function gatherDrawn({ opened, opener, openers, open, gather, steps }) {
  const graded = await gather(opened.driver);
  if (failedItself(graded)) return { graded, opener }; // (its page is gone: nothing more to ask it)
  const unseen = openers.everyFrame && opened.driver.unseen ? await opened.driver.unseen() : null;
  if (!(unseen && unseen.unsafe)) return { graded, opener };
  const t0 = Date.now();
  await opener.done(true);
  const again = await open(openers.everyFrame);
  if (again.why) throw new Error(`the page could not be opened again to draw every frame: ${again.why}`);
  const drawn = await gather(again.driver);
  addStep(steps, EVERY_FRAME_STEP, Date.now() - t0);
  return { graded: drawn, opener: openers.everyFrame };
}

/**
 * Grades `item` of `plan` with `openers` ({ student }): writes item.resultFile (first as a
 * timeout, which stays if the part's time bound stops it) and item.artifactDir. `over()` says the
 * time bound has stopped the part (nothing
 * is written after that). `browserVersion` ("Chromium 156.0.8078.108") names the browser that grades it.
 * Returns { browserFailed }: the browser failed itself on this part (the next part wants a fresh one).
 */
export async function runPart({ item, plan, openers, browserVersion = null, over = () => false }) {
  const rubric = plan.rubric;
  const save = (result) => {
    if (over()) return;
    mkdirSync(path.dirname(item.resultFile), { recursive: true });
    writeFileSync(item.resultFile, JSON.stringify(result, null, 1));
  };
  const timedOutPart = { name: item.name, part: item.part, file: item.page, status: 'timeout', verdict: 'fail', api: null };
  const result = withFindings(timedOutPart, [timedOut(rubric)]);
  Object.assign(result, { actions: [], controls: {}, numbers: {}, mismatch: null, rmse: null, pass: false,
    comparison: null, notes: [], errors: [], blocked: [], images: null,
    ...(plan.browser && plan.browser !== 'chromium' ? { browser: plan.browser } : {}),
    ...(browserVersion ? { browserVersion } : {}) });
  // how the part's page was found, where its name did not say it plainly (core/part-names.js)
  if (item.foundBy) result.notes.push(item.foundBy);
  save(result); // what stays if the page never lets go: a timeout
  if (!item.page) {
    withFindings(Object.assign(result, { status: 'missing' }), [missingPage(item.part)]);
    return save(result);
  }
  if (item.linksTo) {
    withFindings(Object.assign(result, { status: 'linked', verdict: 'review' }), [linkedPage(item.part, item.page, item.linksTo)]);
    return save(result);
  }
  const started = Date.now();
  let graded = { fail: null, checks: [], actions: [], images: {}, shown: {}, busy: 0 };
  const files = {};
  let clean = false;
  // where the part's time goes: opening it, each page-interface call, closing it, writing the
  // pictures; and by step: each step of the gathering, and the judging
  const timing = result.timing = {}, steps = result.steps = {};
  const phase = (what, t0, ms = Date.now() - t0) => {
    addTime(timing, what, ms); addStep(steps, PHASE_STEPS[what], ms);
  };
  let opener = openers && openers.student;
  try {
    const t0 = Date.now();
    const { root, page: rel } = item;
    // what the page has said so far (a page opened again says it again)
    const said = { errors: result.errors.length, blocked: result.blocked.length, notes: result.notes.length };
    const open = (o) => {
      for (const k of Object.keys(said)) result[k].length = said[k];
      return o.open({ root, rel, loadSeconds: rubric.loadSeconds, log: result });
    };
    const opened = await open(opener);
    phase('open', t0);
    if (opened.why) Object.assign(graded, asFail(notOpened(opened.why)));
    else {
      // what has been done so far stays in the result if the time bound stops the part
      const deadline = deadlineOf(started, rubric);
      const progress = progressOf(result, rubric, save);
      const gather = (driver) => gradePart(driver, { part: item.part, rubric, deadline, timing, steps, progress });
      ({ graded, opener } = await gatherDrawn({ opened, opener, openers, open, gather, steps }));
      const t0 = Date.now();
      const { facts, images } = graded.artifact;
      if (over()) return;
      const saved = writeArtifact(item.artifactDir, {
        facts: { ...facts, blocked: result.blocked, notes: result.notes },
        images,
      });
      for (const [name, file] of Object.entries(saved)) {
        files[name] = hrefOf(plan.out, path.join(item.artifactDir, file));
      }
      phase('write', t0);
    }
    // (a browser that failed itself while gathering: what it gathered is judged, and the next part gets a fresh one)
    clean = !failedItself(graded);
  } catch (err) {
    if (over() || CLOSED.test(err.message)) throw err; // the time bound: stays 'timeout'
    // the browser's own failure: not graded here; the grader's own trouble with this page: a review
    Object.assign(graded, troubleWith(err, browserVersion));
    if (process.env.GRADE_DEBUG) console.error(err);
  } finally {
    const t0 = Date.now();
    if (!over()) await opener.done(clean);
    phase('close', t0);
  }
  applyAudit(result, namedBrowser(graded, browserVersion), files);
  result.seconds = (Date.now() - started) / 1000;
  save(result);
  if (rubric.reference && graded.images.judged && !graded.fail && !graded.notGraded) {
    await drawReference({ item, plan, result, graded });
    save(result);
  }
  return { browserFailed: graded.notGradedId === 'browser-failed' || failedItself(graded) };
}
