// The grader's own Playwright Test run: one test per part (grader/node/run/harness.js), its workers,
// its --shard for splitting a class over machines, its reporters: blob (for merge-reports) and the
// command's progress line (the reporter file the command names in GRADE_REPORTER: cli/progress-reporter.js),
// or Playwright's own list (--verbose, GRADE_VERBOSE, or no reporter named).
// Chromium gets a SwiftShader WebGPU adapter too: hand-ins come in both APIs. The browser is the
// one grade.js found (the plan's browserPath: grader/node/run/find-browser.js).
import { defineConfig } from '@playwright/test';
import { CHROMIUM, CHROMIUM_ARGS, WEBGPU_ARGS } from './chromium.js';

const plan = process.env.GRADE_PLAN
  ? JSON.parse(await import('node:fs').then((fs) => fs.readFileSync(process.env.GRADE_PLAN, 'utf8')))
  : { timeoutSeconds: 30, out: 'out/grade' };

export default defineConfig({
  testDir: '.',
  testMatch: 'harness.js',
  timeout: plan.timeoutSeconds * 1000,
  workers: Number(process.env.GRADE_WORKERS || 2),
  fullyParallel: true,
  retries: 0,
  outputDir: `${plan.out}/test-results`,
  reporter: [
    process.env.GRADE_REPORTER && !process.env.GRADE_VERBOSE
      ? [process.env.GRADE_REPORTER, { plan: process.env.GRADE_PLAN }]
      : ['list'],
    ['blob', { outputDir: `${plan.out}/blob-report` }],
  ],
  use: {
    deviceScaleFactor: 1,
    viewport: { width: 900, height: 900 },
    launchOptions: { executablePath: plan.browserPath || CHROMIUM, args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] },
  },
});
