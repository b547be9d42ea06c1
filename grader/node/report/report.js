// The grading report of an out folder, as npm run grade writes it: the files grader/class/ makes,
// written into the folder (writeClass: every file; writeReport: report.json and report.html alone).
import { rmSync } from 'node:fs';
import path from 'node:path';
import { writeFiles } from '../../files/write-files.js';
import { reportFiles } from '../../class/report.js';
import { classOutputs } from '../../class/outputs.js';
import { picturesIn } from './feedback-page.js';

/**
 * Writes every file of the graded class into `out` (class/outputs.js's: the report, the grade
 * files, OUT/feedback/ made anew and the feedback zip), the pictures read from `out`; `options` as
 * classOutputs takes them (but pictureOf). Returns what classOutputs gives.
 */
export function writeClass(out, submissions, options) {
  const made = classOutputs(submissions, { ...options, pictureOf: picturesIn(out) });
  rmSync(path.join(out, 'feedback'), { recursive: true, force: true });
  writeFiles(out, made.files);
  return made;
}

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
