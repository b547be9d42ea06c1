// The similarity check as the grade command runs it: a progress line, similar.csv, and what the
// report needs. --similarity-only writes a report.html of its own where nothing was graded.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import process from 'node:process';
import { similarity, DEFAULTS } from './index.js';
import { similarCsv, similarityJson, similarityPage } from './report.js';

export { similarityBadges, similarityHtml, SIMILARITY_CSS } from './report.js';
export const SIMILARITY_HELP = `  --similarity-only      compare the hand-ins' code (and the judged pictures of an earlier run in --out) with
                         no grading and no browser; with --batch only
  --similarity-bound X   list pairs whose code is alike by X or more in a part or overall (0-1, default ${DEFAULTS.bound})`;

/** A bound from the command line, or an error message. */
export function parseBound(text) {
  const x = Number(text);
  return Number.isFinite(x) && x > 0 && x <= 1 ? x : null;
}

/** Compares the class, writes similar.csv in `out`, and returns the result. */
export async function runSimilarity(submissions, out, options = {}) {
  const started = Date.now();
  const r = await similarity(submissions, out, options, (done, total) => {
    if (process.stderr.isTTY) process.stderr.write(`\rsimilarity: ${done}/${total} pairs that share code`);
  });
  if (process.stderr.isTTY) process.stderr.write('\n');
  writeFileSync(path.join(out, 'similar.csv'), similarCsv(r));
  const listed = r.pairs.filter((p) => p.listed);
  console.log(`similarity: ${r.classSize} hand-ins, ${r.sharing} pairs share code, ${listed.length} listed at ${r.options.bound} ` +
    `in ${((Date.now() - started) / 1000).toFixed(1)} s` + listed.map((p) => `\n  ${p.a} · ${p.b}: ${Math.round(100 * p.score)}%` +
    (p.samePictures?.length ? ` (same pictures: ${p.samePictures.join(', ')})` : '')).join(''));
  return r;
}

/** --similarity-only with nothing graded: report.html and report.json of the similarity alone. */
export function writeSimilarityReport(out, r, names) {
  writeFileSync(path.join(out, 'report.html'), similarityPage(r, names));
  const report = { generated: new Date().toISOString(), similarity: similarityJson(r) };
  writeFileSync(path.join(out, 'report.json'), JSON.stringify(report, null, 1));
}
export { similarityJson };
