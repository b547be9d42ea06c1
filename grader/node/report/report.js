// The grading report of an out folder, as npm run grade writes it: the files grader/class/report.js
// makes (report.json, report.html), written into the folder.
import { writeFiles } from '../../files/write-files.js';
import { reportFiles } from '../../class/report.js';

/**
 * Writes report.json and report.html into `out` for the graded `submissions` ({ name, parts }),
 * with the agreement with `labels` (readLabels) where given; returns the submissions sorted as the
 * grid shows them (with their passes and reviews) and the agreement.
 */
export function writeReport(out, submissions, labels = null, similar = null) {
  const { rows, agreed, files } = reportFiles(submissions, { labels, similar });
  writeFiles(out, files);
  return { rows, agreed };
}
