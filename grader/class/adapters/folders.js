// Plain folders, the adapter for a class that comes from no course site: a folder a student, named
// as the teacher likes; no import file beside our grades-points.csv; the feedback zip a folder a
// student, "<student>/feedback.html".
import { safeName } from '../../files/safe-name.js';

export const folders = {
  id: 'folders',
  describe: 'a folder a student',
  /** A folder at the top is a student's, named as the teacher likes; a file there is nobody's. */
  parseTopName: (top, isFile) =>
    (isFile ? null : { name: top, userId: null, submissionId: null, time: null, late: null, rest: null }),
  leftOut: 'a file at the top of the download, not a student\'s folder',
  /** Taken where no site's names fit most of a download. */
  fallback: true,
  siteFile: null,
  gradeFile: null,
  feedbackPath: (s, file) => `${safeName(s.name)}/${file}`,
};
