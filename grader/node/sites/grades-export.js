// Grades to import into the course site, in its own format (its adapter's gradeFile:
// grader/node/sites/index.js), from the verdicts (a teacher's override counts, and is said); and
// grades-points.csv, ours: every part's points, the total, and which parts a teacher set. Points
// are points.js's.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { PARTS } from '../../files/parts.js';
import { importText, num, studentPoints } from './points.js';
import { siteAdapter } from './index.js';

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

/** Writes grades-points.csv and the site's import file (for `site`) into `out`; returns { files, left }. */
export function writeGradeFiles(out, rows, site, points) {
  const files = [path.join(out, 'grades-points.csv')];
  writeFileSync(files[0], pointsCsv(rows, points));
  let left = [];
  const file = siteAdapter(site).gradeFile;
  if (file) {
    const { name, make } = file;
    const made = make(rows, points);
    writeFileSync(path.join(out, name), made.text);
    files.push(path.join(out, name));
    left = made.left;
  }
  return { files, left };
}
