// The feedback pages on disk (OUT/feedback/<student>.html) and the feedback zip laid out as the
// course site takes it back: the download's own names, so each file finds its student.
//   Moodle (Assignment → Upload multiple feedback files in a zip): a file in the download's
//     folder "<Full Name>_<participant id>_assignsubmission_file/" is a new feedback file for
//     that participant (mod/assign/feedback/file/importziplib.php reads the id from the folder).
//   Brightspace: the download's folder "<submission id>-<user id> - <name> - <date>/".
//   Canvas (Gradebook → Re-Upload Submissions): a file named as the download names one of the
//     student's files, "<lastfirst>[_late]_<user id>_<file id>_<name>", becomes a comment with the
//     file attached on that student's submission (canvas-lms app/models/assignment.rb,
//     infer_comment_context_from_filename: the first two all-digit "_"-parts are the user id and
//     the id of a file of that submission).
//   A folder a student: "<student>/feedback.html".
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { zipSync, strToU8 } from 'fflate';
import { feedbackHtml } from './page.js';
import { safeName } from '../../files/layout.js';

export const FEEDBACK_FILE = 'feedback.html';

/** Where a student's feedback goes in the zip for the course site `site`. */
export function feedbackZipPath(s, site) {
  const id = s.identity || {};
  const source = (id.source && id.source[0]) || '';
  if (site === 'brightspace' || site === 'moodle') {
    const folder = source.replace(/\/$/, '');
    // (Moodle's loose-files download: the same prefix, its folder form)
    const moodle = site === 'moodle' ? /^(.+_\d+_assignsubmission_file)/.exec(folder) : null;
    return `${moodle ? moodle[1] : folder}/${FEEDBACK_FILE}`;
  }
  if (site === 'canvas') return `${id.name}${id.late ? '_late' : ''}_${id.userId}_${(id.fileIds && id.fileIds[0]) || id.submissionId}_${FEEDBACK_FILE}`;
  return `${safeName(s.name)}/${FEEDBACK_FILE}`;
}

/**
 * Writes OUT/feedback/<student>.html for each of `rows` and OUT/feedback-<site>.zip; returns
 * { pages, zip }.
 */
export function writeFeedback(out, rows, rubric, site = 'folders') {
  const dir = path.join(out, 'feedback');
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const entries = {};
  const pages = [];
  for (const s of rows) {
    const html = feedbackHtml(s, out, rubric);
    const file = path.join(dir, `${safeName(s.name)}.html`);
    writeFileSync(file, html);
    pages.push(file);
    entries[feedbackZipPath(s, site)] = [strToU8(html), { level: 6 }];
  }
  const zip = path.join(out, `feedback-${site}.zip`);
  writeFileSync(zip, zipSync(entries));
  return { pages, zip };
}
