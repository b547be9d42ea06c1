// The teacher's loop around the report, in every mode that writes it (grading, --audit-only,
// --report-only): before, each student gets the identity the intake read (OUT/intake.json), the
// roster's ids (--roster, kept as OUT/roster.csv) and the teacher's overrides (--overrides, or
// OUT/overrides.tsv); after, what the grade files and the feedback written (report/report.js's
// writeClass) say.
import { copyFileSync, existsSync, readFileSync, rmSync } from 'node:fs';
import path from 'node:path';
import { readIntake } from '../sites/intake/intake.js';
import { OVERRIDES_FILE, applyOverrides, readOverrides } from '../report/overrides.js';
import { matchRoster, parseRoster } from '../../class/roster.js';

/** An option's file, or OUT's file of that name when it is there, or null. */
const fileOr = (given, out, names) => given || names.map((n) => path.join(out, n)).find((f) => existsSync(f)) || null;

/**
 * Adds identity, roster ids and overrides to `submissions` (in place). Throws an Error (bad usage)
 * for an overrides or roster file that cannot be read. Returns { site, lines: [what to say] }.
 */
export function prepareClass(out, submissions, { overrides, roster } = {}) {
  const lines = [];
  const intake = readIntake(out);
  if (intake) {
    for (const s of submissions) {
      const i = intake.submissions.find((x) => x.name === s.name);
      if (i) Object.assign(s, { identity: { ...i.identity }, earlier: i.earlier, intakeNotes: i.notes });
    }
  }
  if (roster) {
    // kept in OUT, so that --report-only and --audit-only find it again without --roster
    if (!existsSync(roster)) throw new Error(`no such roster file: ${roster}`);
    const kept = path.join(out, /\.tsv$/i.test(roster) ? 'roster.tsv' : 'roster.csv');
    if (path.resolve(roster) !== kept) {
      for (const n of ['roster.csv', 'roster.tsv']) rmSync(path.join(out, n), { force: true });
      copyFileSync(roster, kept);
    }
  }
  const rosterFile = fileOr(null, out, ['roster.csv', 'roster.tsv']);
  if (rosterFile) {
    let parsed;
    try {
      parsed = parseRoster(readFileSync(rosterFile, 'utf8'));
    } catch (err) {
      throw new Error(`cannot read the roster ${rosterFile}: ${err.message}`, { cause: err });
    }
    const unmatched = matchRoster(submissions, parsed);
    lines.push(`roster ${rosterFile}: ${parsed.length} students${unmatched.length ? `; not matched: ${unmatched.join(', ')}` : ''}`);
  }
  const overridesFile = fileOr(overrides, out, [OVERRIDES_FILE]);
  if (overrides && !existsSync(overrides)) throw new Error(`no such overrides file: ${overrides}`);
  if (overridesFile) {
    const { applied, unknown } = applyOverrides(submissions, readOverrides(overridesFile));
    lines.push(`${applied} verdict(s) set by the teacher (${overridesFile})${unknown.length ? `; naming no part graded here: ${unknown.join(', ')}` : ''}`);
  }
  return { site: intake ? intake.site : 'folders', lines };
}

/** What to say of the grade files and the feedback written into `out` (report.js's writeClass: `made`). */
export function teacherLines(out, made) {
  return [
    `grades: ${made.gradeFiles.join(', ')}${made.left.length ? `; left out of the import file: ${made.left.join('; ')}` : ''}`,
    `feedback: ${made.feedbackPages.length} page(s) in ${path.join(out, 'feedback')}, and ${made.feedbackZip} for the course site`,
  ];
}
