// A student's feedback page (grader/node/report/) opened from disk as a student opens it, with
// the network off: every part's verdict is there, every picture loads (inlined), nothing is
// fetched, no other student is named, and axe finds no serious or critical violation. Made from
// the RECORDED fixture class (tests/fixtures/artifacts/, judged without a browser), in seconds.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { recordedOut, testRubric } from '../unit/recorded-out.js';
import { readClass } from '../../grader/node/report/class-results.js';
import { prepareClass } from '../../grader/node/cli/teacher-loop.js';
import { writeClass } from '../../grader/node/report/report.js';

const NAMES = ['ada', 'cy', 'eve'];
const FULL = { ada: 'Ada Lovelace', cy: 'Cy Twombly', eve: 'Eve Ærø Ås' };
let out, rows;
// one worker: the class is judged once for the three pages
test.describe.configure({ mode: 'serial' });

test.beforeAll(async () => {
  out = mkdtempSync(path.join(os.tmpdir(), 'feedback-spec-'));
  await recordedOut(out, NAMES);
  writeFileSync(path.join(out, 'intake.json'), JSON.stringify({ site: 'moodle', submissions: NAMES.map((n, k) => ({ name: n, identity: { site: 'moodle', name: FULL[n], userId: String(700 + k), submissionId: null, time: null, late: null, source: [`${FULL[n]}_${700 + k}_assignsubmission_file/`] }, earlier: [], notes: [], error: null })) }));
  writeFileSync(path.join(out, 'overrides.tsv'), 'student\tpart\tverdict\tnote\ncy\tWP04P1\tpass\tYour colours are right; the grader misread the background.\n');
  const graded = readClass(path.join(out, 'parts'));
  const loop = prepareClass(out, graded);
  rows = writeClass(out, graded, { site: loop.site, rubric: testRubric() }).rows;
});
test.afterAll(() => rmSync(out, { recursive: true, force: true }));

for (const name of NAMES) {
  test(`${name}'s feedback page, offline: every verdict, every picture, no other student, accessible`, async ({ browser }) => {
    const context = await browser.newContext({ offline: true });
    const page = await context.newPage();
    const fetched = [];
    page.on('request', (r) => { if (!/^(data|file):/.test(r.url())) fetched.push(r.url()); });
    await page.goto(pathToFileURL(path.join(out, 'feedback', `${name}.html`)).href);
    const s = rows.find((x) => x.name === name);
    for (const p of s.parts) {
      await expect(page.locator(`section[data-part="${p.part}"] .verdict strong`)).toHaveText(p.verdict);
    }
    const pictures = await page.locator('img').evaluateAll((imgs) => imgs.map((i) => ({ ok: i.complete && i.naturalWidth > 0, data: i.src.startsWith('data:image/png;base64,') })));
    expect(pictures.length).toBeGreaterThan(0);
    expect(pictures.every((p) => p.ok && p.data)).toBe(true);
    const text = await page.locator('body').innerText();
    expect(text).toContain(FULL[name]);
    for (const other of NAMES.filter((n) => n !== name)) expect(text).not.toContain(FULL[other]);
    if (name === 'cy') await expect(page.locator('section[data-part="WP04P1"] .teacher')).toContainText('Your teacher set this verdict');
    expect(fetched).toEqual([]);
    const { violations } = await new AxeBuilder({ page }).analyze();
    expect(violations.filter((v) => ['serious', 'critical'].includes(v.impact)).map((v) => `${v.id}: ${v.help}`)).toEqual([]);
    await context.close();
  });
}
