// The grader's harness in Chromium: one Playwright test per part of the plan that
// grader/node/cli/grade.js wrote (GRADE_PLAN), each graded by run-part.js in pages opened by
// playwright-page.js (served by serve-submission.js, time frozen, instrumented). The test's time
// bound is the part's: a part it stops stays a timeout. (Firefox: grade-firefox.js.)
import { test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { partOpener } from './playwright-page.js';
import { runPart } from './run-part.js';
import { browserLabel } from './browser-version.js';

const plan = JSON.parse(readFileSync(process.env.GRADE_PLAN, 'utf8'));

// a worker's parts open one after another in one page (and ours beside them in another)
let openers = null;

for (const item of plan.items) {
  // a part not handed in is written without a browser: a worker (a shard) with only such parts
  // never starts Chromium
  if (!item.page) {
    test(`${item.name} ${item.part}`, () => runPart({ item, plan, openers: null }));
    continue;
  }
  test(`${item.name} ${item.part}`, async ({ browser }) => {
    // (a part whose skipped frames could have shown is gathered again with every frame drawn: run-part.js)
    openers ??= {
      student: partOpener(browser, 'submission.localhost', { skipUnseen: true }),
      everyFrame: partOpener(browser, 'submission.localhost'),
    };
    const browserVersion = browserLabel(plan.browserName || 'Chromium', browser.version());
    await runPart({ item, plan, openers, browserVersion });
  });
}
