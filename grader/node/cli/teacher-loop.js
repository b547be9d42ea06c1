// The teacher's loop around the report, in every mode that writes it (grading, --audit-only,
// --report-only): before, each student gets the identity the intake read (OUT/intake.json), the
// roster's ids (--roster, kept as OUT/roster.csv) and the teacher's overrides (--overrides, or
// OUT/overrides.tsv); after, the grade files in the course site's format, the feedback pages and
// the feedback zip.
import { copyFileSync, existsSync, readFileSync, rmSync } from 'node:fs';
import path from 'node:path';
import { readIntake } from '../sites/intake/intake.js';
import { OVERRIDES_FILE, applyOverrides, readOverrides } from '../report/overrides.js';
import { matchRoster, parseRoster } from '../../class/roster.js';
import { writeGradeFiles } from '../sites/grades-export.js';
import { writeFeedback } from '../sites/feedback-zip.js';
import { feedbackHtml } from '../report/feedback-page.js';

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

/** Writes the grade files and the feedback (pages and zip) for the report's `rows`; returns lines to say. */
export function writeTeacherFiles(out, rows, rubric, site) {
  const grades = writeGradeFiles(out, rows, site, rubric.points);
  const feedback = writeFeedback(out, rows, (s) => feedbackHtml(s, out, rubric), site);
  return [
    `grades: ${grades.files.map((f) => path.basename(f)).join(', ')}${grades.left.length ? `; left out of the import file: ${grades.left.join('; ')}` : ''}`,
    `feedback: ${feedback.pages.length} page(s) in ${path.join(out, 'feedback')}, and ${path.basename(feedback.zip)} for the course site`,
  ];
}
