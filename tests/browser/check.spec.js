// The self-check page (check/): a student picks a hand-in folder and gets the grader's verdicts,
// in the browser, nothing installed. Here hand-ins are picked through the folder input
// (setInputFiles on <input webkitdirectory>) in a Chromium with WebGPU, and the page's verdicts
// (window.check) are compared with the grader's:
// - npm test: a representative two (our own site in WebGPU, the API only this Chromium gives the
//   check page, and `cy`, one WebGL mistake a part), against their labels, which the grader agrees
//   with on every labelled part (tests/unit/grader-class.test.js; our site in WebGL there too);
//   the check page in WebGL is also held to the grader in Firefox on ../shared/handins
//   (grader.spec.js) and on pages that begin with their scripts (check-guard.spec.js);
// - CHECK_ALL=1 (npm run test:check-all): every hand-in of the fixture class, the hand-written
//   hand-ins and ../shared/handins/ when it is there, against `npm run grade` on the same folders.
// Also: the front page's step pictures are the steps' renders; bad input gets a clear message and
// leaves the page usable; axe finds no serious or critical violation.
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect, chromium } from '@playwright/test';
import { zipSync } from 'fflate';
import { PNG } from 'pngjs';
import { buildClass } from '../fixtures/build.js';
import { copyHandins } from '../fixtures/handins.js';
import { CHROMIUM, CHROMIUM_ARGS, WEBGPU_ARGS } from '../../grader/node/run/chromium.js';
import { STEPS, maxDifference, renderThumbnails, thumbnailPath } from '../../tools/thumbnails.js';
import { readPNG } from '../../tools/reference/png.js';
import { checkFolder, expectAccessible, gradeVerdicts, routeRubric } from './check-helpers.js';
import { AUDITS } from '../../grader/core/audits/index.js';

const ALL = !!process.env.CHECK_ALL;
const SHARED = path.resolve('../shared/handins');
// eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
test.beforeEach(({}, testInfo) => test.skip(testInfo.project.name !== 'webgl2', 'its own Chromium with WebGPU; once is enough'));


test('the front page shows each step as its own render, and links to the self-check', async ({ page }) => {
  test.setTimeout(180_000);
  await page.goto('/');
  const imgs = page.locator('ol.steps img');
  await expect(imgs).toHaveCount(STEPS.length);
  const loaded = await imgs.evaluateAll((els) => els.map((i) => [i.getAttribute('src'), i.complete && i.naturalWidth]));
  expect(loaded).toEqual(STEPS.map((s) => [`${s}/thumbnail.png`, 160]));
  // the pictures are what the steps draw today (npm run thumbnails makes them)
  const shots = await renderThumbnails(page, new URL(page.url()).origin);
  for (const step of STEPS) expect(maxDifference(PNG.sync.read(shots[step]), readPNG(thumbnailPath(step))), `${step}/thumbnail.png is the step's render`).toBeLessThanOrEqual(2);
  await page.goto('/');
  await page.getByRole('link', { name: 'Check your hand-in' }).click();
  await expect(page).toHaveURL(/\/check\/$/);
  await expect(page.locator('input[type=file][webkitdirectory]')).toHaveCount(1);
  await page.goto('/WP04P3/');
  await expect(page.locator('nav').getByRole('link', { name: 'Check your hand-in' })).toHaveAttribute('href', '../check/');
});

test('bad input gets a clear message and the page stays usable; a zip is unpacked in the browser', async ({ page }) => {
  test.setTimeout(180_000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'check-bad-'));
  const make = (rel, text) => { mkdirSync(path.dirname(path.join(dir, rel)), { recursive: true }); writeFileSync(path.join(dir, rel), text); };
  make('notes/readme.txt', 'no pages here');
  make('pages/Part1/notes.txt', 'x');
  make('pages/hello.html', '<!doctype html><title>hello</title><p>hello');
  // a part that never returns, alone: stopped, said so, and the page goes on
  // ... which also asks for a file of another host and one of our site outside the hand-in: blocked, not served
  make('hangs/Part1/index.html', '<!doctype html><title>p1</title><canvas width=64 height=64></canvas>' +
    '<script src="https://cdn.example.com/lib.js"></script><script src="/grader/core/rubric.json"></script><script>for (;;) {}</script>');
  const message = () => page.locator('#messages').innerText();
  // the loop is stopped after loadSeconds: 2 s here, not the shipped 20 (check-guard.spec.js holds each form)
  await routeRubric(page, { loadSeconds: 2 });

  await page.goto('/check/');
  await page.locator('#folder').setInputFiles(path.join(dir, 'notes'));
  await page.waitForFunction(() => window.check.done);
  expect(await message()).toMatch(/No HTML page in what you dropped \(1 files\)/);
  await page.locator('#folder').setInputFiles(path.join(dir, 'pages'));
  await page.waitForFunction(() => window.check.done);
  expect(await message()).toMatch(/None of the HTML pages is named for a part of worksheet 4 \(hello\.html\)/);
  await expectAccessible(page, 'the check page with a message');

  // a .zip of a folder, through the zip input: unpacked, its top folder taken as the root
  const zip = zipSync({ 'hangs/Part1/index.html': readFileSync(path.join(dir, 'hangs/Part1/index.html')) });
  writeFileSync(path.join(dir, 'hangs.zip'), zip);
  await page.locator('#zip').setInputFiles(path.join(dir, 'hangs.zip'));
  await page.waitForFunction(() => window.check.done, null, { timeout: 120_000 });
  const check = await page.evaluate(() => window.check);
  expect(check.parts.map((p) => [p.part, p.verdict])).toEqual([['WP04P1', 'fail'], ['WP04P2', 'fail'], ['WP04P3', 'fail'], ['WP04P4', 'fail'], ['WP04P5', 'fail']]);
  expect(check.parts[0].reasons[0]).toMatch(/did not finish loading in \d+ s .*a loop ran for \d+ s without returning/);
  expect(check.parts[1].reasons[0]).toBe('no page for WP04P2 was found in the submission');
  await expect(page.locator('#card-WP04P1 .slide')).toContainText('Draw a solid sphere');
  await expect(page.locator('#card-WP04P1').getByRole('link', { name: /Our WP04P1/ })).toHaveAttribute('href', '../WP04P1/');
  // no WebGPU adapter in this Chromium, and none asked for: nothing said of it (check-guard.spec.js: a WebGPU part here)
  await expect(page.locator('#messages')).toBeEmpty();
  await expect(page.locator('#card-WP04P1')).toContainText('request: https://cdn.example.com/lib.js');
  await expect(page.locator('#card-WP04P1')).toContainText('missing file: /grader/core/rubric.json');

  // a browser that refuses service workers
  const blocked = await page.context().browser().newContext({ serviceWorkers: 'block' });
  const p2 = await blocked.newPage();
  await p2.goto(page.url());
  await p2.locator('#folder').setInputFiles(path.join(dir, 'hangs'));
  await p2.waitForFunction(() => window.check.done);
  await expect(p2.locator('#messages')).toContainText('service worker');
  await blocked.close();
});

/** The class: the fixture class and the hand-written hand-ins (labelled), and ../shared/handins/ (with CHECK_ALL). */
function theClass() {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'check-class-'));
  const { labels } = buildClass(path.join(dir, 'class'));
  Object.assign(labels, copyHandins(path.join(dir, 'class')));
  if (ALL && existsSync(SHARED)) {
    for (const name of readdirSync(SHARED)) {
      if (statSync(path.join(SHARED, name)).isDirectory()) cpSync(path.join(SHARED, name), path.join(dir, 'class', `shared-${name}`), { recursive: true });
    }
  }
  const names = readdirSync(path.join(dir, 'class')).filter((n) => statSync(path.join(dir, 'class', n)).isDirectory()).sort();
  return { dir, labels, names };
}

test('the check page gives the grader\'s verdicts: our own site passes in WebGPU, mistakes get their reviews', async () => {
  const { dir, labels, names } = theClass();
  // CHECK_ONLY=regex: a share of the class (to split the whole comparison into runs)
  const picked = ALL ? names.filter((n) => new RegExp(process.env.CHECK_ONLY || '.').test(n)) : ['own-gpu', 'cy'];
  test.setTimeout((ALL ? 600 + 150 * picked.length : 150 * picked.length) * 1000);
  // the grader itself on the same folders (CHECK_ALL); in npm test the labels stand for it
  const graded = ALL ? gradeVerdicts(dir, picked) : null;
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] });
  const rows = [];
  try {
    // a context of its own: axe (expectAccessible) opens its frames in the page's context
    const context = await browser.newContext({ viewport: { width: 1200, height: 900 }, deviceScaleFactor: 1, baseURL: test.info().project.use.baseURL });
    const page = await context.newPage();
    for (const name of picked) {
      // our step drawn beside each part on our own site's check (the check page's default); left out elsewhere
      const { check, seconds } = await checkFolder(page, path.join(dir, 'class', name), { query: ALL || name !== 'own-gpu' ? '?reference=0' : '' });
      expect(check.error, name).toBeUndefined();
      const apis = [...new Set(check.parts.map((p) => p.api).filter(Boolean))].join('+');
      console.log(`check: ${name} in ${seconds.toFixed(0)} s (${apis}): ${check.parts.map((p) => p.verdict).join(' ')}`);
      if (name === 'own-gpu' || name === 'cy') await expectAccessible(page, `the check page with ${name}'s cards`);
      if (name === 'cy') {
        // every reason shows its audit's id, and each slide a review quotes is named by the audit that asks it
        expect(check.parts.flatMap((p) => p.findings).every((f) => f.id), 'every finding has its audit id').toBe(true);
        const tags = await page.locator('.card .reasons li').evaluateAll((lis) => lis.map((li) => [li.dataset.audit, li.querySelector('code.audit') && li.querySelector('code.audit').textContent,
          li.querySelector('code.audit') && li.querySelector('code.audit').title, /^(REVIEW|FAIL): /.test(li.textContent)]));
        expect(tags.length).toBeGreaterThan(5);
        for (const [id, shown] of tags) expect(shown).toBe(id);
        // its tooltip: the audit's title where it passed, the title a part that misses it gets where it asks, and what it checks
        for (const [id, , tip, asks] of tags.filter(([id]) => AUDITS[id])) expect(tip).toBe(`${asks ? AUDITS[id].failureTitle : AUDITS[id].title}: ${AUDITS[id].description}`);
        expect(tags.some(([, , , asks]) => asks)).toBe(true);
        expect(await page.locator('.card .slide[data-audit]').count()).toBeGreaterThan(0);
      }
      for (const p of check.parts) {
        const want = graded ? graded[name][p.part] : labels[name] && labels[name][p.part];
        if (!want || want.status === 'missing') continue; // not handed in: both say so
        rows.push({ name, part: p.part, check: p.verdict, grade: want.verdict, reasons: p.reasons, gradeReasons: want.reasons || [want.because] });
        if (p.verdict !== want.verdict) console.log(`differs: ${name} ${p.part}: check ${p.verdict} (${p.reasons.join(' | ')}), ${graded ? 'grade' : 'label'} ${want.verdict} (${(want.reasons || [want.because]).join(' | ')})`);
      }
      if (name === 'own' || name === 'own-gpu') {
        expect(check.parts.map((p) => [p.part, p.verdict, p.api]), `${name}: our own site`).toEqual(STEPS.map((s) => [s, 'pass', name === 'own' ? 'webgl2' : 'webgpu']));
      }
    }
  } finally {
    await browser.close();
  }
  const differ = rows.filter((r) => r.check !== r.grade);
  console.log(`check = ${graded ? 'grade' : 'labels'} on ${rows.length - differ.length} of ${rows.length} parts`);
  expect(rows.length).toBeGreaterThanOrEqual(10);
  if (ALL) expect(differ.length, 'parts where the check page and the grader differ').toBeLessThanOrEqual(Math.floor(0.05 * rows.length));
  else expect(differ.map((r) => `${r.name} ${r.part}`)).toEqual([]);
});
