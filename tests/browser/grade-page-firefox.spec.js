// The class page (grade/) in Firefox ESR (Debian's, through puppeteer-core: firefox-fixtures.js),
// where there is no WebGPU: the built Brightspace download of class-download.js (WebGL parts only)
// picked as a teacher picks it gets the verdicts and reasons of `npm run grade -- --batch
// --browser firefox` on it, and the results' files. Project "firefox" only.
import { mkdtempSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from './firefox-fixtures.js';
import { commandReport, verdictsOf, writeClassDownload } from './class-download.js';

test('the class page in Firefox gives the command\'s verdicts and reasons on a download of WebGL hand-ins', async ({ firefox, baseURL }) => {
  test.setTimeout(300_000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'grade-page-firefox-'));
  const zip = writeClassDownload(path.join(dir, 'download.zip'));
  const command = commandReport(zip, dir, ['--browser', 'firefox']);
  const page = await firefox.newPage();
  try {
    await page.goto(new URL('/grade/?reference=0', baseURL).href);
    await (await page.$('#zip')).uploadFile(zip);
    await page.waitForFunction(() => window.grading && window.grading.done, { timeout: 240_000, polling: 500 });
    const grading = await page.evaluate(() => window.grading);
    expect(grading.error).toBeUndefined();
    expect(verdictsOf(grading.students)).toEqual(verdictsOf(command.report.submissions));
    for (const f of ['report.html', 'report.json', 'grades.csv', 'grades-points.csv', 'grades-brightspace.csv', 'feedback-brightspace.zip']) {
      expect(grading.files, f).toContain(f);
    }
  } finally {
    await page.close();
  }
});
