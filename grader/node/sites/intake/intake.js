// npm run grade -- --batch <download>: a course site's download (its .zip, or the folder it was
// unpacked into, either one inside a folder around it: wrapping.js) turned into one folder a
// student, each with the identity the site gave it.
// A folder a student with no zip in it is graded where it is, as before; everything else is
// unpacked (safely, bounded: class/intake/unpack.js) into OUT/handins/<student>/. What was found is written
// to OUT/intake.json, which every later run of the report (--report-only, --audit-only) reads.
import { existsSync, lstatSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { IntakeError, TooBig } from '../../../class/intake/zip.js';
import { isJunk } from '../../../class/intake/names.js';
import { zipListing } from '../../../class/intake/download.js';
import { takeInDownload } from '../../../class/intake/take-in.js';
import { handinWriter } from './unpack-folder.js';
import { safeName } from '../../../files/layout.js';

export const INTAKE_FILE = 'intake.json';

/** The files under folder `root`: [{ segments, read(cap) }] (links are not followed, and said). */
function folderFiles(root) {
  const files = [], notes = [];
  const walk = (segments) => {
    for (const name of readdirSync(path.join(root, ...segments)).sort()) {
      const rel = [...segments, name];
      if (isJunk(rel)) continue;
      const full = path.join(root, ...rel);
      const st = lstatSync(full);
      if (st.isSymbolicLink()) notes.push(`left out "${rel.join('/')}": a symbolic link`);
      else if (st.isDirectory()) walk(rel);
      else if (st.isFile()) {
        files.push({ segments: rel, size: st.size, read: (cap) => {
          if (st.size > cap) throw new TooBig(st.size);
          return readFileSync(full);
        } });
      }
    }
  };
  walk([]);
  return { files, notes };
}

/**
 * Reads the download `input` (a .zip or a folder) into one folder a student under `out`/handins.
 * `bounds`: the rubric's unpack; `due`: the due date (dueTime's form) that makes a timed hand-in
 * late, or null. Returns { site, found (what it was, in words), due, submissions: [{ name, root,
 * identity, earlier, notes, error }], notes, seconds }, also written to OUT/intake.json.
 */
export function intake(input, out, bounds, due = null) {
  const t0 = Date.now();
  const isZipFile = lstatSync(input).isFile();
  let listing;
  try {
    listing = isZipFile ? zipListing(readFileSync(input)) : folderFiles(input);
  } catch (err) {
    if (err instanceof IntakeError) throw new IntakeError(`${input} could not be read as a download: ${err.message}`);
    throw err;
  }
  const handins = path.join(out, 'handins');
  rmSync(handins, { recursive: true, force: true });
  const got = takeInDownload(listing, input, bounds, due, (s, sub, { site, layout }) => {
    if (site === 'folders' && !isZipFile && !s.files.some((f) => /\.zip$/i.test(f.segments[f.segments.length - 1]))) {
      // as before: a plain folder is graded where it lies
      sub.root = path.resolve(input, ...layout.prefix, s.identity.source[0].replace(/\/$/, ''));
      return null;
    }
    sub.root = path.join(handins, safeName(sub.name));
    return { put: handinWriter(sub.root), failed: () => rmSync(sub.root, { recursive: true, force: true }) };
  });
  const result = {
    site: got.site,
    found: got.found,
    input: path.resolve(input),
    due,
    submissions: got.submissions,
    notes: got.notes,
    seconds: (Date.now() - t0) / 1000,
  };
  writeFileSync(path.join(out, INTAKE_FILE), JSON.stringify(result, null, 1));
  return result;
}

/** OUT/intake.json, or null when the class came as folders before intake existed. */
export function readIntake(out) {
  const f = path.join(out, INTAKE_FILE);
  return existsSync(f) ? JSON.parse(readFileSync(f, 'utf8')) : null;
}
