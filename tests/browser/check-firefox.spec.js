// The check page in Firefox ESR (Debian's, through puppeteer-core: tests/browser/firefox-fixtures.js),
// where many students are, and where there is no WebGPU. A hand-in's .zip is picked as a student
// picks it. Project "firefox" only.
// - npm test: the fixture hand-in `early` (tests/fixtures/check/early, check-helpers.js): a page with
//   no <html> or <head> and one with its scripts before <head> pass as in Chromium; its WebGPU part
//   is "not checked here", said once at the top, never a fail; a page the self-check's own script
//   broke gets no verdict.
// The WebGL parts of ../shared/handins/ in Firefox against the grader's verdicts in Chromium are
// held in grader.spec.js, beside the grading they are compared with.
import { mkdtempSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from './firefox-fixtures.js';
import { checkZipInFirefox, earlyHandIn, NO_WEBGPU, zipFolder } from './check-helpers.js';

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
