// What a grading of a labelled class costs and how far it agrees, read from its report.json (the
// grader's own record): seconds a part (median, p90, slowest), the parts past the time bound, and
// the labels' agreement. Pure: the benchmark command (tools/bench-grader.js) reads and prints.
import { NOT_GRADED } from '../../grader/core/verdict.js';

/** The q-quantile (0…1) of `xs` by the nearest rank; null for none. */
export function quantile(xs, q) {
  if (!xs.length) return null;
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1))];
}

/**
 * { parts, median, p90, max, slowest: [{ name, part, seconds }], notGraded, agreement } from a
 * report (report.json). A part with no `seconds` (missing, linked) is not counted.
 */
export function gradingStats(report) {
  const parts = report.submissions.flatMap((s) => s.parts).filter((p) => Number.isFinite(p.seconds));
  const seconds = parts.map((p) => p.seconds);
  const slowest = [...parts].sort((a, b) => b.seconds - a.seconds).slice(0, 3).map((p) => ({ name: p.name, part: p.part, seconds: p.seconds }));
  const notGraded = report.submissions.flatMap((s) => s.parts).filter((p) => p.verdict === NOT_GRADED || p.status === 'too slow' || p.status === 'timeout').map((p) => `${p.name} ${p.part}`);
  const rows = report.labels ? report.labels.rows : [];
  const labelled = rows.filter((r) => r.want);
  const agreement = labelled.length ? {
    exact: labelled.filter((r) => r.agree).length, of: labelled.length,
    correctPassed: rows.filter((r) => r.label === 'correct' && r.verdict === 'pass').length, correct: rows.filter((r) => r.label === 'correct').length,
    partialPassed: rows.filter((r) => r.label === 'partial' && r.verdict === 'pass').length,
    brokenPassed: rows.filter((r) => r.label === 'broken' && r.verdict === 'pass').length,
  } : null;
  return { parts: parts.length, median: quantile(seconds, 0.5), p90: quantile(seconds, 0.9), max: quantile(seconds, 1), slowest, notGraded, agreement };
}

/** The stats as the lines a person reads. */
export function statsLines(st, wallSeconds) {
  const f = (x) => (x === null ? '–' : x.toFixed(1));
  const lines = [`${st.parts} parts in ${f(wallSeconds)} s: a part median ${f(st.median)} s, p90 ${f(st.p90)} s, slowest ${f(st.max)} s (${st.slowest.map((s) => `${s.name} ${s.part} ${f(s.seconds)} s`).join(', ')})`];
  lines.push(st.notGraded.length ? `past the time bound: ${st.notGraded.join(', ')}` : 'every part judged within the time bound');
  const a = st.agreement;
  if (a) lines.push(`labels: ${a.exact} of ${a.of} exact, correct parts passed ${a.correctPassed} of ${a.correct}, partial parts passed ${a.partialPassed}, broken parts passed ${a.brokenPassed}`);
  return lines;
}
