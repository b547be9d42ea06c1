// --batch's side of the intake: the download read (intake.js), what was found said on stdout, and
// each hand-in that could not be unpacked given its result at once (every part `fail`, the reason
// the message), so that no browser opens it and the report still lists the student.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { intake } from './intake.js';
import { IntakeError } from '../../../class/intake/zip.js';
import { PARTS } from '../../../files/parts.js';
import { safeName } from '../../../files/layout.js';
import { notUnpackedRow } from '../../../class/part-rows.js';

/**
 * Reads the download `input` into `out` (the rubric's unpack bounds; `due`, dueTime's form, makes a
 * hand-in after it late) and says what it found.
 * Returns the submissions to grade ([{ name, root }]) and all of them ({ all }, the failed too).
 * Throws an Error with a message for the teacher when `input` cannot be read at all.
 */
export function takeIn(input, out, rubric, { log = console.log, due = null } = {}) {
  let got;
  try {
    got = intake(input, out, rubric.unpack, due);
  } catch (err) {
    if (err instanceof IntakeError) throw new Error(err.message, { cause: err });
    throw err;
  }
  const failed = got.submissions.filter((s) => s.error);
  const earlier = got.submissions.filter((s) => s.earlier.length);
  const late = got.submissions.filter((s) => s.identity.late);
  log(`grade: found ${got.found}: ${got.submissions.length} hand-in(s)` +
    (earlier.length ? `; ${earlier.length} student(s) handed in more than once (the latest is graded)` : '') +
    (late.length ? `; ${late.length} late` : '') +
    (failed.length ? `; ${failed.length} could not be unpacked` : '') + ` (${got.seconds.toFixed(1)} s)`);
  for (const s of failed) log(`grade: ${s.name}: ${s.error}`);
  for (const n of got.notes) log(`grade: ${n}`);
  for (const s of failed) writeNotUnpacked(out, s);
  return {
    submissions: got.submissions.filter((s) => !s.error).map((s) => ({ name: s.name, root: s.root })),
    all: got.submissions,
  };
}

/** Every part of `s` failed with its intake message as the reason (parts/<student>/<part>.json). */
function writeNotUnpacked(out, s) {
  const dir = path.join(out, 'parts', safeName(s.name));
  mkdirSync(dir, { recursive: true });
  for (const part of PARTS) {
    writeFileSync(path.join(dir, `${part}.json`), JSON.stringify(notUnpackedRow(s.name, part, s.error), null, 1));
  }
}
