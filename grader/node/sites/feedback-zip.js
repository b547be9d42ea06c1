// The feedback pages and the feedback zip of grader/class/feedback-zip.js, written into the out
// folder (OUT/feedback/ made anew, OUT/feedback-<site>.zip).
import { rmSync } from 'node:fs';
import path from 'node:path';
import { writeFiles } from '../../files/write-files.js';
import { feedbackFiles } from '../../class/feedback-zip.js';

export { FEEDBACK_FILE, feedbackZipPath } from '../../class/feedback-zip.js';

/**
 * Writes OUT/feedback/<student>.html for each of `rows` (its page: `pageOf(row)`, the report's
 * feedback page) and OUT/feedback-<site>.zip; returns { pages, zip }.
 */
export function writeFeedback(out, rows, pageOf, site = 'folders') {
  rmSync(path.join(out, 'feedback'), { recursive: true, force: true });
  const { pages, zip } = feedbackFiles(rows, pageOf, site);
  return { pages: writeFiles(out, pages), zip: writeFiles(out, zip)[0] };
}
