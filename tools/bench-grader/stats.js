// What a grading of a labelled class costs and how far it agrees, read from its report.json (the
// grader's own record): seconds a part (median, p90, slowest), the parts past the time bound, and
// the labels' agreement; on how many lit parts the page's own surface was read, from the parts'
// artifacts (facts.surface), and on how many slider trials the terms were read there (the parts'
// numbers). Pure: the benchmark command (tools/bench-grader.js) reads and prints.
import { NOT_GRADED } from '../../grader/core/verdict.js';
import { MS_PER_SECOND } from '../../grader/core/units.js';
import { STEPS } from '../../common/steps.js';

/** How many of the steps that took the most time the lines name. */
const STEPS_SAID = 8;

/** The q-quantile (0…1) of `xs` by the nearest rank; null for none. */
export function quantile(xs, q) {
  if (!xs.length) return null;
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1))];
}

/** How many of the reasons the surface was not read the line names. */
const WHYS_SAID = 6;

/** The first WHYS_SAID reasons (in words, most first) and how many more, on one line. */
const whysSaid = (whys) =>
  [...whys.slice(0, WHYS_SAID), ...(whys.length > WHYS_SAID ? [`${whys.length - WHYS_SAID} reasons more`] : [])].join('; ');

/**
 * On how many lit parts (the steps that light the sphere: P3-P5, common/steps.js) that were graded the
 * grader read the page's own surface: { read, of, why: [{ why, parts }] (most parts first) }.
 * `surfaceOf(part)` is the part's facts.surface (its artifact): { why } where it could not be read,
 * undefined where none was gathered (the grading stopped before it, or the page could not be opened).
 */
export function surfaceStats(parts, surfaceOf) {
  const lit = parts.filter((p) => STEPS[p.part] && STEPS[p.part].shading !== 'normals');
  const whys = new Map();
  let read = 0;
  for (const p of lit) {
    const s = surfaceOf(p);
    if (s && !s.why) { read++; continue; }
    const why = s ? s.why : `none gathered (${p.verdict})`;
    whys.set(why, (whys.get(why) || 0) + 1);
  }
  const why = [...whys].map(([w, n]) => ({ why: w, parts: n })).sort((a, b) => b.parts - a.parts);
  return { read, of: lit.length, why };
}

/**
 * On how many of the slider trials (P4) the terms were read on the page's own surface, from the
 * parts' numbers (the term-controls audit's `sliderTrials`): { read, of, why: [{ why, trials }] (most
 * trials first) }, or null where no part tried a slider.
 */
export function trialStats(parts) {
  const counted = parts.map((p) => p.numbers && p.numbers.sliderTrials).filter(Boolean);
  if (!counted.length) return null;
  const whys = new Map();
  for (const t of counted) for (const [w, n] of Object.entries(t.why || {})) whys.set(w, (whys.get(w) || 0) + n);
  const why = [...whys].map(([w, n]) => ({ why: w, trials: n })).sort((a, b) => b.trials - a.trials);
  return { read: counted.reduce((a, t) => a + t.onSurface, 0), of: counted.reduce((a, t) => a + t.read, 0), why };
}

/**
 * { parts, median, p90, max, slowest: [{ name, part, seconds }], notGraded, agreement, steps, calls,
 * surface } from a report (report.json) and its parts' facts.surface (`surfaceOf(part)`, optional:
 * without it no `surface`, surfaceStats). A part with no `seconds` (missing, linked) is not counted. `steps`:
 * the seconds of each step of the parts' gathering and judging, added up over the parts (their
 * `steps`), most first: [{ step, seconds }]. `calls`: the same by page call (their `timing`: open,
 * tick, snap, surface, ...), with how many: [{ call, calls, seconds }], most seconds first.
 */
export function gradingStats(report, surfaceOf = null) {
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
  const surface = surfaceOf ? surfaceStats(parts, surfaceOf) : null;
  const trials = trialStats(parts);
  return { parts: parts.length, median: quantile(seconds, 0.5), p90: quantile(seconds, 0.9), max: quantile(seconds, 1), slowest, notGraded, agreement, steps, calls, surface, trials };
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
  const sf = st.surface;
  if (sf) {
    const rest = sf.of - sf.read, whys = whysSaid(sf.why.map((w) => `${w.why} (${w.parts})`));
    lines.push(`the page's own surface read on ${sf.read} of ${sf.of} lit parts (P3-P5)${rest ? `; not on ${rest}: ${whys}` : ''}`);
  }
  const tr = st.trials;
  if (tr) {
    const rest = tr.of - tr.read, whys = whysSaid(tr.why.map((w) => `${w.why} (${w.trials})`));
    lines.push(`the slider trials (P4) read on the page's own surface: ${tr.read} of ${tr.of}${rest ? `; on the pictures ${rest}: ${whys}` : ''}`);
  }
  const a = st.agreement;
  if (a) lines.push(`labels: ${a.exact} of ${a.of} exact, correct parts passed ${a.correctPassed} of ${a.correct}, partial parts passed ${a.partialPassed}, broken parts passed ${a.brokenPassed}`);
  return lines;
}
