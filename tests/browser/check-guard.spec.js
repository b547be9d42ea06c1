// The check page against a script that never returns, in each form a hand-in writes it: inline in
// the HTML, in a .js file, in an inline module, in a .mjs and in a .js that a module imports (one
// hand-in, a form a part), and in a WebGPU part's JavaScript (WP04P1; its WP04P2, a page with no
// canvas, shows that the next part is checked). A part's frame shares the check page's thread, so
// only the loop guard (check/guard.js, served by check/serve.js) stops such a loop: without it, the
// check page freezes and the test times out. The rubric's time bounds are shortened (the loop
// is stopped after loadSeconds) so that a form costs seconds, not the shipped 20 s.
// Also: pages that begin with their scripts (no <head> or <html>, scripts before <head>) are
// checked as the grader checks them, and a part gets no verdict where the browser has no WebGPU
// or the self-check's own script broke the page (check-firefox.spec.js does the same in Firefox).
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect, chromium } from '@playwright/test';
import { CHROMIUM, CHROMIUM_ARGS, WEBGPU_ARGS } from '../../grader/node/run/chromium.js';
import { checkFolder, earlyHandIn, routeRubric } from './check-helpers.js';

// eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
test.beforeEach(({}, testInfo) => test.skip(testInfo.project.name !== 'webgl2', 'the check page in Chromium; once is enough'));

const NEXT = { 'WP04P2/index.html': '<!doctype html><title>P2</title><p>a page with no canvas: checked after the loop</p>' };
const page1 = (body) => `<!doctype html><html><head><title>P1</title></head><body><canvas width="64" height="64"></canvas>${body}</body></html>`;
const FORMS = {
  'inline in the HTML': { 'WP04P1/index.html': page1('<script>let n = 0; for (;;) n++;</script>') },
  'in a .js file': { 'WP04P1/index.html': page1('<script src="spin.js"></script>'), 'WP04P1/spin.js': 'var n = 0;\nwhile (true) n++;\n' },
  'in an inline module': { 'WP04P1/index.html': page1('<script type="module">import { n } from "./n.js"; let k = n; do k++; while (k > 0);</script>'), 'WP04P1/n.js': 'export const n = 1;\n' },
  'in a .mjs a module imports': {
    'WP04P1/index.html': page1('<script type="module" src="main.js"></script>'),
    'WP04P1/main.js': "import { spin } from './spin.mjs';\nspin();\n",
    'WP04P1/spin.mjs': 'export function spin() {\n  for (let k = 0; k >= 0; k = (k + 1) % 1000);\n}\n',
  },
  'in a .js a module imports': {
    'WP04P1/index.html': page1('<script type="module">import "./spin.js";</script>'),
    'WP04P1/spin.js': 'export let x = 0;\nfor (;;) x++;\n',
  },
};

/** A hand-in in a new folder from { path: text }, with `next` (by default NEXT: a WP04P2 checked after the loop). */
function handIn(files, next = NEXT) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'check-loop-'));
  for (const [rel, text] of Object.entries({ ...files, ...next })) {
    mkdirSync(path.dirname(path.join(dir, rel)), { recursive: true });
    writeFileSync(path.join(dir, rel), text);
  }
  return dir;
}

/** Checks `dir` with short bounds, and holds: WP04P1 fails for its loop, WP04P2 is checked after it, the page is usable. */
async function expectLoopStopped(page, dir) {
  await routeRubric(page, { loadSeconds: 2, timeoutSeconds: 20 });
  const { check } = await checkFolder(page, dir, { query: '?reference=0', timeout: 150_000 });
  expect(check.error).toBeUndefined();
  const [p1, p2] = check.parts;
  expect([p1.part, p1.verdict]).toEqual(['WP04P1', 'fail']);
  expect(p1.reasons[0]).toMatch(/never returns.*a loop ran for \d+ s without returning \(stopped by the self-check\)/);
  expect([p2.part, p2.verdict, p2.reasons[0]]).toEqual(['WP04P2', 'fail', 'no canvas on the page']);
  await expect(page.locator('#progress')).toHaveText(/^done in \d+ s: 0 of 5 parts pass$/);
  await expect(page.locator('#card-WP04P1')).toContainText('a loop ran for');
  await expect(page.getByLabel('Your worksheet folder:')).toBeEnabled();
}

test.describe('a script that never returns', () => {
  test.setTimeout(180_000);
  // one hand-in whose five parts loop in the five forms, one a part: each is stopped and said, and
  // the next is checked after it (a form whose files the guard misses freezes the page there)
  test(`each form, one a part (${Object.keys(FORMS).join('; ')}): stopped, said, and the next part is checked`, async ({ page }) => {
    const files = {};
    Object.values(FORMS).forEach((form, k) => {
      for (const [rel, text] of Object.entries(form)) files[rel.replace(/^WP04P1\//, `WP04P${k + 1}/`)] = text;
    });
    await routeRubric(page, { loadSeconds: 2, timeoutSeconds: 20 });
    const { check } = await checkFolder(page, handIn(files, {}), { query: '?reference=0', timeout: 150_000 });
    expect(check.error).toBeUndefined();
    expect(check.parts.map((p) => [p.part, p.verdict])).toEqual(Object.keys(FORMS).map((_, k) => [`WP04P${k + 1}`, 'fail']));
    Object.keys(FORMS).forEach((form, k) => {
      expect(check.parts[k].reasons[0], form).toMatch(/never returns.*a loop ran for \d+ s without returning \(stopped by the self-check\)/);
    });
    await expect(page.locator('#progress')).toHaveText(/^done in \d+ s: 0 of 5 parts pass$/);
    await expect(page.locator('#card-WP04P5')).toContainText('a loop ran for');
    await expect(page.getByLabel('Your worksheet folder:')).toBeEnabled();
  });

  test('in a WebGPU part\'s JavaScript, after the adapter and device: stopped, said, and the next part is checked', async ({ baseURL }) => {
    const gpu = 'async function main() {\n' +
      '  const adapter = await navigator.gpu.requestAdapter();\n' +
      '  const device = await adapter.requestDevice();\n' +
      "  document.querySelector('canvas').getContext('webgpu').configure({ device, format: navigator.gpu.getPreferredCanvasFormat() });\n" +
      '  for (let frame = 0; ; frame++) device.queue.submit([]);\n' +
      '}\nmain();\n';
    // a Chromium of its own, with a WebGPU adapter (SwiftShader)
    const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] });
    try {
      const page = await (await browser.newContext({ baseURL })).newPage();
      await page.goto('/check/');
      expect(await page.evaluate(async () => !!(navigator.gpu && await navigator.gpu.requestAdapter())), 'a WebGPU adapter').toBe(true);
      await expectLoopStopped(page, handIn({ 'WP04P1/index.html': page1('<script src="main.js"></script>'), 'WP04P1/main.js': gpu }));
    } finally {
      await browser.close();
    }
  });
});

test('pages that begin with their scripts are checked as any other; no verdict where WebGPU is missing or the self-check broke the page', async ({ page }) => {
  test.setTimeout(180_000);
  // this Chromium has navigator.gpu but no WebGPU adapter (no --enable-unsafe-webgpu)
  const dir = earlyHandIn(mkdtempSync(path.join(os.tmpdir(), 'check-early-')));
  const { check, seconds } = await checkFolder(page, dir, { query: '?reference=0', timeout: 150_000 });
  console.log(`check: early in ${seconds.toFixed(0)} s: ${check.parts.map((p) => p.verdict).join(' | ')}`);
  expect(check.parts.map((p) => [p.part, p.verdict, p.api])).toEqual([
    ['WP04P1', 'pass', 'webgl'], ['WP04P2', 'pass', 'webgl'], ['WP04P3', 'not checked', null], ['WP04P4', 'not checked', null], ['WP04P5', 'fail', null]]);
  for (const p of check.parts.slice(0, 2)) expect(p.reasons.join(' | '), p.part).not.toMatch(/page error|page reported errors/);
  expect(check.parts[2].reasons[0]).toMatch(/^not checked here: this part uses WebGPU, which this browser does not have/);
  expect(check.parts[3].reasons[0]).toMatch(/^not checked here: the self-check's own instrumentation broke this page \(.*__checkWatch/);
  await expect(page.locator('#messages')).toHaveText(/^This browser has no WebGPU, which your WebGPU parts need: they are marked "not checked here", not failed\. Check them in Chromium or Google Chrome/);
  await expect(page.locator('#card-WP04P3 .badge')).toHaveText('not checked here');
  await expect(page.locator('#progress')).toHaveText(/: 2 of 5 parts pass, 2 not checked here$/);
});

// A part the grader itself gives no verdict (too heavy: past the rubric's budget of work, a count of
// vertices, with nothing wrong found) gets none on the check page either: "not graded here", as
// npm run grade says of it (grader.spec.js holds the command to it on the same page and budget).
test('a part past the rubric\'s budget of work is not graded here on the check page, as the command says', async ({ page }) => {
  test.setTimeout(240_000);
  await page.route('**/rubric.json', async (route) => {
    const rubric = await (await route.fetch()).json();
    await route.fulfill({ json: { ...rubric, thresholds: { ...rubric.thresholds, gatherWork: 20e6 } } });
  });
  const { check } = await checkFolder(page, path.resolve('tests/fixtures/heavy/dagny'), { query: '?reference=0', timeout: 200_000 });
  const p5 = check.parts.find((p) => p.part === 'WP04P5');
  expect(p5.verdict).toBe('not graded here');
  expect(p5.reasons[0]).toMatch(/^not graded here: too heavy to grade: the page's own work over the grading \(20 million vertices, draw calls at 80 each\) passed the rubric's budget of 20 million \(gatherWork\)/);
});

// tove's WP04P1 clears its WebGL canvas and paints a sphere on a 2D canvas laid over it: the browser
// shows a sphere, a read-back of the WebGL canvas one grey. The command sees it in its screenshot; the
// check page (and the class page), which cannot photograph the page, draw the canvases laid over it
// (check/frame-page.js's shown): the same review, in the command's words (tests/fixtures/handins/labels.json).
test('a canvas laid over the page\'s canvas is seen on the check page as the command sees it', async ({ page }) => {
  test.setTimeout(120_000);
  const { check } = await checkFolder(page, path.resolve('tests/fixtures/handins/tove'), { query: '?reference=0', timeout: 100_000 });
  const p1 = check.parts.find((p) => p.part === 'WP04P1');
  expect(p1.verdict).toBe('review');
  expect(p1.reasons[0]).toBe('REVIEW: what the page reads back differs from what the browser shows, at the first frame: 56% of the canvas\'s opaque pixels in view (another canvas or an element laid over it, or a CSS filter on it?); the browser\'s picture is shown: a teacher looks');
});
