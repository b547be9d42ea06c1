// A part's row of the class (what OUT/parts/<student>/<part>.json and report.json say of it) where
// no page was opened: its hand-in could not be unpacked, or no page was found for the part. The
// command (node/sites/intake/batch.js, node/run/run-part.js) and the class page (grade/) write the same.
import { withFindings } from '../core/part-result.js';
import { missingPage } from '../core/audits/page.js';

/** The status of a part whose hand-in could not be unpacked. */
export const NOT_UNPACKED = 'not unpacked';

/** Part `part` of student `name`, whose hand-in could not be unpacked (`error`: the intake's message, its reason). */
export function notUnpackedRow(name, part, error) {
  const notUnpacked = { id: 'not-unpacked', level: 'fail', reason: error };
  const failed = { name, part, status: NOT_UNPACKED, verdict: 'fail', pass: false };
  const rest = { api: null, actions: [], mismatch: null, rmse: null, errors: [], blocked: [] };
  return { ...withFindings(failed, [notUnpacked]), ...rest };
}

/** A part's row before its page is graded (its fields in the command's order); `fields` are set over it. */
export function partRow(name, part, file, fields = {}) {
  return {
    name, part, file, status: 'timeout', verdict: 'fail', api: null, reasons: [], findings: [],
    actions: [], controls: {}, numbers: {}, mismatch: null, rmse: null, pass: false, comparison: null,
    notes: [], errors: [], blocked: [], images: null, ...fields,
  };
}

/** Part `part` of student `name` with no page found for it (`notes`: how the parts were looked for). */
export function missingRow(name, part, notes = []) {
  return withFindings(partRow(name, part, null, { status: 'missing', notes }), [missingPage(part)]);
}
