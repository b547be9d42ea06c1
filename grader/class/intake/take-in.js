// A course site's download taken in: its students named (download.js) and each one's hand-in
// unpacked (unpack.js) through the caller's `put`, a hand-in that cannot be unpacked (a zip bomb, a
// broken zip, a name that climbs out) given its message and contained to its own student. The
// command writes each hand-in into a folder (grader/node/sites/intake/intake.js), the class page
// keeps it in the browser (grade/); both take the download in here.
import { IntakeError } from './zip.js';
import { SITES } from './formats.js';
import { downloadStudents } from './download.js';
import { unpackFiles } from './unpack.js';

/**
 * The download's `listing` ({ files, notes }: zipListing's, or a folder's listed by the caller)
 * named `input`, taken in within `bounds` (the rubric's unpack); `due`: dueTime's form, or null.
 * `open(student, sub, { site, layout })` says where each hand-in goes: { put(segments, data, shown),
 * failed() (its hand-in could not be unpacked) }, or null to unpack nothing (the caller has set
 * what it needs on `sub`). Returns { site, found (in words), submissions: [{ name, identity,
 * earlier, notes, error, ...what open set, files, bytes }], notes }.
 */
export function takeInDownload(listing, input, bounds, due, open) {
  const { site, layout, students, notes } = downloadStudents(listing.files, input, due);
  const submissions = students.map((s) => {
    const sub = { name: s.name, identity: s.identity, earlier: s.earlier, notes: [], error: null };
    const to = open(s, sub, { site, layout });
    if (!to) return sub;
    try {
      const done = unpackFiles(s.files, bounds, to.put);
      sub.notes = done.notes;
      Object.assign(sub, { files: done.files, bytes: done.bytes });
    } catch (err) {
      if (!(err instanceof IntakeError)) throw err;
      to.failed();
      sub.error = `the hand-in could not be unpacked: ${err.message}`;
    }
    return sub;
  });
  return { site, found: SITES[site], submissions, notes: [...listing.notes, ...layout.notes, ...notes] };
}
