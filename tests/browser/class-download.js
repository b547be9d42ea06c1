// A built Brightspace download of three fixture hand-ins, for the class page's specs: wanda (P1 a
// wireframe drawn once, P2 drawn once: her zip wraps her folders one folder down), signe (her parts
// in worksheet4/, a button that closes the window) and "Broken Zip" (a zip cut short: contained to
// its own student). Written as the course site names it (tests/unit/downloads.js).
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { expect } from '@playwright/test';
import { makeZip, entriesOf, siteName } from '../unit/downloads.js';

const HANDINS = path.resolve('tests/fixtures/handins');

/** The students of the download: name, k (their ids' number) and their own zip's bytes. */
export const CLASS_STUDENTS = [
  { name: 'Wanda Wire', k: 1, zip: () => makeZip(entriesOf(path.join(HANDINS, 'wanda'), 'wanda-worksheet4/')) },
  { name: 'Signe Søndergård', k: 2, zip: () => makeZip(entriesOf(path.join(HANDINS, 'signe'))) },
  { name: 'Broken Zip', k: 3, zip: () => makeZip([{ name: 'index.html', data: 'hello world '.repeat(100) }]).slice(0, 120) },
];

/** The class list Brightspace exports for the grade import (OrgDefinedId with leading zeros, as text), one student left out of it. */
export const CLASS_ROSTER = 'OrgDefinedId,Username,Last Name,First Name,Email,End-of-Line Indicator\n' +
  '#00000101,#wawi,Wire,Wanda,wawi@student.example,#\n#00000102,#sisø,Søndergård,Signe,siso@student.example,#\n';

/** Writes the download to `file` (the students `students`, by default all three); returns `file`. */
export function writeClassDownload(file, students = CLASS_STUDENTS) {
  const entries = students.map((s) => ({ name: siteName('brightspace', s, `${s.name.split(' ')[0].toLowerCase()}.zip`), data: s.zip(), store: true }));
  writeFileSync(file, makeZip(entries));
  return file;
}

/**
 * `npm run grade -- --batch` on `zip` into `dir`/command (our reference left out, as on the page
 * with ?reference=0; `more`: options such as --browser firefox or --overrides FILE): { report
 * (report.json), out }.
 */
export function commandReport(zip, dir, more = []) {
  const rubric = path.join(dir, 'rubric.json');
  writeFileSync(rubric, JSON.stringify({ reference: false }));
  const out = path.join(dir, 'command');
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--batch', zip, '--rubric', rubric, '--out', out, ...more],
    { encoding: 'utf8', timeout: 600_000 });
  expect(run.status, run.stderr + run.stdout.slice(-2000)).toBe(0);
  return { report: JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')), out };
}

/** Each student's parts, as window.grading and report.json have them: { name: [[part, verdict, reasons]] }. */
export const verdictsOf = (students) => Object.fromEntries(students.map((s) => [s.name, s.parts.map((p) => [p.part, p.verdict, p.reasons])]));
