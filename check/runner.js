// One part of a hand-in, checked as `npm run grade` checks it: opened in a frame of its own
// (1000 × 1000 CSS pixels, as the grader's page; time frozen; only the hand-in's files served),
// loaded within the rubric's loadSeconds, then driven and judged by the grader's own modules
// (gradePart, grader/core/grade-part.js; its verdict and reasons, grader/core/part-result.js) through the
// frame's page interface (check/frame-page.js), within the rubric's timeoutSeconds. A part that
// never returns is stopped and said so. A part this browser cannot run (WebGPU here without it), or
// whose page the self-check's own instrumentation broke, gets no verdict: "not checked here"
// (check/not-checked.js). Our own part can be drawn beside it (drawReference).
import { framePage } from './frame-page.js';
import { frameWatchScript } from './frame-watch.js';
import { FROZEN, clockScript } from '../grader/browser/clock.js';
import { drawBatchScript } from '../grader/browser/draw-batch.js';
import { instrumentScript } from '../grader/browser/instrument.js';
import { recordersInit } from '../grader/browser/geometry.js';
import { nativesInit } from '../grader/browser/natives.js';
import { stayInit } from '../grader/browser/stay.js';
import { pixelsScript } from '../grader/browser/pixels.js';
import { canvasesScript } from '../grader/browser/canvases.js';
import { tamperScript } from '../grader/browser/tamper.js';
import { webgpuCaptureScript } from '../grader/browser/webgpu-capture.js';
import { gradePart } from '../grader/core/grade-part.js';
import { judgement, notJudgedHere, statusOf } from '../grader/core/part-result.js';
import { NOT_GRADED } from '../grader/core/verdict.js';
import { timedOut, notOpened, asFail, graderTrouble } from '../grader/core/audits/page.js';
import { referenceQuery, referencePicture } from '../grader/core/reference-state.js';
import { deadlineOf } from '../grader/core/deadline.js';
import { NOT_CHECKED, notCheckedHere } from './not-checked.js';
import { MS_PER_SECOND } from '../grader/core/units.js';

export const VIEWPORT = 1000;

/** The script every part's HTML gets first: the watch, the WebGPU capture, the draw batching and the grader's instrumentation, the clock. */
export function frameScript(rubric) {
  return [
    nativesInit, // (first: the browser's own WebGL functions)
    stayInit, // (the page kept open where it is: no close, no leaving once loaded)
    `(${frameWatchScript})(${JSON.stringify({ loopSeconds: rubric.loadSeconds })});`,
    webgpuCaptureScript,
    drawBatchScript,
    instrumentScript,
    `(${pixelsScript})();`,
    `(${canvasesScript})();`,
    recordersInit,
    clockScript(FROZEN),
    `(${tamperScript})();`,
  ].join('\n');
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/** How often a loading frame is looked at for a loop that never returns. */
const HUNG_POLL_MS = 200;

/** Loads `src` in a new frame in `stage`: 'load', 'hung' (a loop stopped) or 'timeout'. */
async function load(stage, src, seconds) {
  const frame = document.createElement('iframe');
  // no popups, no top navigation, no dialogs (frame-watch.js records them), no downloads
  frame.setAttribute('sandbox', 'allow-scripts allow-same-origin allow-forms allow-pointer-lock');
  frame.title = 'The part being checked';
  frame.width = frame.height = String(VIEWPORT);
  const loaded = new Promise((resolve) => frame.addEventListener('load', () => resolve('load'), { once: true }));
  frame.src = src;
  stage.replaceChildren(frame);
  const hung = (async () => {
    for (;;) {
      await sleep(HUNG_POLL_MS);
      if (frame.contentWindow && frame.contentWindow.__checkWatch && frame.contentWindow.__checkWatch.hung) return 'hung';
    }
  })();
  const how = await Promise.race([loaded, hung, sleep(seconds * MS_PER_SECOND).then(() => 'timeout')]);
  return { frame, how };
}

/**
 * Checks one part. Returns what report.json says of it ({ part, verdict, reasons, api, actions,
 * controls, numbers, errors, blocked, notes, seconds }) and its pictures (images: { first, judged,
 * ... } as { width, height, data }).
 * A part not checked here has verdict NOT_CHECKED, its reason first, and notChecked: 'webgpu' | 'instrumentation'.
 * @param {object} o { part, page (path in the hand-in), session (host.js), rubric, stage (element), progress (text),
 *   webgpuHere (this browser has WebGPU and an adapter), graderWords (the class page: where the grader
 *   itself gives no verdict, its words stand, as the command's report has them) }
 */
export async function checkPart(o) {
  const { part, page, session, rubric, stage, progress = () => {}, webgpuHere = true, graderWords = false } = o;
  const started = performance.now();
  const loadSeconds = rubric.loadSeconds;
  let graded = { fail: null, checks: [], actions: [], images: {}, busy: 0 };
  progress(`opening ${page}`);
  const { frame, how } = await load(stage, session.url(page), loadSeconds);
  const fp = framePage(frame, session.log);
  const broken = [];
  try {
    if (how === 'load' && !fp.hung() && !frame.contentWindow.__checkWatch) {
      broken.push('the self-check\'s own script did not run in the page');
    } else if (how !== 'load' || fp.hung()) {
      const notLoaded = `it did not finish loading in ${loadSeconds} s (a script that never returns?)`;
      Object.assign(graded, asFail(notOpened(fp.hung() ? `${notLoaded}: ${fp.hung()}` : notLoaded)));
    } else {
      await session.idle();
      frame.contentWindow.__checkWatch.setLoopSeconds(rubric.timeoutSeconds);
      let timer;
      const bound = new Promise((resolve) => {
        timer = setTimeout(() => resolve('timeout'), rubric.timeoutSeconds * MS_PER_SECOND);
      });
      // a loop stopped after loading (in a promise, a frame, a handler) is a page that never returns, as
      // under the grader, whatever was judged meanwhile; the grader's outer bound (core/deadline.js)
      const deadline = deadlineOf(Date.now(), rubric);
      const grading = fp.hung() ? Promise.reject(new Error('hung')) : gradePart(fp, { part, rubric, progress, deadline });
      grading.catch(() => {}); // after the time bound the frame is gone, and so is the grading
      try {
        const r = await Promise.race([grading, bound]);
        if (r === 'timeout') Object.assign(graded, asFail(timedOut(rubric)));
        else graded = r;
      } catch (err) {
        // the grader's own trouble with this page: never a pass on it, a teacher looks (as harness.js)
        if (!fp.hung()) graded.checks = [graderTrouble(err)];
      } finally {
        clearTimeout(timer);
      }
      if (fp.hung()) Object.assign(graded, asFail(timedOut(rubric, fp.hung())));
    }
  } finally {
    frame.remove();
  }
  const seconds = (performance.now() - started) / MS_PER_SECOND;
  const errors = fp.errors();
  const result = {
    part,
    file: page,
    api: graded.api ?? null,
    canvas: graded.canvas,
    controls: graded.controls || {},
    numbers: graded.numbers || {},
    ...judgement(graded, errors),
    status: statusOf(graded),
    actions: graded.actions || [],
    images: graded.images || {},
    errors,
    blocked: fp.blocked(),
    notes: [...session.log.notes],
    seconds,
  };
  // a part the grader itself does not grade here (too slow or too heavy with nothing wrong found, the
  // browser failing): no verdict, what was seen below, as part-result.js's applyAudit says it
  if (graded.notGraded) notJudgedHere(result, NOT_GRADED, graded.notGraded, (r) => `(seen here: ${r})`, graded.notGradedId || 'not-graded');
  // what the grader would have said stays below, for the student to read, but is no verdict
  const usedWebGPU = session.log.webgpu || graded.api === 'webgpu' || errors.some((e) => /requestAdapter|navigator\.gpu|\bgpu is (undefined|null)/.test(e));
  const not = notCheckedHere({ webgpuHere, usedWebGPU, api: graded.api, broken: [...broken, ...fp.broken()] });
  if (not && !(graderWords && result.verdict === NOT_GRADED)) {
    Object.assign(notJudgedHere(result, NOT_CHECKED, not.reason, (r) => `(the check saw: ${r})`, 'not-checked'), { notChecked: not.why });
  }
  return result;
}

/**
 * Our own part beside the student's, as the grader's report has it: the exact sphere our page shows
 * at the student's canvas size, lit from the light the judge fitted (core/reference-state.js).
 * { width, height, data } or null.
 */
export function drawReference({ result, rubric }) {
  const judged = result.images.judged;
  if (!judged || result.verdict === 'fail') return null;
  const query = referenceQuery(judged, result.numbers, rubric.thresholds, {}, result.part);
  return referencePicture(result.part, query, judged).img;
}
