// The check page in Firefox ESR (Debian's, through puppeteer-core: tests/browser/firefox-fixtures.js),
// where many students are, and where there is no WebGPU. A hand-in's .zip is picked as a student
// picks it. Project "firefox" only.
// - npm test: the fixture hand-in `early` (tests/fixtures/check/early, check-helpers.js): a page with
//   no <html> or <head> and one with its scripts before <head> pass as in Chromium; its WebGPU part
//   is "not checked here", said once at the top, never a fail; a page the self-check's own script
//   broke gets no verdict.
// - CHECK_FIREFOX_ALL=1 (npm run test:check-firefox-all): the WebGL parts of ../shared/handins/
//   against the grader's verdicts (Chromium), the parts that differ named; its WebGPU parts are
//   "not checked here".
import { cpSync, existsSync, mkdtempSync, readdirSync, statSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from './firefox-fixtures.js';
import { checkZipInFirefox, earlyHandIn, gradeVerdicts, zipFolder } from './check-helpers.js';

const SHARED = path.resolve('../shared/handins');
const NO_WEBGPU = /^This browser has no WebGPU, which your WebGPU parts need: they are marked "not checked here", not failed\. Check them in Chromium or Google Chrome/;

test('the check page in Firefox: pages that begin with their scripts pass, a WebGPU part is not checked here, a page the self-check broke gets no verdict', async ({ firefox, baseURL }) => {
  test.setTimeout(240_000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'check-firefox-'));
  const zip = zipFolder(earlyHandIn(dir), path.join(dir, 'early.zip'));
  const page = await firefox.newPage();
  try {
    expect(await page.evaluate(() => 'gpu' in navigator), 'this Firefox has no WebGPU').toBe(false);
    const { check, seconds, message } = await checkZipInFirefox(page, baseURL, zip, { timeout: 200_000 });
    console.log(`check in Firefox: early in ${seconds.toFixed(0)} s: ${check.parts.map((p) => p.verdict).join(' | ')}`);
    expect(check.error).toBeUndefined();
    expect(check.parts.map((p) => [p.part, p.verdict, p.api])).toEqual([
      ['WP04P1', 'pass', 'webgl'], ['WP04P2', 'pass', 'webgl'], ['WP04P3', 'not checked', null], ['WP04P4', 'not checked', null], ['WP04P5', 'fail', null]]);
    for (const p of check.parts.slice(0, 2)) expect(p.reasons.join(' | '), p.part).not.toMatch(/page error|page reported errors|__check/);
    expect(check.parts[2].reasons[0]).toMatch(/^not checked here: this part uses WebGPU, which this browser does not have/);
    expect(check.parts[3].reasons[0]).toMatch(/^not checked here: the self-check's own instrumentation broke this page \(.*__checkWatch/);
    expect(message).toMatch(NO_WEBGPU);
    expect(await page.$eval('#card-WP04P3 .badge', (e) => e.textContent)).toBe('not checked here');
  } finally {
    await page.close();
  }
});

test('shared: the WebGL parts of ../shared/handins get the grader\'s verdicts in Firefox; the WebGPU parts are not checked here', async ({ firefox, baseURL }) => {
  test.skip(!process.env.CHECK_FIREFOX_ALL || !existsSync(SHARED), 'opt-in: npm run test:check-firefox-all, with ../shared/handins');
  const names = readdirSync(SHARED).filter((n) => statSync(path.join(SHARED, n)).isDirectory()).sort();
  test.setTimeout((600 + 120 * names.length) * 1000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'check-firefox-all-'));
  for (const n of names) cpSync(path.join(SHARED, n), path.join(dir, 'class', n), { recursive: true });
  const graded = gradeVerdicts(dir, names); // the grader, in Chromium (with WebGPU)
  const rows = [];
  const page = await firefox.newPage();
  try {
    for (const name of names) {
      const { check, seconds, message } = await checkZipInFirefox(page, baseURL, zipFolder(path.join(dir, 'class', name), path.join(dir, `${name}.zip`)));
      expect(check.error, name).toBeUndefined();
      console.log(`check in Firefox: ${name} in ${seconds.toFixed(0)} s: ${check.parts.map((p) => p.verdict).join(' ')}`);
      for (const p of check.parts) {
        const want = graded[name][p.part];
        if (!want || want.status === 'missing') continue;
        // a WebGPU part: the grader drew it with WebGPU, or it is not checked here for want of WebGPU
        if (want.api === 'webgpu' || /uses WebGPU/.test(p.reasons[0])) {
          expect([p.verdict, message], `${name} ${p.part} (WebGPU)`).toEqual(['not checked', expect.stringMatching(NO_WEBGPU)]);
          continue;
        }
        rows.push({ name, part: p.part, firefox: p.verdict, grade: want.verdict });
        if (p.verdict !== want.verdict) console.log(`differs: ${name} ${p.part}: Firefox ${p.verdict} (${p.reasons.join(' | ')}); grader ${want.verdict} (${want.reasons.join(' | ')})`);
      }
    }
  } finally {
    await page.close();
  }
  const differ = rows.filter((r) => r.firefox !== r.grade);
  console.log(`check in Firefox = grade in Chromium on ${rows.length - differ.length} of ${rows.length} WebGL parts${differ.length ? `; differ: ${differ.map((r) => `${r.name} ${r.part}`).join(', ')}` : ''}`);
  expect(rows.length).toBeGreaterThanOrEqual(25);
  expect(rows.filter((r) => r.firefox === 'not checked'), 'no WebGL part left unchecked').toEqual([]);
  // the engines differ on a part or two (the issue's note: 29 of 30), never on most
  expect(differ.length, 'parts where Firefox\'s check and Chromium\'s grader differ').toBeLessThanOrEqual(2);
});
