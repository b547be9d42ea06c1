// A class split over machines (npm run grade -- --shard I/N): three shards graded apart, each
// into an out folder of its own; their parts/ and artifacts/ copied into one; one --report-only
// (with the download, for the identities and the similarity) gives the report, the grade files
// and the feedback of one run over the whole class, timings aside. A small class built from the
// fixture hand-ins, cheap to grade: bertil's WP04P1 page, handed in as his WP04P2 too, and hugo's
// WP04P1: ten parts, three opened in the browser, in shards 2 and 3 (shard 1 holds parts not
// handed in). Project webgl2 only: the grader runs its own Chromium.
import { spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { unzipSync } from 'fflate';

const HANDINS = path.resolve(import.meta.dirname, '../fixtures/handins');

const grade = (...args) => spawnSync(process.execPath, ['grader/node/cli/grade.js', ...args, '--rubric', 'tests/fixtures/test-rubric.json', '--workers', '1'],
  { encoding: 'utf8', timeout: 170_000 });

/** report.json without what differs run to run: when it was written and how long each part took. */
function reportOf(out) {
  const drop = (x) => (Array.isArray(x) ? x.map(drop) : x && typeof x === 'object'
    ? Object.fromEntries(Object.entries(x).filter(([k]) => !['generated', 'seconds', 'timing', 'steps'].includes(k)).map(([k, v]) => [k, drop(v)])) : x);
  return drop(JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')));
}

/** The files a teacher takes away, byte for byte: the grade files, similar.csv, each feedback page and the feedback zip's entries. */
function filesOf(out) {
  const files = {};
  for (const f of readdirSync(out).filter((n) => /\.csv$/.test(n))) files[f] = readFileSync(path.join(out, f), 'utf8');
  for (const f of readdirSync(path.join(out, 'feedback'))) files[`feedback/${f}`] = readFileSync(path.join(out, 'feedback', f), 'utf8');
  const zip = readdirSync(out).find((n) => /^feedback-.*\.zip$/.test(n));
  // (the zip's own dates are when it was written: its entries are compared)
  for (const [name, data] of Object.entries(unzipSync(readFileSync(path.join(out, zip))))) files[`${zip}:${name}`] = Buffer.from(data).toString('utf8');
  return files;
}

test('--shard 1/3, 2/3 and 3/3 copied together and --report-only give one run\'s report, grade files and feedback', ({}, testInfo) => { // eslint-disable-line no-empty-pattern
  test.skip(testInfo.project.name !== 'webgl2', 'the grader runs its own Chromium; once is enough');
  test.setTimeout(600_000);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'grade-shards-'));
  try {
    const classDir = path.join(dir, 'class');
    cpSync(path.join(HANDINS, 'bertil/ws4/part1.html'), path.join(classDir, 'bertil/ws4/part1.html'));
    cpSync(path.join(HANDINS, 'bertil/ws4/part1.html'), path.join(classDir, 'bertil/ws4/part2.html'));
    cpSync(path.join(HANDINS, 'hugo'), path.join(classDir, 'hugo'), { recursive: true });

    const one = path.join(dir, 'one');
    const run = grade('--batch', classDir, '--out', one);
    expect(run.status, run.stderr + run.stdout.slice(-3000)).toBe(0);

    const merged = path.join(dir, 'merged');
    const shared = [];
    for (let i = 1; i <= 3; i++) {
      const out = path.join(dir, `shard-${i}`);
      const shard = grade('--batch', classDir, '--out', out, '--shard', `${i}/3`);
      expect(shard.status, shard.stderr + shard.stdout.slice(-3000)).toBe(0);
      // each machine's share of the parts, as the CI job uploads it
      const parts = readdirSync(path.join(out, 'parts')).flatMap((s) => readdirSync(path.join(out, 'parts', s)).filter((f) => f.endsWith('.json')).map((f) => `${s} ${f}`));
      shared.push(parts.sort());
      for (const folder of ['parts', 'artifacts']) {
        if (existsSync(path.join(out, folder))) cpSync(path.join(out, folder), path.join(merged, folder), { recursive: true });
      }
    }
    expect(shared.map((p) => p.length), 'the ten parts split over the three shards').toEqual([4, 3, 3]);
    expect(new Set(shared.flat()).size, 'each part graded on one machine only').toBe(10);
    expect(readdirSync(path.join(merged, 'artifacts', 'bertil')).sort(), 'pictures from shards 2 and 3').toEqual(['WP04P1', 'WP04P2']);

    mkdirSync(merged, { recursive: true });
    const report = grade('--batch', classDir, '--report-only', '--out', merged);
    expect(report.status, report.stderr + report.stdout.slice(-3000)).toBe(0);
    expect(reportOf(merged)).toEqual(reportOf(one));
    const [a, b] = [filesOf(merged), filesOf(one)];
    expect(Object.keys(a).sort()).toEqual(Object.keys(b).sort());
    for (const name of Object.keys(b)) expect(a[name], name).toBe(b[name]);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
