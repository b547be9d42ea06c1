// The grading report of a class as files: report.json (the verdicts, reasons and numbers of every
// part, and the agreement with a teacher's labels) and report.html (report-html.js: the class grid,
// then each part's reasons, pictures and numbers). Rows in, files out: the command writes them
// (grader/node/report/report.js); nothing here reads or writes a file.
import { PARTS } from '../core/part-names.js';
import { agreement } from './labels.js';
import { similarityJson } from '../similarity/report.js';
import { itemAnalysis } from './item-analysis.js';
import { reportHtml } from './report-html.js';

/** The passes of a submission, then its reviews (a count a reader can read: more is better). */
function passes(parts) {
  return parts.filter((p) => p.verdict === 'pass').length;
}

/**
 * report.json and report.html for the graded `submissions` ({ name, parts }), with the agreement
 * with `labels` (parseLabels) where given, made at `generated` (an ISO time): { rows (the
 * submissions sorted as the grid shows them, with their passes and reviews), agreed, files:
 * { 'report.json', 'report.html' } (text) }.
 */
export function reportFiles(submissions, { labels = null, similar = null, generated = new Date().toISOString() } = {}) {
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
  const report = { generated, browsers, submissions: rows,
    ...(similar ? { similarity: similarityJson(similar) } : {}), itemAnalysis: items, ...said };
  return {
    rows,
    agreed,
    files: {
      'report.json': JSON.stringify(report, null, 1),
      'report.html': reportHtml({ rows, browsers, agreed, similar, items }),
    },
  };
}
