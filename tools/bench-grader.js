#!/usr/bin/env node
// The grader's benchmark: grades a labelled class (the course's real hand-ins beside this checkout,
// ../shared/handins, by default) in Chromium and prints what it cost (seconds a part: median, p90,
// slowest; the whole run's wall time) and how far it agrees with the labels. A benchmark, never a
// test: run it on a quiet machine, and compare runs made on the same one.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseOptions, UsageError, wholeNumber } from './cli.js';
import { gradingStats, statsLines } from './bench-grader/stats.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const HELP = `usage: npm run bench:grader -- [--handins DIR] [--labels FILE] [--out DIR] [--workers N] [--json FILE]
Grades a labelled class with npm run grade (Chromium) and prints seconds a part (median, p90,
slowest), the wall time, the parts past the time bound and the agreement with the labels.
  --handins DIR  the class (default ../shared/handins, or HANDINS_DIR)
  --labels FILE  its labels (default DIR/labels.tsv)
  --out DIR      where the grading goes (default a new temporary folder)
  --workers N    parts graded at once (default 2)
  --json FILE    also write the numbers as JSON
Run it with nothing else busy: the seconds are this machine's.
exit codes: 0 measured, 1 the grading failed, 2 bad usage`;

function main() {
  let o;
  try {
    o = parseOptions(process.argv.slice(2), { handins: { type: 'string' }, labels: { type: 'string' }, out: { type: 'string' }, workers: { type: 'string' }, json: { type: 'string' } });
    if (o.workers) wholeNumber(o.workers, '--workers', 1, 16);
  } catch (err) {
    if (!(err instanceof UsageError)) throw err;
    console.error(`bench:grader: ${err.message}\n\n${HELP}`);
    process.exit(2);
  }
  if (o.help) return console.log(HELP);
  const handins = path.resolve(o.handins || process.env.HANDINS_DIR || path.join(repo, '../shared/handins'));
  if (!existsSync(handins)) {
    console.error(`bench:grader: no class at ${handins}: give one with --handins DIR\n\n${HELP}`);
    process.exit(2);
  }
  const labels = o.labels || path.join(handins, 'labels.tsv');
  const out = path.resolve(o.out || mkdtempSync(path.join(os.tmpdir(), 'bench-grader-')));
  console.error(`bench:grader: grading ${handins} into ${out}`);
  const t0 = Date.now();
  const run = spawnSync(process.execPath, [path.join(repo, 'grader/node/cli/grade.js'), '--batch', handins, ...(existsSync(labels) ? ['--labels', labels] : []),
    '--out', out, '--workers', o.workers || '2'], { stdio: ['ignore', 'ignore', 'inherit'] });
  const wall = (Date.now() - t0) / 1000;
  const reportFile = path.join(out, 'report.json');
  if (run.status !== 0 || !existsSync(reportFile)) {
    console.error(`bench:grader: the grading failed (exit ${run.status}); its output is in ${out}`);
    process.exit(1);
  }
  const st = gradingStats(JSON.parse(readFileSync(reportFile, 'utf8')));
  for (const line of statsLines(st, wall)) console.log(`bench:grader: ${line}`);
  if (o.json) writeFileSync(o.json, JSON.stringify({ handins, wallSeconds: wall, ...st }, null, 1));
}

main();
