// Every file a graded class gives back, from one call, as the command writes them into its out
// folder and a page of the site hands them to the teacher: report.json and report.html, grades.csv
// (a class taken in from a download), grades-points.csv and the course site's import file, each
// student's feedback page and the feedback zip. Rows in, files out (no Node).
import { PARTS } from '../core/part-names.js';
import { reportFiles } from './report.js';
import { gradesCsv } from './grades-csv.js';
import { gradeFiles } from './grade-files.js';
import { feedbackFiles } from './feedback-zip.js';
import { feedbackPage } from './feedback-page.js';

/**
 * The class's files from its graded `submissions` (with identity and overrides, as the report is
 * given them): { rows, agreed, left (what the site's import file leaves out), gradeFiles,
 * feedbackPages, feedbackZip (their names), files: { relative path: text or bytes } }. `labels` (parseLabels) and `similar` go into the report; `aClass`: it
 * came as a download (grades.csv); `site`: the course site's adapter; `rubric`: points and the
 * feedback's words; `pictureOf(href)`: a picture as a data: URL, or null; `generated`: an ISO time.
 */
export function classOutputs(submissions, options) {
  const { labels = null, similar = null, aClass = false, site = 'folders', rubric, pictureOf, generated } = options;
  const { rows, agreed, files } = reportFiles(submissions, { labels, similar, generated });
  const grades = gradeFiles(rows, site, rubric.points);
  const feedback = feedbackFiles(rows, (s) => feedbackPage(s, rubric, pictureOf), site);
  return {
    rows,
    agreed,
    left: grades.left,
    gradeFiles: Object.keys(grades.files),
    feedbackPages: Object.keys(feedback.pages),
    feedbackZip: Object.keys(feedback.zip)[0],
    files: {
      ...files, ...(aClass ? { 'grades.csv': gradesCsv(rows, PARTS) } : {}), ...grades.files, ...feedback.pages, ...feedback.zip,
    },
  };
}
