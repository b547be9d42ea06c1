// Moodle, the course site's adapter: its download, its grade import and its feedback zip.
//   Download (Download all submissions): folders "<Full Name>_<participant id>_assignsubmission_file"
//     (older versions end it with "_"; without "download as folders", files
//     "<Full Name>_<participant id>_assignsubmission_file_<original name>").
//   Grade import (Grades → Import → CSV file): ID number and Email address to map the user on, the
//     item, and a Feedback column to map to the item's feedback.
//   Feedback zip (Assignment → Upload multiple feedback files in a zip): a file in the download's
//     folder "<Full Name>_<participant id>_assignsubmission_file/" is a new feedback file for
//     that participant (mod/assign/feedback/file/importziplib.php reads the id from the folder).
import { importFile, verdictWords } from './points.js';
import { sourceFolder } from './source-folder.js';

const NAME = /^(.+)_(\d+)_assignsubmission_([a-z]+)(?:_(.*))?$/;

/** The CSV grade import: map the user on ID number or Email address; Feedback to the item's feedback. */
export function moodleCsv(rows, points) {
  return importFile(rows, points, ['Full name', 'ID number', 'Email address', points.item, 'Feedback'],
    (id, total, s) => (id.idNumber || id.email
      ? [id.rosterName || id.name, id.idNumber, id.email, total, verdictWords(s)]
      : 'no ID number or email (give --roster)'));
}

export const moodle = {
  id: 'moodle',
  describe: 'Moodle download: folders "<Full Name>_<participant id>_assignsubmission_file"',
  /** What a top-level name says ({ name, userId, plugin, rest }), or null. */
  parseTopName(top, isFile) {
    const m = NAME.exec(top);
    if (!m || (isFile && !m[4])) return null;
    return {
      name: m[1],
      userId: m[2],
      submissionId: null,
      time: null,
      late: null,
      plugin: m[3],
      rest: isFile ? m[4] : null,
    };
  },
  /** Why a top-level name that parseTopName refuses is left out. */
  leftOut: 'not named as moodle names a hand-in',
  siteFile: null,
  gradeFile: { name: 'grades-moodle.csv', make: moodleCsv },
  /** The feedback file `file` in the folder the download gave the participant (a loose-files download: the same prefix, its folder form). */
  feedbackPath(s, file) {
    const folder = sourceFolder(s);
    const prefix = /^(.+_\d+_assignsubmission_file)/.exec(folder);
    return `${prefix ? prefix[1] : folder}/${file}`;
  },
};
