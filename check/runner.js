// One part of a hand-in, checked as `npm run grade` checks it: opened in a frame of its own
// (1000 × 1000 CSS pixels, as the grader's page; time frozen; only the hand-in's files served),
// loaded within the rubric's loadSeconds, then driven and judged by the grader's own modules
// (gradePart, tools/grade/drive.js) through the frame's page interface (check/frame-page.js),
// within the rubric's timeoutSeconds. A part that never returns is stopped and said so.
import { framePage } from './frame-page.js';
import { frameWatchScript } from './frame-watch.js';
import { frameClockScript } from './frame-clock.js';
import { instrumentScript } from '../tools/grade/instrument.js';
import { webgpuCaptureScript } from '../tools/webgpu-capture.js';

/** The grader's frozen clock: the same wall time as tools/grade (2026-01-05 09:00 UTC). */
export const FROZEN = Date.UTC(2026, 0, 5, 9, 0, 0);
export const VIEWPORT = 1000;

/** The script every part's HTML gets first: the watch, the WebGPU capture, the grader's instrumentation, the clock. */
export function frameScript(rubric) {
  return [
    `(${frameWatchScript})(${JSON.stringify({ loopSeconds: rubric.loadSeconds ?? 20 })});`,
    `(${webgpuCaptureScript})();`,
    `(${instrumentScript})();`,
    `(${frameClockScript})(${FROZEN});`,
  ].join('\n');
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

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
      await sleep(200);
      if (frame.contentWindow && frame.contentWindow.__checkWatch && frame.contentWindow.__checkWatch.hung) return 'hung';
    }
  })();
  const how = await Promise.race([loaded, hung, sleep(seconds * 1000).then(() => 'timeout')]);
  return { frame, how };
}

/**
 * Checks one part. Returns the grader's result for it ({ verdict, reasons, api, images, ... }),
 * or a fail with the reason when it cannot be opened or does not finish in time.
 * @param {object} o { part, page (path in the hand-in), session (host.js), rubric, stage (element), gradePart, log (progress text) }
 */
export async function checkPart({ part, page, session, rubric, stage, gradePart, progress = () => {} }) {
  const started = performance.now();
  const loadSeconds = rubric.loadSeconds ?? 20;
  const failed = (reason) => ({ part, verdict: 'fail', reasons: [reason], api: null, images: {}, actions: [], errors: session.log.errors, blocked: session.log.blocked, notes: session.log.notes });
  progress(`opening ${page}`);
  const { frame, how } = await load(stage, session.url(page), loadSeconds);
  try {
    const fp = framePage(frame, session.log);
    const notLoaded = `the page could not be opened: it did not finish loading in ${loadSeconds} s (a script that never returns?)`;
    if (how !== 'load' || fp.hung()) return failed(fp.hung() ? `${notLoaded}: ${fp.hung()}` : notLoaded);
    await session.idle(500, 5000);
    let timer;
    const bound = new Promise((resolve) => { timer = setTimeout(() => resolve('timeout'), (rubric.timeoutSeconds ?? 90) * 1000); });
    const result = await Promise.race([gradePart(fp, { part, rubric, log: progress }), bound]).finally(() => clearTimeout(timer));
    if (result === 'timeout' || fp.hung()) {
      return failed(`the page did not finish within the time bound (${fp.hung() || `${rubric.timeoutSeconds ?? 90} s`}): it never returns, or is far too slow`);
    }
    return { part, ...result, errors: fp.errors(), blocked: fp.blocked(), notes: session.log.notes, seconds: (performance.now() - started) / 1000 };
  } finally {
    frame.remove();
  }
}
