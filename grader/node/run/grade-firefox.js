// The grader's harness in Firefox ESR (npm run grade -- --browser firefox): the plan's parts, the
// same items as Chromium's harness.js runs, graded by run-part.js in a plain Node loop, with
// pages opened by firefox-page.js; each worker drives a Firefox of its own. The same artifacts and
// results are written, so report.js, --report-only and --audit-only read them as Chromium's. A
// part's time bound is the rubric's: a part it stops stays a timeout, and
// its worker's Firefox is ended and started again for the next part.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { launchFirefox } from './firefox.js';
import { firefoxOpener } from './firefox-page.js';
import { runPart } from './run-part.js';
import { browserLabel } from './browser-version.js';
import { verdictOfPart } from '../../files/part-verdict.js';

// nothing leaves the page but through the grader's serving (firefox-page.js): a request it does not
// see (a popup's, a worker's) goes to a proxy that is not there; and no favicon is asked for (Chromium's
// headless pages ask for none: a hand-in has none, and its 404 would be listed as the page's error)
export const NO_NETWORK = {
  'browser.chrome.site_icons': false,
  'dom.security.https_first': false, // (an address is asked for as the page wrote it, and listed so)
  'dom.security.https_first_schemeless': false,
  'network.proxy.type': 1, 'network.proxy.http': '127.0.0.1', 'network.proxy.http_port': 9,
  'network.proxy.ssl': '127.0.0.1', 'network.proxy.ssl_port': 9, 'network.proxy.no_proxies_on': '',
  'network.proxy.allow_hijacking_localhost': true,
};

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * Grades `plan`'s items with `workers` Firefoxes at once. `progress` (progress.js's
 * gradingProgress) hears each part as it ends; without it, `say(line)` hears a line a part.
 * Returns { graded, timedOut }.
 */
export async function gradeInFirefox(plan, { workers = 2, say = console.log, progress = null } = {}) {
  const queue = [...plan.items];
  const total = queue.length;
  let graded = 0, timedOut = 0;
  const worker = async () => {
    let browser = null, openers = null, browserVersion = null;
    const end = async () => {
      const b = browser;
      browser = openers = null;
      if (!b) return;
      const proc = b.process();
      await Promise.race([b.close().catch(() => {}), sleep(5000)]);
      if (proc && proc.exitCode === null) proc.kill('SIGKILL');
    };
    try {
      for (let item = queue.shift(); item; item = queue.shift()) {
        if (!browser && item.page) {
          browser = await launchFirefox({
            extraPrefsFirefox: NO_NETWORK,
            protocolTimeout: 1000 * (plan.timeoutSeconds + 60),
          });
          openers = { student: firefoxOpener(browser, 'submission.localhost') };
          browserVersion = browserLabel(plan.browserName || 'Firefox', await browser.version().catch(() => ''));
        }
        const started = Date.now();
        const limit = plan.timeoutSeconds * 1000;
        let over = false;
        const running = runPart({
          item,
          plan,
          openers,
          browserVersion: item.page ? browserVersion : null,
          over: () => over,
        }).then(
          (r) => (r && r.browserFailed ? 'browser failed' : 'done'),
          (err) => err,
        );
        let how;
        while (!(how = await Promise.race([running, sleep(250).then(() => null)]))) {
          if (Date.now() - started > limit) {
            over = true;
            how = 'timeout';
            break;
          }
        }
        const seconds = ((Date.now() - started) / 1000).toFixed(1);
        graded++;
        if (how === 'timeout') {
          timedOut++;
          await end(); // a page that never lets go takes its Firefox with it
        } else if (how !== 'done' && how !== 'browser failed') {
          // the grader's own trouble outside the part (the browser went away): the part stays a timeout
          const trouble = `the grader's own trouble: ${how.message.split('\n')[0]}`;
          if (progress) progress.ended(item, { verdict: 'timeout', trouble });
          else say(`  ✘ [${graded}/${total}] ${item.name} ${item.part}: ${trouble}`);
          await end();
          continue;
        }
        const verdict = verdictOfPart(item);
        if (progress) progress.ended(item, { verdict });
        else say(`  ${how === 'timeout' ? '✘' : '✓'} [${graded}/${total}] ${item.name} ${item.part} (${seconds} s) ${verdict}`);
        // a Firefox that failed itself (out of memory, a frame lost) is not trusted with the next part
        if (how === 'browser failed') await end();
      }
    } finally {
      await end();
    }
  };
  try {
    await Promise.all(Array.from({ length: Math.max(1, Math.min(workers, total)) }, worker));
  } finally {
    progress?.finish();
  }
  return { graded, timedOut };
}

// node grader/node/run/grade-firefox.js PLAN [WORKERS]: the plan grade.js wrote (grade.js runs this itself)
if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const plan = JSON.parse(readFileSync(process.argv[2], 'utf8'));
  gradeInFirefox(plan, { workers: Number(process.argv[3] || 2) }).catch((err) => {
    console.error(`grade: ${err.message}`);
    process.exit(1);
  });
}
