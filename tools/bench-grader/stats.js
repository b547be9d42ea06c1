// What a grading of a labelled class costs and how far it agrees, read from its report.json (the
// grader's own record): seconds a part (median, p90, slowest), the parts past the time bound, and
// the labels' agreement. Pure: the benchmark command (tools/bench-grader.js) reads and prints.
import { NOT_GRADED } from '../../grader/core/verdict.js';
import { MS_PER_SECOND } from '../../grader/core/units.js';

/** How many of the steps that took the most time the lines name. */
const STEPS_SAID = 8;

/** The q-quantile (0…1) of `xs` by the nearest rank; null for none. */
export function quantile(xs, q) {
  if (!xs.length) return null;
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1))];
}

/**
 * { parts, median, p90, max, slowest: [{ name, part, seconds }], notGraded, agreement, steps, calls }
 * from a report (report.json). A part with no `seconds` (missing, linked) is not counted. `steps`:
 * the seconds of each step of the parts' gathering and judging, added up over the parts (their
 * `steps`), most first: [{ step, seconds }]. `calls`: the same by page call (their `timing`: open,
 * tick, snap, surface, ...), with how many: [{ call, calls, seconds }], most seconds first.
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
  const bySteps = new Map();
  for (const p of parts) for (const [k, ms] of Object.entries(p.steps || {})) bySteps.set(k, (bySteps.get(k) || 0) + ms / MS_PER_SECOND);
  const steps = [...bySteps].map(([step, s]) => ({ step, seconds: s })).sort((a, b) => b.seconds - a.seconds);
  const byCall = new Map();
  for (const p of parts) {
    for (const [call, t] of Object.entries(p.timing || {})) {
      const c = byCall.get(call) || byCall.set(call, { call, calls: 0, seconds: 0 }).get(call);
      c.calls += t.calls;
      c.seconds += t.ms / MS_PER_SECOND;
    }
  }
  const calls = [...byCall.values()].sort((a, b) => b.seconds - a.seconds);
  return { parts: parts.length, median: quantile(seconds, 0.5), p90: quantile(seconds, 0.9), max: quantile(seconds, 1), slowest, notGraded, agreement, steps, calls };
}

/**
 * Of runs of the same grading ([{ wall, st }], in the order run), the one of the median wall time
 * (the lower middle of an even count), with every run's wall time: { wall, st, walls }.
 */
export function medianRun(runs) {
  const sorted = [...runs].sort((a, b) => a.wall - b.wall);
  const mid = sorted[Math.ceil(sorted.length / 2) - 1];
  return { wall: mid.wall, st: mid.st, walls: runs.map((r) => r.wall) };
}

/** The stats as the lines a person reads. */
export function statsLines(st, wallSeconds) {
  const f = (x) => (x === null ? '–' : x.toFixed(1));
  const lines = [`${st.parts} parts in ${f(wallSeconds)} s: a part median ${f(st.median)} s, p90 ${f(st.p90)} s, slowest ${f(st.max)} s (${st.slowest.map((s) => `${s.name} ${s.part} ${f(s.seconds)} s`).join(', ')})`];
  lines.push(st.notGraded.length ? `past the time bound: ${st.notGraded.join(', ')}` : 'every part judged within the time bound');
  if (st.steps && st.steps.length) {
    const all = st.steps.reduce((t, s) => t + s.seconds, 0);
    lines.push(`where the parts' ${f(all)} s went: ${st.steps.slice(0, STEPS_SAID).map((s) => `${s.step} ${f(s.seconds)} s`).join(', ')}`);
  }
  if (st.calls && st.calls.length) {
    lines.push(`by page call: ${st.calls.slice(0, STEPS_SAID).map((c) => `${c.call} ${f(c.seconds)} s in ${c.calls}`).join(', ')}`);
  }
  const a = st.agreement;
  if (a) lines.push(`labels: ${a.exact} of ${a.of} exact, correct parts passed ${a.correctPassed} of ${a.correct}, partial parts passed ${a.partialPassed}, broken parts passed ${a.brokenPassed}`);
  return lines;
}
