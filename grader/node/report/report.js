// The grading report of an out folder: report.json (the verdicts, reasons and numbers of every
// part, and the agreement with a teacher's labels) and report.html (report-html.js: the class grid,
// then each part's reasons, pictures and numbers), as npm run grade writes them.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { PARTS } from '../../files/parts.js';
import { agreement } from './labels.js';
import { similarityJson } from '../../similarity/run.js';
import { itemAnalysis } from './item-analysis.js';
import { reportHtml } from './report-html.js';

/** The passes of a submission, then its reviews (a count a reader can read: more is better). */
function passes(parts) {
  return parts.filter((p) => p.verdict === 'pass').length;
}

/**
 * Writes report.json and report.html into `out` for the graded `submissions` ({ name, parts }),
 * with the agreement with `labels` (readLabels) where given; returns the submissions sorted as the
 * grid shows them (with their passes and reviews) and the agreement.
 */
export function writeReport(out, submissions, labels = null, similar = null) {
  const rows = submissions
    .map((s) => ({ ...s, passes: passes(s.parts), reviews: s.parts.filter((p) => p.verdict === 'review').length }))
    .sort((a, b) => b.passes - a.passes || b.reviews - a.reviews || a.name.localeCompare(b.name));
  const agreed = labels ? agreement(labels, rows) : null;
  // the browsers that graded, with their versions (a class graded on two machines may name two)
  const browsers = [...new Set(rows.flatMap((s) => s.parts.map((p) => p.browserVersion).filter(Boolean)))].sort();
  const items = itemAnalysis(rows, PARTS);
  // (the labels' rows with the reasons each part was said to give)
  const labelled = agreed && agreed.rows.map(({ asking, ...r }) => ({ ...r, reasons: asking }));
  const said = agreed ? { labels: { ...agreed, rows: labelled } } : {};
  const report = { generated: new Date().toISOString(), browsers, submissions: rows,
    ...(similar ? { similarity: similarityJson(similar) } : {}), itemAnalysis: items, ...said };
  writeFileSync(path.join(out, 'report.json'), JSON.stringify(report, null, 1));
  writeFileSync(path.join(out, 'report.html'), reportHtml({ rows, browsers, agreed, similar, items }));
  return { rows, agreed };
}
