// The similarity section of the grader's report, found from the class grid: a class of our own
// hand-ins with the planted copies (tests/fixtures/similar/), two of them graded (their parts'
// results written here, as a grading run leaves them), and `grade --similarity-only` rebuilding
// the report from them with no browser of its own.
import { spawnSync } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { test, expect } from '@playwright/test';
import { copyHandins } from '../fixtures/handins.js';

const PARTS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];
let out;
let dir;

// eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
test.beforeAll(({}, testInfo) => {
  test.skip(testInfo.project.name !== 'webgl2', 'the report in Chromium; once is enough');
  dir = mkdtempSync(path.join(os.tmpdir(), 'similar-class-'));
  out = path.join(dir, 'out');
  const cls = path.join(dir, 'class');
  copyHandins(cls);
  cpSync('tests/fixtures/similar', cls, { recursive: true });
  for (const name of ['carla', 'quinn', 'kaja']) {
    mkdirSync(path.join(out, 'parts', name), { recursive: true });
    for (const part of PARTS) {
      writeFileSync(path.join(out, 'parts', name, `${part}.json`), JSON.stringify({ name, part, verdict: 'review', status: 'graded', reasons: [], api: 'webgl', actions: [] }));
    }
  }
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--batch', cls, '--similarity-only', '--out', out], { encoding: 'utf8' });
  expect(run.status, run.stderr).toBe(0);
});
test.afterAll(() => { if (dir) rmSync(dir, { recursive: true, force: true }); });

test('the report leads from the class grid to the planted pair, its fragments side by side', async ({ page }) => {
  await page.goto(pathToFileURL(path.join(out, 'report.html')).href);
  const row = page.locator('#grid tbody tr[data-name="quinn"]');
  await expect(row.locator('.similar-badge')).toHaveText('similar: carla');
  await expect(page.locator('#grid tbody tr[data-name="carla"] .similar-badge')).toHaveText('similar: quinn');
  await expect(page.locator('#grid tbody tr[data-name="kaja"] .similar-badge')).toHaveCount(1); // kaja · nils
  await row.locator('.similar-badge').click();
  const pair = page.locator('section.pair:target');
  await expect(pair).toBeVisible();
  await expect(pair.locator('h3')).toContainText('carla');
  await expect(pair.locator('h3')).toContainText('quinn');
  await expect(pair.locator('.fragment').first().locator('figcaption').nth(1)).toContainText('wk4/p4/index.html');
  await expect(pair.locator('.fragment').first().locator('pre').first().locator('.ln').first()).toHaveText(/^\d+$/);
  await expect(page.locator('#similarity .pointer')).toContainText('never a verdict');
  const json = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
  expect(json.similarity.pairs.some((p) => [p.a, p.b].sort().join() === 'carla,quinn')).toBe(true);
  expect(readFileSync(path.join(out, 'similar.csv'), 'utf8')).toMatch(/"carla","quinn",0\.\d+/);
});
