// The teacher's last word: overrides.tsv (student, part, verdict, note to the student), applied
// every time the report is written (grading, --audit-only, --report-only) and never written into
// the parts' results, so the grader's own verdict stays, is shown beside the teacher's, and comes
// back when a line is deleted. The grade files and the feedback pages use the teacher's verdict
// and say a teacher set it. From text (the command reads the file: grader/node/report/overrides.js).
import { VERDICT_OF_LABEL } from './labels.js';
import { safeName } from '../files/safe-name.js';
import { csvText, readRows } from '../files/csv.js';

export const OVERRIDES_FILE = 'overrides.tsv';

/**
 * Parses overrides.tsv: a header naming the columns student, part, verdict and (optionally) note,
 * tab-separated; "#" starts a comment line; a cell may be quoted (a note with a tab, a quote or a line
 * break in it, as a spreadsheet writes it). A verdict is pass, review or fail (or a label: correct,
 * partial, broken). Returns [{ student, part, verdict, note, line }]; throws an Error naming the line.
 */
export function parseOverrides(text, file = OVERRIDES_FILE) {
  const rows = readRows(text, { delimiter: '\t', comments: true, file });
  if (!rows.length) return [];
  const head = rows[0].cells.map((h) => h.trim().toLowerCase());
  for (const need of ['student', 'part', 'verdict']) {
    if (!head.includes(need)) throw new Error(`${file}: the first line must name the columns student, part, verdict and note (tab-separated); it has ${head.join(', ')}`);
  }
  return rows.slice(1).map(({ cells, line: k }) => {
    const get = (name) => (head.includes(name) ? (cells[head.indexOf(name)] || '').trim() : '');
    const verdict = VERDICT_OF_LABEL[get('verdict').toLowerCase()];
    const part = get('part').toUpperCase();
    if (!verdict) throw new Error(`${file}, line ${k}: verdict "${get('verdict')}" is none of pass, review, fail`);
    if (!/^WP04P[1-5]$/.test(part)) throw new Error(`${file}, line ${k}: part "${get('part')}" is none of WP04P1 … WP04P5`);
    if (!get('student')) throw new Error(`${file}, line ${k}: no student`);
    return { student: get('student'), part, verdict, note: get('note'), line: k };
  });
}

/** overrides.tsv's text for `overrides` ([{ student, part, verdict, note }]), as parseOverrides reads it. */
export function overridesText(overrides) {
  const rows = overrides.map((o) => [o.student, o.part, o.verdict, o.note || '']);
  return csvText([['student', 'part', 'verdict', 'note'], ...rows], { delimiter: '\t' });
}

/** Whether overrides.tsv's `student` names submission `s`: its name as the report shows it, its folder's name, the site's name or user id. */
function names(s, student) {
  const id = s.identity || {};
  return [s.name, safeName(s.name), id.name, id.userId, id.orgDefinedId, id.username].some(
    (n) => n && String(n).toLowerCase() === student.toLowerCase(),
  );
}

/**
 * Sets each overridden part's verdict to the teacher's (in place): the part keeps the grader's as
 * `grader` ({ verdict }) and gets `teacher` ({ verdict, note }). Returns { applied, unknown: [lines
 * naming no student graded] }.
 */
export function applyOverrides(submissions, overrides) {
  let applied = 0;
  const unknown = [];
  for (const o of overrides) {
    const s = submissions.find((x) => names(x, o.student));
    const r = s && s.parts.find((p) => p.part === o.part);
    if (!r) { unknown.push(`line ${o.line}: ${o.student} ${o.part}`); continue; }
    r.grader = { verdict: r.grader ? r.grader.verdict : r.verdict };
    r.teacher = { verdict: o.verdict, note: o.note };
    r.verdict = o.verdict;
    r.pass = o.verdict === 'pass';
    applied++;
  }
  return { applied, unknown };
}
