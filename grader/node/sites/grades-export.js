// The grade files of grader/class/grade-files.js (grades-points.csv and the course site's import
// file), written into the out folder.
import { writeFiles } from '../../files/write-files.js';
import { gradeFiles } from '../../class/grade-files.js';

export { pointsCsv } from '../../class/grade-files.js';

/** Writes grades-points.csv and the site's import file (for `site`) into `out`; returns { files, left }. */
export function writeGradeFiles(out, rows, site, points) {
  const { files, left } = gradeFiles(rows, site, points);
  return { files: writeFiles(out, files), left };
}
