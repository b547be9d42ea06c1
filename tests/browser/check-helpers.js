// What the check page's specs share (check.spec.js, check-guard.spec.js, check-firefox.spec.js):
// a folder checked on the check page in Chromium (Playwright) or Firefox (puppeteer-core), the
// grader's verdicts on the same folders, a rubric with shorter time bounds, and the fixture
// hand-in whose pages begin with their scripts (tests/fixtures/check/early).
import { spawnSync } from 'node:child_process';
import { cpSync, mkdirSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { zipSync } from 'fflate';

/** Picks `dir` on the check page and waits for window.check.done; returns window.check and the seconds it took. */
export async function checkFolder(page, dir, { timeout = 300_000, query = '' } = {}) {
  await page.goto(`/check/${query}`);
  const started = Date.now();
  await page.locator('#folder').setInputFiles(dir);
  await page.waitForFunction(() => window.check && window.check.done, null, { timeout, polling: 500 });
  return { check: await page.evaluate(() => window.check), seconds: (Date.now() - started) / 1000 };
}

/** `dir` as a .zip at `zip`, its folder's name on top (as a student zips it). */
export function zipFolder(dir, zip) {
  const files = {};
  const walk = (d, rel) => {
    for (const n of readdirSync(d).sort()) {
      const p = path.join(d, n);
      if (statSync(p).isDirectory()) walk(p, `${rel}${n}/`);
      else files[`${rel}${n}`] = readFileSync(p);
    }
  };
  walk(dir, `${path.basename(dir)}/`);
  writeFileSync(zip, zipSync(files));
  return zip;
}

/**
 * A hand-in's .zip picked on the check page in Firefox (a puppeteer page: Playwright cannot drive
 * Debian's Firefox, nor pick a folder there), as a student does; returns window.check, the seconds
 * it took and the top message.
 */
export async function checkZipInFirefox(page, baseURL, zip, { timeout = 300_000, query = '?reference=0' } = {}) {
  await page.goto(new URL(`/check/${query}`, baseURL).href);
  const started = Date.now();
  await (await page.$('#zip')).uploadFile(zip);
  await page.waitForFunction(() => window.check && window.check.done, { timeout, polling: 500 });
  const check = await page.evaluate(() => window.check);
  return { check, seconds: (Date.now() - started) / 1000, message: await page.$eval('#messages', (e) => e.innerText) };
}

/** `npm run grade -- --batch` on `names` (folders of `dir`/class): { name: { part: { verdict, reasons, api } } }. */
export function gradeVerdicts(dir, names) {
  const batch = path.join(dir, 'batch');
  for (const n of names) cpSync(path.join(dir, 'class', n), path.join(batch, n), { recursive: true });
  const rubric = path.join(dir, 'rubric.json');
  writeFileSync(rubric, JSON.stringify({ reference: false }));
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--batch', batch, '--rubric', rubric, '--out', path.join(dir, 'report')],
    { encoding: 'utf8', timeout: 3_000_000 });
  expect(run.status, run.stderr + run.stdout.slice(-2000)).toBe(0);
  return partsByName(JSON.parse(readFileSync(path.join(dir, 'report', 'report.json'), 'utf8')));
}

/** A report.json's parts by submission and part: { name: { part: { verdict, reasons, api } } }. */
export function partsByName(report) {
  return Object.fromEntries(report.submissions.map((s) => [s.name, Object.fromEntries(s.parts.map((p) => [p.part, p]))]));
}

/** Serves the check page a rubric with these bounds (Playwright's page.route: the check page fetches its rubric.json). */
export async function routeRubric(page, bounds) {
  await page.route('**/rubric.json', async (route) => {
    const rubric = await (await route.fetch()).json();
    await route.fulfill({ json: { ...rubric, ...bounds } });
  });
}

const FIXTURES = path.resolve('tests/fixtures');
/**
 * The hand-in `early` in `dir`: Part1 with no <html> or <head> (the doctype, then the scripts, and
 * a "<head>" in a script's text), Part2 with its scripts before <html> and <head>, both correct
 * WebGL; Part3 a WebGPU part (tests/fixtures/handins/kaja's, which passes where there is WebGPU);
 * Part4 a page whose own global clashes with the self-check's; no Part5. Returns its folder.
 */
export function earlyHandIn(dir) {
  const out = path.join(dir, 'early');
  cpSync(path.join(FIXTURES, 'check/early'), out, { recursive: true });
  cpSync(path.join(FIXTURES, 'handins/finn/common.js'), path.join(out, 'common.js'));
  mkdirSync(path.join(out, 'Part3'), { recursive: true });
  cpSync(path.join(FIXTURES, 'handins/kaja/week4/part3.html'), path.join(out, 'Part3/index.html'));
  return out;
}

/** The top message the check page shows where the browser has no WebGPU. */
export const NO_WEBGPU = /^This browser has no WebGPU, which your WebGPU parts need: they are marked "not checked here", not failed\. Check them in Chromium or Google Chrome/;

/**
 * Each hand-in folder `names` of `dir`, zipped as a student zips it and checked on the check page
 * in Firefox (`firefox`: a puppeteer Browser), one after another in one page:
 * [{ name, parts: window.check.parts, message, seconds }].
 */
export async function checkClassInFirefox(firefox, baseURL, dir, names, zips) {
  const page = await firefox.newPage();
  const out = [];
  try {
    for (const name of names) {
      const { check, seconds, message } = await checkZipInFirefox(page, baseURL, zipFolder(path.join(dir, name), path.join(zips, `${name}.zip`)));
      expect(check.error, name).toBeUndefined();
      console.log(`check in Firefox: ${name} in ${seconds.toFixed(0)} s: ${check.parts.map((p) => p.verdict).join(' ')}`);
      out.push({ name, parts: check.parts, message, seconds });
    }
  } finally {
    await page.close();
  }
  return out;
}

/** No serious or critical violation axe finds on the page as it is now (the frames being graded left out). */
export async function expectAccessible(page, what) {
  const { violations } = await new AxeBuilder({ page }).exclude('#stage').exclude('#stages').analyze();
  const bad = violations.filter((v) => ['serious', 'critical'].includes(v.impact)).map((v) => `${v.id}: ${v.help} (${v.nodes.length}× e.g. ${v.nodes[0].target})`);
  expect(bad, what).toEqual([]);
}
