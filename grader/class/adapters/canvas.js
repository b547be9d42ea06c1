// Canvas, the course site's adapter: its download, its grade import and its feedback zip.
//   Download (Download Submissions): files "<lastfirst>[_late]_<user id>_<file id>_<original name>"
//     (canvas-lms lib/content_zipper.rb: the student's sortable name with all but letters, digits
//     and "_" taken out, lower-cased; "late" when the submission is late; then the user id, and for
//     each file handed in its own attachment id). Only the latest submission is in the download, so
//     a student's files, each with its own id, are one hand-in.
//   Grade import (Grades → Import): Student, ID, SIS User ID, SIS Login ID, Section, then the
//     assignment's column ("<name> (<assignment id>)" as Canvas exports it matches that assignment).
//   Feedback zip (Gradebook → Re-Upload Submissions): a file named as the download names one of the
//     student's files, "<lastfirst>[_late]_<user id>_<file id>_<name>", becomes a comment with the
//     file attached on that student's submission (canvas-lms app/models/assignment.rb,
//     infer_comment_context_from_filename: the first two all-digit "_"-parts are the user id and
//     the id of a file of that submission).
import { importFile } from './points.js';

const NAME = /^([^_/]+?)(_late)?_(\d+)_(\d+)_(.+)$/i;

/** The gradebook import: Student, ID, SIS User ID, SIS Login ID, Section, the assignment. */
export function canvasCsv(rows, points) {
  return importFile(rows, points, ['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', points.item],
    (id, total) => (id.userId
      ? [id.rosterName || id.name, id.userId, id.sisUserId, id.sisLoginId, id.section, total]
      : 'no Canvas user id'));
}

export const canvas = {
  id: 'canvas',
  describe: 'Canvas download: files "<lastfirst>_<user id>_<file id>_<name>" (late: "_late_")',
  /** What a top-level name says ({ name, late, userId, fileId, rest }), or null: only files, never folders. */
  parseTopName(top, isFile) {
    const m = isFile ? NAME.exec(top) : null;
    return m
      ? { name: m[1], late: Boolean(m[2]), userId: m[3], submissionId: null, fileId: m[4], time: null, rest: m[5] }
      : null;
  },
  /** Why a top-level name that parseTopName refuses is left out. */
  leftOut: 'not named as canvas names a hand-in',
  siteFile: null,
  gradeFile: { name: 'grades-canvas.csv', make: canvasCsv },
  /** The feedback file `file` named as the download names one of the student's files. */
  feedbackPath(s, file) {
    const id = s.identity || {};
    return `${id.name}${id.late ? '_late' : ''}_${id.userId}_${(id.fileIds && id.fileIds[0]) || id.submissionId}_${file}`;
  },
};
