// Browser tests: the machine's Chromium and Firefox (grader/node/run/find-browser.js: Debian's Chromium
// and Firefox ESR here; never a downloaded browser), small canvases,
// one server. Every Chromium spec runs under WebGL 2 (the page's ?api= is set from the project),
// and what the API changes in the page specs again under WebGPU, whose screenshots must match the
// WebGL 2 baselines. The project "firefox" runs firefox.spec.js, which
// launches Firefox itself (puppeteer-core over WebDriver BiDi: tests/browser/firefox-fixtures.js).
import { defineConfig } from '@playwright/test';
import { CHROMIUM, CHROMIUM_ARGS, CHROMIUM_MISSING, WEBGPU_ARGS } from './grader/node/run/chromium.js';

const PORT = Number(process.env.TEST_PORT || 4173);
// (without one, Playwright would ask for a browser of its own to be downloaded: say what to install instead)
if (!CHROMIUM) throw new Error(CHROMIUM_MISSING);

export default defineConfig({
  testDir: 'tests/browser',
  snapshotPathTemplate: 'tests/screenshots/{projectName}/{arg}{ext}',
  timeout: 60_000,
  expect: { timeout: 10_000, toHaveScreenshot: { maxDiffPixelRatio: 0.001, threshold: 0.02 } },
  workers: 2,
  fullyParallel: true,
  forbidOnly: !!process.env.CI,
  reporter: process.env.CI ? 'list' : [['list'], ['html', { open: 'never' }]],
  use: {
    baseURL: `http://127.0.0.1:${PORT}`,
    deviceScaleFactor: 1,
    viewport: { width: 800, height: 700 },
    launchOptions: { executablePath: CHROMIUM, args: CHROMIUM_ARGS },
  },
  projects: [
    // the course's real hand-ins graded live (grader.spec.js): the longest test, queued first so
    // that the others fill the second worker around it instead of waiting on it at the end
    { name: 'handins', testMatch: /grader\.spec\.js/, grep: /real hand-ins/ },
    // Firefox (WebGL 2 and WebGL 1 inside the spec); Playwright's own browser is not used here.
    // Projects are queued in this order: the long tests early (Firefox's grader run is 16 s), the
    // short ones of WebGPU's page specs last, so that neither worker waits on the other at the end
    { name: 'firefox', testMatch: /firefox\.spec\.js/ },
    { name: 'webgl2', use: { api: 'webgl2' }, testIgnore: /(firefox|surface-webgpu)\.spec\.js/, grepInvert: /real hand-ins/ },
    {
      name: 'webgpu',
      use: { api: 'webgpu', launchOptions: { executablePath: CHROMIUM, args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] } },
      testMatch: /(foundation|lighting|faults|edge-cases|webgpu)\.spec\.js/,
      grepInvert: /@any-api/,
      // the same pictures: a WebGPU page is held to the WebGL 2 baselines
      snapshotPathTemplate: 'tests/screenshots/webgl2/{arg}{ext}',
    },
    // WebGL 1 runs the same GLSL and the same JavaScript as WebGL 2 (only getContext differs): it
    // has no project of its own. Firefox's suite runs every step under WebGL 1 (firefox.spec.js),
    // and foundation.spec.js's fallback test holds Chromium's WebGL 1 to the exact sphere. Tests
    // tagged @any-api run once, under WebGL 2: the same JavaScript whichever API (the controls, the
    // URL, fuzzed values), or a picture whose WebGPU twin webgpu.spec.js holds equal to WebGL 2's
    // in the same views.
  ],
  webServer: {
    command: `node tools/serve.js --port ${PORT}`,
    url: `http://127.0.0.1:${PORT}/`,
    // always a server of this checkout: another one already on the port is an error, not a reuse
    // (run two checkouts at once with TEST_PORT=...)
    reuseExistingServer: false,
  },
});
