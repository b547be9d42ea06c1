// The teacher's overrides.tsv read from its file (parsed and applied by grader/class/overrides.js,
// which takes text, not files).
import { readFileSync } from 'node:fs';
import { parseOverrides } from '../../class/overrides.js';

export { OVERRIDES_FILE, parseOverrides, applyOverrides } from '../../class/overrides.js';

/** The overrides in `file` (parseOverrides: it throws naming the line it cannot read). */
export function readOverrides(file) {
  return parseOverrides(readFileSync(file, 'utf8'), file);
}
