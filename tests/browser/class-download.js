// A built Brightspace download of three fixture hand-ins, for the class page's specs: wanda (P1 a
// wireframe drawn once, P2 drawn once: her zip wraps her folders one folder down), signe (her parts
// in worksheet4/, a button that closes the window) and "Broken Zip" (a zip cut short: contained to
// its own student). Written as the course site names it (tests/unit/downloads.js).
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { makeZip, entriesOf, siteName } from '../unit/downloads.js';

const HANDINS = path.resolve('tests/fixtures/handins');

/** The students of the download: name, k (their ids' number) and their own zip's bytes. */
export const CLASS_STUDENTS = [
  { name: 'Wanda Wire', k: 1, zip: () => makeZip(entriesOf(path.join(HANDINS, 'wanda'), 'wanda-worksheet4/')) },
  { name: 'Signe Søndergård', k: 2, zip: () => makeZip(entriesOf(path.join(HANDINS, 'signe'))) },
  { name: 'Broken Zip', k: 3, zip: () => makeZip([{ name: 'index.html', data: 'hello world '.repeat(100) }]).slice(0, 120) },
];

/** Writes the download to `file` (the students `students`, by default all three); returns `file`. */
export function writeClassDownload(file, students = CLASS_STUDENTS) {
  const entries = students.map((s) => ({ name: siteName('brightspace', s, `${s.name.split(' ')[0].toLowerCase()}.zip`), data: s.zip(), store: true }));
  writeFileSync(file, makeZip(entries));
  return file;
}
