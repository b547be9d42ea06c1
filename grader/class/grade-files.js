// Grades to import into the course site, in its own format (its adapter's gradeFile:
// grader/class/adapters/index.js), from the verdicts (a teacher's override counts, and is said); and
// grades-points.csv, ours: every part's points, the total, and which parts a teacher set. Points
// are adapters/points.js's. Rows in, files out: the command writes them (grader/node/report/report.js's writeClass).
import { PARTS } from '../core/part-names.js';
import { importText, num, studentPoints } from './adapters/points.js';
import { siteAdapter } from './adapters/index.js';

/** Ours: every part's points, the total, the identity, and which parts a teacher set. */
export function pointsCsv(rows, points) {
  const lines = [['name', 'site', 'user id', 'submission id', 'time', 'late', ...PARTS, 'total', 'max', 'set by the teacher']];
  for (const s of rows) {
    const id = s.identity || {};
    const p = studentPoints(s, points);
    const late = id.late === null || id.late === undefined ? '' : id.late ? 'late' : 'on time';
    lines.push([s.name, id.site, id.userId, id.submissionId, id.time, late,
      ...PARTS.map((k) => (p.byPart[k] === null ? '' : num(p.byPart[k]))),
      p.total === null ? '' : num(p.total), num(p.max), p.teacherSet.join(' ')]);
  }
  return importText(lines);
}

/**
 * grades-points.csv and the site's import file (for `site`, where it has one): { files: { name:
 * text }, in that order, left (the rows the site's file leaves out, with why) }.
 */
export function gradeFiles(rows, site, points) {
  const files = { 'grades-points.csv': pointsCsv(rows, points) };
  let left = [];
  const file = siteAdapter(site).gradeFile;
  if (file) {
    const made = file.make(rows, points);
    files[file.name] = made.text;
    left = made.left;
  }
  return { files, left };
}
