// A teacher's labels read from their file (the TSV parsed, and compared with the verdicts, by
// grader/class/labels.js, which takes text, not files).
import { readFileSync } from 'node:fs';
import { parseLabels } from '../../class/labels.js';

export { VERDICT_OF_LABEL, LABELS, parseLabels, agreement, agreementText, agreementHtml } from '../../class/labels.js';

/** The labels in `file` (parseLabels: it throws naming the line it cannot read). */
export function readLabels(file) {
  return parseLabels(readFileSync(file, 'utf8'), file);
}
