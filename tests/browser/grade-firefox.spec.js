// npm run grade -- --browser firefox: the grader in Debian's Firefox ESR (grader/node/run/grade-firefox.js,
// firefox-page.js), on two hand-written fixture hand-ins: carla's WP04P1 (WebGL, drawn in a
// requestAnimationFrame loop, so it shows only if the driver runs frames) gets its label, pass;
// jonas's WP04P1 (WebGPU, which this Firefox does not have) is "not graded here", with the reason,
// never a fail, and the labels' agreement leaves it out; elin's WP04P2 (its scripts before <html>)
// gets Chromium's verdict, pass. One Firefox grades both, one after the
// other (--workers 1), as each of a class's Firefoxes grades its share. --audit-only says the same
// again from the artifacts. Project "firefox" only.
import { spawnSync } from 'node:child_process';
import { cpSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from '@playwright/test';

const HANDINS = path.resolve(import.meta.dirname, '../fixtures/handins');

test('--browser firefox: a WebGL part gets its label; a WebGPU part is not graded here, said, never failed', () => {
  test.setTimeout(180_000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'grade-firefox-'));
  cpSync(path.join(HANDINS, 'carla/W04/W04P1.html'), path.join(dir, 'class/carla/W04/W04P1.html'));
  cpSync(path.join(HANDINS, 'jonas/WP04P1'), path.join(dir, 'class/jonas/WP04P1'), { recursive: true });
  // elin's P2 has its scripts before <html> (Chromium passes it; Firefox's grader once could not finish on such a page)
  cpSync(path.resolve(import.meta.dirname, '../fixtures/firefox/elin'), path.join(dir, 'class/elin'), { recursive: true });
  const labels = path.join(dir, 'labels.tsv');
  writeFileSync(labels, 'submission\tpart\tlabel\treasons\ncarla\tWP04P1\tcorrect\trAF loop\njonas\tWP04P1\tcorrect\tWebGPU\nelin\tWP04P2\tcorrect\tscripts before <html>\n');
  const out = path.join(dir, 'out');
  const grade = (...args) => spawnSync(process.execPath, ['grader/node/cli/grade.js', ...args, '--rubric', 'tests/fixtures/test-rubric.json', '--labels', labels],
    { encoding: 'utf8', timeout: 170_000 });
  const run = grade('--batch', path.join(dir, 'class'), '--browser', 'firefox', '--workers', '1', '--out', out);
  expect(run.status, run.stderr + run.stdout.slice(-3000)).toBe(0);
  const parts = (report) => Object.fromEntries(report.submissions.flatMap((s) => s.parts.filter((p) => p.status !== 'missing').map((p) => [`${s.name} ${p.part}`, p])));
  const report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
  const got = parts(report);
  const carla = got['carla WP04P1'], jonas = got['jonas WP04P1'];
  expect([carla.verdict, carla.api, carla.browser], carla.reasons.join(' | ')).toEqual(['pass', 'webgl', 'firefox']);
  expect(jonas.verdict, jonas.reasons.join(' | ')).toBe('not graded here');
  expect(jonas.reasons[0]).toMatch(/^not graded here: this part uses WebGPU .* this browser has no WebGPU \(Firefox ESR has none\): grade it in Chromium/);
  expect([got['elin WP04P2'].verdict, got['elin WP04P2'].api], got['elin WP04P2'].reasons.join(' | ')).toEqual(['pass', 'webgl']);
  expect(report.labels).toMatchObject({ agree: 2, total: 2, notGraded: ['jonas WP04P1'] });
  expect(run.stdout).toMatch(/labels: not graded here \(WebGPU, which this browser does not have\), left out of the counts: jonas WP04P1/);
  // judged again from the artifacts Firefox gathered, with no browser: the same
  const again = grade('--audit-only', out);
  expect(again.status, again.stderr).toBe(0);
  const judged = parts(JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')));
  for (const k of Object.keys(got)) expect([k, judged[k].verdict, judged[k].reasons], k).toEqual([k, got[k].verdict, got[k].reasons]);
});
