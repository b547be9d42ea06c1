// The grader (npm run grade) on a class built from tests/fixtures/: our own parts score ~0, known
// mistakes clearly worse, and every broken page gets its status within its time bound.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { buildClass } from '../fixtures/build.js';
import { findParts, partNumber } from '../../tools/grade/parts.js';

test('parts are found by the names students give them', () => {
  for (const [name, n] of [['WP04P1', 1], ['Part2', 2], ['part3', 3], ['p4', 4], ['p05', 5], ['w4p1', 1], ['week04p03', 3], ['part-2', 2]]) {
    expect(partNumber(name), name).toBe(n);
  }
  for (const name of ['week04', 'worksheet4', 'index', 'p12', 'exercise5']) expect(partNumber(name), name).toBeNull();
});

test.describe('grading a class', () => {
  // one grading run, shared by the checks below (serial: one worker runs beforeAll once)
  test.describe.configure({ mode: 'serial', timeout: 300_000 });
  let out, report, started, seconds;
  // eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
  test.beforeAll(async ({}, testInfo) => {
    test.skip(testInfo.project.name !== 'webgl2', 'the grader runs its own Chromium; once is enough');
    const dir = mkdtempSync(path.join(os.tmpdir(), 'class-'));
    buildClass(path.join(dir, 'class'));
    out = path.join(dir, 'report');
    const rubric = path.join(dir, 'rubric.json');
    await import('node:fs').then((fs) => fs.writeFileSync(rubric, JSON.stringify({ timeoutSeconds: 20 })));
    started = Date.now();
    const run = spawnSync(process.execPath, ['tools/grade/grade.js', '--batch', path.join(dir, 'class'), '--rubric', rubric, '--out', out],
      { encoding: 'utf8', timeout: 280_000 });
    seconds = (Date.now() - started) / 1000;
    expect(run.status, run.stderr).toBe(0);
    report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    console.log(`graded the class of ${report.submissions.length} in ${seconds.toFixed(0)} s`);
  });
  const sub = (name) => report.submissions.find((s) => s.name === name);
  const part = (name, p) => sub(name).parts.find((x) => x.part === p);

  test('our own site scores ~0 on every part', () => {
    for (const p of sub('own').parts) {
      expect(p.status, p.part).toBe('ok');
      expect(p.mismatch, p.part).toBeLessThan(0.005);
      expect(p.pass).toBe(true);
    }
  });

  test('known mistakes score clearly worse, part by part', () => {
    for (const p of ['WP04P1', 'WP04P2', 'WP04P4']) {
      expect(part('mistakes', p).status).toBe('ok');
      expect(part('mistakes', p).mismatch, p).toBeGreaterThan(0.1);
      expect(part('mistakes', p).pass).toBe(false);
    }
    expect(part('mistakes', 'WP04P3').status).toBe('missing');
    const names = report.submissions.map((s) => s.name);
    expect(names[0]).toBe('own'); // sorted by score, best first
    expect(names.indexOf('mistakes')).toBeGreaterThan(0);
  });

  test('bad pages get their status and their messages, and the next part goes on', () => {
    expect(part('throws', 'WP04P1').status).toBe('ok');
    expect(part('throws', 'WP04P1').errors.join('\n')).toContain('student bug');
    expect(part('loops', 'WP04P1').status).toBe('timeout');
    expect(part('nocanvas', 'WP04P1').status).toBe('no-canvas');
    expect(part('badshader', 'WP04P1').errors.join('\n')).toMatch(/dialog: Fragment shader: ERROR: 0:4: 'vColour'/);
    const blocked = part('fetches', 'WP04P1').blocked.join('\n');
    expect(blocked).toContain('http://example.com/tracker.js');
    expect(blocked).toContain('https://example.org/collect');
    expect(blocked).toContain('http://example.net/');
    const other = part('othersize', 'WP04P1');
    expect(other.comparison).toBe('object-only');
    expect(other.notes.join('\n')).toMatch(/300×200 canvas was resized/);
  });

  test('the three layouts: every part found, root-absolute paths served, a missing file reported', () => {
    for (const name of ['layout-worksheet', 'layout-js', 'layout-weeks']) {
      expect(sub(name).parts.map((p) => p.status), name).toEqual(['ok', 'ok', 'ok', 'ok', 'ok']);
    }
    expect(part('layout-weeks', 'WP04P1').errors).toContain('missing file: /node_modules/jquery/dist/jquery.min.js');
    expect(part('layout-worksheet', 'WP04P3').file).toBe(path.join('Worksheet4', 'Part3', 'index.html'));
  });

  test('report.html, images and grades.csv are written', () => {
    const html = readFileSync(path.join(out, 'report.html'), 'utf8');
    expect(html).toContain('<h1>Grading report</h1>');
    expect(html).not.toContain('<script');
    expect(existsSync(path.join(out, 'parts/own/WP04P5-diff.png'))).toBe(true);
    const csv = readFileSync(path.join(out, 'grades.csv'), 'utf8').trim().split('\n');
    expect(csv[0]).toMatch(/^name,score,WP04P1_status,WP04P1_mismatch/);
    expect(csv.length).toBe(1 + report.submissions.length);
  });
});

test('a submission folder that does not exist: a clear message and exit code 1', () => {
  const run = spawnSync(process.execPath, ['tools/grade/grade.js', '/nonexistent/student'], { encoding: 'utf8' });
  expect(run.status).toBe(1);
  expect(run.stderr).toContain('grade: no such folder: /nonexistent/student');
  const usage = spawnSync(process.execPath, ['tools/grade/grade.js', '--bogus'], { encoding: 'utf8' });
  expect(usage.status).toBe(2);
  expect(findParts('/nonexistent')).toEqual({ WP04P1: null, WP04P2: null, WP04P3: null, WP04P4: null, WP04P5: null });
});
