// Grades to import into the course site, in its own format, from the verdicts (a teacher's
// override counts, and is said): points a part are the rubric's points for its verdict times the
// part's weight (the "points" of grader/core/rubric.json); a part not graded here gives no total, never a 0.
//   Brightspace (Grades → Import): OrgDefinedId or Username, "<item> Points Grade", then
//     "End-of-Line Indicator" "#"; each id written "#<id>" so that a spreadsheet keeps it text
//     (leading zeros too).
//   Canvas (Grades → Import): Student, ID, SIS User ID, SIS Login ID, Section, then the
//     assignment's column ("<name> (<assignment id>)" as Canvas exports it matches that assignment).
//   Moodle (Grades → Import → CSV file): ID number and Email address to map the user on, the item,
//     and a Feedback column to map to the item's feedback.
// And grades-points.csv, ours: every part's points, the total, and which parts a teacher set.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { PARTS } from '../files/parts.js';
import { NOT_GRADED } from '../core/verdict.js';
import { csvText } from '../files/csv.js';

// (each file's lines end in CRLF, as the sites' own exports do)
const importText = (rows) => csvText(rows, { eol: '\r\n' });
const num = (x) => String(Number(x.toFixed(2)));

/** A part's points under `points` (the rubric's), or null when it was not graded here (or not in this run). */
export function partPoints(r, points) {
  if (r.verdict === NOT_GRADED || r.status === NOT_GRADED || !(r.verdict in points)) return null;
  return points[r.verdict] * points.weights[r.part];
}

/** A student's { total (null when a part has no points), max, byPart, teacherSet: [parts] }. */
export function studentPoints(s, points) {
  const byPart = Object.fromEntries(PARTS.map((p) => [p, partPoints(s.parts.find((x) => x.part === p), points)]));
  const values = Object.values(byPart);
  return { byPart, total: values.includes(null) ? null : values.reduce((a, b) => a + b, 0), max: PARTS.reduce((a, p) => a + points.pass * points.weights[p], 0),
    teacherSet: s.parts.filter((p) => p.teacher).map((p) => p.part) };
}

/** A line of words on the verdicts, for a grade's feedback: "WP04P1 pass; WP04P3 review (set by the teacher; the grader said fail)". */
export function verdictWords(s) {
  return s.parts.map((p) => `${p.part} ${p.verdict}${p.teacher ? ` (set by the teacher; the grader said ${p.grader.verdict})` : ''}`).join('; ');
}

/** Brightspace's import: rows keyed on OrgDefinedId (or Username when every student has one and not every OrgDefinedId is known). */
export function brightspaceCsv(rows, points) {
  const id = (s) => s.identity || {};
  const key = rows.every((s) => id(s).orgDefinedId) || !rows.every((s) => id(s).username) ? 'orgDefinedId' : 'username';
  const left = [];
  const lines = [[key === 'orgDefinedId' ? 'OrgDefinedId' : 'Username', `${points.item} Points Grade`, 'End-of-Line Indicator']];
  for (const s of rows) {
    const { total } = studentPoints(s, points);
    if (!id(s)[key] || total === null) { left.push(`${s.name}: ${total === null ? 'a part not graded here' : `no ${key === 'orgDefinedId' ? 'OrgDefinedId' : 'Username'} (give --roster)`}`); continue; }
    lines.push([`#${id(s)[key]}`, num(total), '#']);
  }
  return { text: importText(lines), left };
}

/** Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID, Section, the assignment. */
export function canvasCsv(rows, points) {
  const left = [];
  const lines = [['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', points.item]];
  for (const s of rows) {
    const id = s.identity || {};
    const { total } = studentPoints(s, points);
    if (!id.userId || total === null) { left.push(`${s.name}: ${total === null ? 'a part not graded here' : 'no Canvas user id'}`); continue; }
    lines.push([id.rosterName || id.name, id.userId, id.sisUserId, id.sisLoginId, id.section, num(total)]);
  }
  return { text: importText(lines), left };
}

/** Moodle's CSV grade import: map the user on ID number or Email address; Feedback to the item's feedback. */
export function moodleCsv(rows, points) {
  const left = [];
  const lines = [['Full name', 'ID number', 'Email address', points.item, 'Feedback']];
  for (const s of rows) {
    const id = s.identity || {};
    const { total } = studentPoints(s, points);
    if (!(id.idNumber || id.email) || total === null) { left.push(`${s.name}: ${total === null ? 'a part not graded here' : 'no ID number or email (give --roster)'}`); continue; }
    lines.push([id.rosterName || id.name, id.idNumber, id.email, num(total), verdictWords(s)]);
  }
  return { text: importText(lines), left };
}

/** Ours: every part's points, the total, the identity, and which parts a teacher set. */
export function pointsCsv(rows, points) {
  const lines = [['name', 'site', 'user id', 'submission id', 'time', 'late', ...PARTS, 'total', 'max', 'set by the teacher']];
  for (const s of rows) {
    const id = s.identity || {};
    const p = studentPoints(s, points);
    lines.push([s.name, id.site, id.userId, id.submissionId, id.time, id.late === null || id.late === undefined ? '' : id.late ? 'late' : 'on time',
      ...PARTS.map((k) => (p.byPart[k] === null ? '' : num(p.byPart[k]))), p.total === null ? '' : num(p.total), num(p.max), p.teacherSet.join(' ')]);
  }
  return importText(lines);
}

const SITE_FILES = { brightspace: ['grades-brightspace.csv', brightspaceCsv], canvas: ['grades-canvas.csv', canvasCsv], moodle: ['grades-moodle.csv', moodleCsv] };

/** Writes grades-points.csv and the site's import file (for `site`) into `out`; returns { files, left }. */
export function writeGradeFiles(out, rows, site, points) {
  const files = [path.join(out, 'grades-points.csv')];
  writeFileSync(files[0], pointsCsv(rows, points));
  let left = [];
  if (SITE_FILES[site]) {
    const [name, make] = SITE_FILES[site];
    const made = make(rows, points);
    writeFileSync(path.join(out, name), made.text);
    files.push(path.join(out, name));
    left = made.left;
  }
  return { files, left };
}
