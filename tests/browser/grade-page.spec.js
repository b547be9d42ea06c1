// The class page (grade/): a built Brightspace download (tests/browser/class-download.js: three
// students, one wrapped one folder down, one a broken zip) dropped on it gives, with nothing
// installed, the verdicts and reasons of `npm run grade -- --batch` on the same download, and one
// zip of the results holding the report, the grade files and the feedback zip (the same files
// written into a folder the teacher picks); the teacher's verdicts set in its grid; a reload in the
// middle resumes.
import { test, expect } from '@playwright/test';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { unzipSync } from 'fflate';
import { CLASS_ROSTER, commandReport, verdictsOf, writeClassDownload } from './class-download.js';
import { expectAccessible } from './check-helpers.js';
import { publish } from '../../tools/publish.js';
import { startServer } from '../../tools/browser.js';

test.describe.configure({ mode: 'serial' });

/** The results zip the page offers, downloaded: its files. */
async function downloadResults(page, dir) {
  const download = page.waitForEvent('download');
  await page.getByRole('link', { name: 'Download the results (zip)' }).click();
  const saved = path.join(dir, 'results.zip');
  await (await download).saveAs(saved);
  return unzipSync(readFileSync(saved));
}

const GRADE_FILES = ['grades.csv', 'grades-points.csv', 'grades-brightspace.csv'];
const text = (bytes) => new TextDecoder().decode(bytes);

test('a download dropped on the class page gets the command\'s verdicts and reasons and the results in one zip; a verdict the teacher sets in the grid is in them as overrides.tsv puts it in the command\'s', async ({ page }) => {
  test.setTimeout(300_000);
  const dir = mkdtempSync(path.join(tmpdir(), 'grade-page-'));
  const zip = writeClassDownload(path.join(dir, 'download.zip'));
  const roster = path.join(dir, 'classlist.csv');
  writeFileSync(roster, CLASS_ROSTER);
  const command = commandReport(zip, dir, ['--roster', roster, '--due', '2025-10-10 10:00']);
  // nothing leaves the machine: every request the page makes is of its own origin (or its own data: and blob: URLs)
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto('/grade/?reference=0');
  await page.locator('#roster').setInputFiles(roster);
  await page.locator('#due').fill('2025-10-10T10:00');
  await page.locator('#zip').setInputFiles(zip);
  await page.waitForFunction(() => window.grading && window.grading.done, null, { timeout: 240_000, polling: 500 });
  const grading = await page.evaluate(() => window.grading);
  expect(grading.error).toBeUndefined();
  expect(verdictsOf(grading.students)).toEqual(verdictsOf(command.report.submissions));
  const origin = new URL(page.url()).origin;
  expect(requests.filter((u) => !u.startsWith(`${origin}/`) && !/^(data|blob):/.test(u))).toEqual([]);
  await expect(page.locator('#messages')).toContainText('Not in the class list: Broken Zip');
  // a cell open: its reasons, its pictures beside ours and the teacher's controls
  await page.locator('td[data-verdict]').filter({ has: page.getByLabel('Wanda Wire WP04P2: the teacher\'s verdict') }).locator('summary').click();
  await expect(page.getByRole('img', { name: 'Wanda Wire WP04P2: judged' })).toBeVisible();
  await expectAccessible(page, 'the class page with its grid, a cell open');
  const files = await downloadResults(page, dir);
  for (const f of ['report.html', 'report.json', 'grades.csv', 'grades-points.csv', 'grades-brightspace.csv', 'feedback-brightspace.zip']) {
    expect(Object.keys(files), f).toContain(f);
  }
  // the grade files as the command writes them, and the feedback zip with the command's entries
  for (const f of GRADE_FILES) expect(text(files[f]), f).toBe(readFileSync(path.join(command.out, f), 'utf8'));
  expect(text(files['grades-brightspace.csv']), 'the class list\'s ids').toMatch(/00000101/);
  expect(text(files['grades-points.csv']), 'handed in at 10:22, due at 10:00: late').toMatch(/^Wanda Wire,brightspace,640601,39701,2025-10-10T10:22,late,/m);
  const entries = (bytes) => Object.keys(unzipSync(bytes)).sort();
  expect(entries(files['feedback-brightspace.zip'])).toEqual(entries(readFileSync(path.join(command.out, 'feedback-brightspace.zip'))));

  // written into a folder the teacher picks (File System Access; the picker answered with a folder of the origin's private file system)
  await page.evaluate(() => {
    window.showDirectoryPicker = async () => (await navigator.storage.getDirectory()).getDirectoryHandle('picked', { create: true });
  });
  await page.getByRole('button', { name: 'Write them into a folder…' }).click();
  await page.waitForFunction(() => window.grading.written, null, { timeout: 30_000 });
  const written = await page.evaluate(async () => {
    const out = {};
    const walk = async (dir, prefix) => {
      for await (const [name, h] of dir.entries()) {
        if (h.kind === 'directory') await walk(h, `${prefix}${name}/`);
        else out[`${prefix}${name}`] = Array.from(new Uint8Array(await (await h.getFile()).arrayBuffer()));
      }
    };
    await walk(await (await navigator.storage.getDirectory()).getDirectoryHandle('picked'), '');
    return out;
  });
  expect(Object.keys(written).sort()).toEqual(Object.keys(files).sort());
  for (const [f, bytes] of Object.entries(files)) expect(Uint8Array.from(written[f]), f).toEqual(bytes);

  // the teacher's verdict, set in the grid: the command, given the overrides.tsv the page wrote, writes the same grade files and feedback
  const cell = page.locator('td[data-verdict]').filter({ has: page.getByLabel('Wanda Wire WP04P1: the teacher\'s verdict') });
  await cell.locator('summary').click();
  await page.getByLabel('Wanda Wire WP04P1: the teacher\'s verdict').selectOption('pass');
  await page.getByLabel('Wanda Wire WP04P1: a note to the student').fill('A wireframe, but the colours are right: pass.');
  await cell.getByRole('button', { name: 'Set' }).click();
  await page.waitForFunction(() => window.grading.students.find((s) => s.name === 'Wanda Wire').parts[0].verdict === 'pass', null, { timeout: 30_000 });
  const set = await downloadResults(page, dir);
  const tsv = path.join(dir, 'overrides.tsv');
  writeFileSync(tsv, set['overrides.tsv']);
  const again = commandReport(zip, dir, ['--report-only', '--overrides', tsv, '--roster', roster, '--due', '2025-10-10 10:00']);
  for (const f of GRADE_FILES) expect(text(set[f]), f).toBe(readFileSync(path.join(again.out, f), 'utf8'));
  expect(text(set['grades-points.csv'])).toMatch(/^Wanda Wire,.*,1,1,0,0,0,2,5,/m);
  const wanda = Object.keys(set).find((f) => /^feedback\/.*Wanda/.test(f));
  expect(text(set[wanda])).toContain('A wireframe, but the colours are right: pass.');
  expect(text(set[wanda])).toBe(readFileSync(path.join(again.out, wanda), 'utf8'));
});

test('a reload in the middle resumes where it stopped: the hand-ins graded are not graded again, and the verdicts are the same', async ({ page }) => {
  test.setTimeout(300_000);
  const dir = mkdtempSync(path.join(tmpdir(), 'grade-page-reload-'));
  const zip = writeClassDownload(path.join(dir, 'download.zip'));
  await page.goto('/grade/?reference=0');
  await page.locator('#workers').fill('1');
  await page.locator('#zip').setInputFiles(zip);
  // one at a time, in the grid's order (Broken Zip, Signe Søndergård, Wanda Wire): reloaded while Wanda is graded
  await page.waitForFunction(() => window.grading.gradedHere && window.grading.gradedHere.length === 2, null, { timeout: 240_000, polling: 'raf' });
  const before = await page.evaluate(() => window.grading);
  expect(before.done).toBe(false);
  await page.reload();
  await page.locator('#workers').fill('1');
  await page.locator('#zip').setInputFiles(zip);
  await page.waitForFunction(() => window.grading && window.grading.done, null, { timeout: 240_000, polling: 500 });
  const after = await page.evaluate(() => window.grading);
  expect(after.error).toBeUndefined();
  expect(after.resumed).toEqual(before.gradedHere);
  expect(after.gradedHere).toEqual(['Wanda Wire']);
  expect(after.students.map((s) => [s.name, s.parts.map((p) => p.verdict)])).toEqual([
    ['Signe Søndergård', ['pass', 'pass', 'fail', 'fail', 'fail']],
    ['Wanda Wire', ['review', 'pass', 'fail', 'fail', 'fail']],
    ['Broken Zip', ['fail', 'fail', 'fail', 'fail', 'fail']],
  ]);
});

test('the site published as static files under a path (npm run publish-site) grades a download, picked as its folder, on its class page there', async ({ page }) => {
  test.setTimeout(300_000);
  const dir = mkdtempSync(path.join(tmpdir(), 'grade-page-published-'));
  publish(path.join(dir, 'site', '02561'));
  const server = await startServer(path.join(dir, 'site'));
  try {
    // the download as the folder it unpacked into, picked as a folder
    const zip = writeClassDownload(path.join(dir, 'download.zip'));
    const folder = path.join(dir, 'download');
    for (const [name, data] of Object.entries(unzipSync(readFileSync(zip)))) {
      mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
      writeFileSync(path.join(folder, name), data);
    }
    await page.goto(`${server.url}/02561/grade/?reference=0`);
    await page.locator('#folder').setInputFiles(folder);
    await page.waitForFunction(() => window.grading && window.grading.done, null, { timeout: 240_000, polling: 500 });
    const grading = await page.evaluate(() => window.grading);
    expect(grading.error).toBeUndefined();
    // the fixture hand-ins' labels (tests/fixtures/handins/labels.json), which the command's verdicts are held to
    const labels = JSON.parse(readFileSync('tests/fixtures/handins/labels.json', 'utf8'));
    const want = (who) => ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'].map((p) => (labels[who][p] ? labels[who][p].verdict : 'fail'));
    expect(grading.students.map((s) => [s.name, s.parts.map((p) => p.verdict)])).toEqual([
      ['Signe Søndergård', want('signe')], ['Wanda Wire', want('wanda')], ['Broken Zip', ['fail', 'fail', 'fail', 'fail', 'fail']]]);
  } finally {
    server.stop();
  }
});

test('a part during which the page is lost twice is not graded here, with why, and the rest of the class goes on', async ({ page }) => {
  test.setTimeout(300_000);
  const dir = mkdtempSync(path.join(tmpdir(), 'grade-page-lost-'));
  const zip = writeClassDownload(path.join(dir, 'download.zip'));
  const begun = (what) => page.waitForFunction((w) => window.grading.begun && window.grading.begun.includes(w), what, { timeout: 240_000, polling: 'raf' });
  await page.goto('/grade/?reference=0');
  // the page lost (reloaded here, as a renderer that crashed or a tab closed would lose it) twice while Wanda's WP04P1 is graded
  for (let k = 0; k < 2; k++) {
    await page.locator('#workers').fill('1');
    await page.locator('#zip').setInputFiles(zip);
    await begun('Wanda Wire WP04P1');
    await page.reload();
  }
  await page.locator('#workers').fill('1');
  await page.locator('#zip').setInputFiles(zip);
  await page.waitForFunction(() => window.grading && window.grading.done, null, { timeout: 240_000, polling: 500 });
  const grading = await page.evaluate(() => window.grading);
  expect(grading.error).toBeUndefined();
  const wanda = grading.students.find((s) => s.name === 'Wanda Wire').parts;
  expect(wanda.map((p) => p.verdict)).toEqual(['not graded here', 'pass', 'fail', 'fail', 'fail']);
  expect(wanda[0].reasons[0]).toMatch(/^not graded here: the page was lost 2 times while this part was graded/);
  expect(grading.students.find((s) => s.name === 'Signe Søndergård').parts.map((p) => p.verdict)).toEqual(['pass', 'pass', 'fail', 'fail', 'fail']);
});
