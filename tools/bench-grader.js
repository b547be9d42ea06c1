#!/usr/bin/env node
// The grader's benchmark: grades a labelled class (the course's real hand-ins beside this checkout,
// ../shared/handins, by default) in Chromium and prints what it cost (seconds a part: median, p90,
// slowest; the whole run's wall time), how far it agrees with the labels, on how many lit parts
// the page's own surface was read (each part's artifact, facts.surface) and on how many slider
// trials the terms were read there (the parts' numbers). A benchmark, never a test: run it on a
// quiet machine, and compare runs made on the same one.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseOptions, UsageError, wholeNumber } from './cli.js';
import { gradingStats, statsLines, medianRun } from './bench-grader/stats.js';

/** The most runs --runs takes (each grades the whole class). */
const MOST_RUNS = 9;

/** surfaceOf(part): the part's facts.surface in the grading `out`'s artifacts (undefined where it has none). */
const surfacesIn = (out) => (p) => {
  const file = path.join(out, 'artifacts', p.name, p.part, 'facts.json');
  return existsSync(file) ? JSON.parse(readFileSync(file, 'utf8')).surface : undefined;
};

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const HELP = `usage: npm run bench:grader -- [--handins DIR] [--labels FILE] [--out DIR] [--workers N] [--runs N] [--json FILE]
Grades a labelled class with npm run grade (Chromium) and prints seconds a part (median, p90,
slowest), the wall time, the parts past the time bound, where the parts' time went (by step and by
page call), on how many lit parts the page's own surface was read (why not, on the rest), on how
many slider trials (P4) the terms were read there (why not, on the rest) and the agreement with
the labels.
  --handins DIR  the class (default ../shared/handins, or HANDINS_DIR)
  --labels FILE  its labels (default DIR/labels.tsv)
  --out DIR      where the grading goes (default a new temporary folder)
  --workers N    parts graded at once (default 2)
  --runs N       grade it N times (each into OUT/run-K) and give the median run's numbers with
                 every run's wall time: one run's wall time varies by a tenth on a quiet machine
  --json FILE    also write the numbers as JSON
Run it with nothing else busy: the seconds are this machine's.
exit codes: 0 measured, 1 the grading failed, 2 bad usage`;

function main() {
  let o;
  try {
    o = parseOptions(process.argv.slice(2), { handins: { type: 'string' }, labels: { type: 'string' }, out: { type: 'string' }, workers: { type: 'string' }, runs: { type: 'string' }, json: { type: 'string' } });
    if (o.workers) wholeNumber(o.workers, '--workers', 1, 16);
    if (o.runs) wholeNumber(o.runs, '--runs', 1, MOST_RUNS);
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
  const top = path.resolve(o.out || mkdtempSync(path.join(os.tmpdir(), 'bench-grader-')));
  const runs = Number(o.runs || 1);
  const measured = [];
  for (let k = 1; k <= runs; k++) {
    const out = runs > 1 ? path.join(top, `run-${k}`) : top;
    console.error(`bench:grader: grading ${handins} into ${out}${runs > 1 ? ` (run ${k} of ${runs})` : ''}`);
    const t0 = Date.now();
    const run = spawnSync(process.execPath, [path.join(repo, 'grader/node/cli/grade.js'), '--batch', handins, ...(existsSync(labels) ? ['--labels', labels] : []),
      '--out', out, '--workers', o.workers || '2'], { stdio: ['ignore', 'ignore', 'inherit'] });
    const wall = (Date.now() - t0) / 1000;
    const reportFile = path.join(out, 'report.json');
    if (run.status !== 0 || !existsSync(reportFile)) {
      console.error(`bench:grader: the grading failed (exit ${run.status}); its output is in ${out}`);
      process.exit(1);
    }
    measured.push({ wall, st: gradingStats(JSON.parse(readFileSync(reportFile, 'utf8')), surfacesIn(out)) });
    if (runs > 1) console.error(`bench:grader: run ${k} of ${runs}: ${wall.toFixed(1)} s`);
  }
  const { wall, st, walls } = medianRun(measured);
  for (const line of statsLines(st, wall)) console.log(`bench:grader: ${line}`);
  if (runs > 1) console.log(`bench:grader: the median of ${runs} runs, whose wall times were ${walls.map((w) => `${w.toFixed(1)} s`).join(', ')}`);
  if (o.json) writeFileSync(o.json, JSON.stringify({ handins, wallSeconds: wall, ...(runs > 1 ? { runWallSeconds: walls } : {}), ...st }, null, 1));
}

main();
