#!/usr/bin/env node
// Two gradings of the same class (npm run grade --out A, then --out B) set side by side: for every
// part, the same verdict and reasons, the same facts and the same pictures pixel for pixel? The
// grader's verdict must not depend on the machine: grade once on a quiet machine and once beside
// busy processes, then run this.
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { readArtifact, listArtifacts } from '../grader/node/run/artifacts.js';
import { parseOptions, UsageError, progressLine } from './cli.js';

const HELP = `usage: node tools/compare-gradings.js --a OUT1 --b OUT2
Compares two grading out folders part by part: verdicts and reasons (parts/), facts and pictures
(artifacts/; a folder of artifacts alone, such as tests/fixtures/artifacts, compares its artifacts).
Prints each difference and a summary.
exit codes: 0 the same, 1 they differ, 2 bad usage`;

function results(out) {
  const m = new Map();
  const dir = path.join(out, 'parts');
  for (const s of existsSync(dir) ? readdirSync(dir) : []) {
    for (const f of readdirSync(path.join(dir, s)).filter((x) => /^WP04P\d\.json$/.test(x))) {
      const r = JSON.parse(readFileSync(path.join(dir, s, f), 'utf8'));
      m.set(`${s} ${f.slice(0, 6)}`, r);
    }
  }
  return m;
}

function main() {
  let o;
  try {
    o = parseOptions(process.argv.slice(2), { a: { type: 'string' }, b: { type: 'string' } });
  } catch (err) {
    if (!(err instanceof UsageError)) throw err;
    console.error(`compare-gradings: ${err.message}\n\n${HELP}`);
    process.exit(2);
  }
  if (o.help) return console.log(HELP);
  if (!o.a || !o.b) {
    console.error(`compare-gradings: give --a and --b\n\n${HELP}`);
    process.exit(2);
  }
  const ra = results(o.a), rb = results(o.b);
  const diffs = [];
  for (const [k, a] of ra) {
    const b = rb.get(k);
    if (!b) { diffs.push(`${k}: only in ${o.a}`); continue; }
    if (a.verdict !== b.verdict) diffs.push(`${k}: verdict ${a.verdict} / ${b.verdict}`);
    if (JSON.stringify(a.reasons) !== JSON.stringify(b.reasons)) diffs.push(`${k}: reasons differ:\n    ${a.reasons.join(' | ')}\n    ${b.reasons.join(' | ')}`);
  }
  let parts = 0, pictures = 0;
  // (a folder of artifacts, such as tests/fixtures/artifacts, compares as it is)
  const artifactsOf = (out) => (existsSync(path.join(out, 'artifacts')) ? path.join(out, 'artifacts') : out);
  const arts = listArtifacts(artifactsOf(o.a));
  const progress = progressLine('compare-gradings');
  for (const [k, { submission, part, dir }] of arts.entries()) {
    progress(`artifact ${k + 1} of ${arts.length}`);
    const a = readArtifact(dir), b = readArtifact(path.join(artifactsOf(o.b), submission, part));
    if (!b) { diffs.push(`${submission} ${part}: no artifact in ${o.b}`); continue; }
    parts++;
    if (JSON.stringify(a.facts) !== JSON.stringify(b.facts)) diffs.push(`${submission} ${part}: facts differ`);
    for (const name of new Set([...Object.keys(a.images), ...Object.keys(b.images)])) {
      const x = a.images[name], y = b.images[name];
      pictures++;
      if (!x || !y || x.width !== y.width || x.height !== y.height || Buffer.compare(Buffer.from(x.data), Buffer.from(y.data)) !== 0) diffs.push(`${submission} ${part}: picture ${name} differs`);
    }
  }
  progress.end(`${arts.length} artifacts compared`);
  for (const d of diffs) console.log(d);
  console.log(`compare-gradings: ${ra.size} parts' verdicts and reasons, ${parts} artifacts with ${pictures} pictures: ${diffs.length ? `${diffs.length} differences` : 'the same'}`);
  process.exit(diffs.length ? 1 : 0);
}

main();
