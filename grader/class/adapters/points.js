// A student's points from the verdicts (a teacher's override counts), as every course site's import
// file and our own grades-points.csv write them: points a part are the rubric's points for its
// verdict times the part's weight (the "points" of grader/core/rubric.json); a part not graded here
// gives no total, never a 0.
import { PARTS } from '../../core/part-names.js';
import { NOT_GRADED } from '../../core/verdict.js';
import { csvText } from '../../files/csv.js';

/** An import file's text: each line ends in CRLF, as the sites' own exports do. */
export const importText = (rows) => csvText(rows, { eol: '\r\n' });

/** Points as written: at most two decimals, no trailing zeros. */
export const num = (x) => String(Number(x.toFixed(2)));

/** A part's points under `points` (the rubric's), or null when it was not graded here (or not in this run). */
export function partPoints(r, points) {
  if (r.verdict === NOT_GRADED || r.status === NOT_GRADED || !(r.verdict in points)) return null;
  return points[r.verdict] * points.weights[r.part];
}

/** A student's { total (null when a part has no points), max, byPart, teacherSet: [parts] }. */
export function studentPoints(s, points) {
  const byPart = Object.fromEntries(PARTS.map((p) => [p, partPoints(s.parts.find((x) => x.part === p), points)]));
  const values = Object.values(byPart);
  return {
    byPart,
    total: values.includes(null) ? null : values.reduce((a, b) => a + b, 0),
    max: PARTS.reduce((a, p) => a + points.pass * points.weights[p], 0),
    teacherSet: s.parts.filter((p) => p.teacher).map((p) => p.part),
  };
}

/** A line of words on the verdicts, for a grade's feedback: "WP04P1 pass; WP04P3 review (set by the teacher; the grader said fail)". */
export function verdictWords(s) {
  return s.parts.map((p) => `${p.part} ${p.verdict}${p.teacher ? ` (set by the teacher; the grader said ${p.grader.verdict})` : ''}`).join('; ');
}

/**
 * An import file: `header`, then a line a student: lineOf(identity, total as written, student) →
 * the line, or why the student is left out (a student with a part not graded here always is):
 * { text, left: ["<student>: <why>"] }.
 */
export function importFile(rows, points, header, lineOf) {
  const left = [], lines = [header];
  for (const s of rows) {
    const { total } = studentPoints(s, points);
    const line = total === null ? 'a part not graded here' : lineOf(s.identity || {}, num(total), s);
    if (typeof line === 'string') left.push(`${s.name}: ${line}`);
    else lines.push(line);
  }
  return { text: importText(lines), left };
}
