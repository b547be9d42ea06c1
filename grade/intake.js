// The class page's side of the intake: the course site's download as the teacher picked or dropped
// it (its .zip, or the folder it was unpacked into), taken in by the command's own rules
// (grader/class/intake/take-in.js: the site, the latest hand-in, the names, the bounds), each
// hand-in kept in the browser as a map of its files. Nothing is written anywhere.
import { TooBig, IntakeError } from '../grader/class/intake/zip.js';
import { isJunk } from '../grader/class/intake/names.js';
import { zipListing } from '../grader/class/intake/download.js';
import { takeInDownload } from '../grader/class/intake/take-in.js';

export { IntakeError };

/**
 * A picked or dropped folder's files ([{ path, bytes }], '/'-separated paths with the folder's own
 * name first) as a download's listing ({ files: [{ segments, read(cap) }], notes }), relative to
 * the folder, as the command lists a folder given to --batch.
 */
export function folderListing(entries) {
  const files = [];
  for (const e of entries) {
    const segments = e.path.split('/').filter(Boolean).slice(1);
    if (!segments.length || isJunk(segments)) continue;
    files.push({ segments, read: (cap) => {
      if (e.bytes.length > cap) throw new TooBig(e.bytes.length);
      return e.bytes;
    } });
  }
  return { files, notes: [] };
}

/**
 * The download `listing` (zipListing's or folderListing's) named `input` (the file's or folder's
 * name), taken in within `bounds` (the rubric's unpack); `due`: dueTime's form or null. Returns
 * take-in.js's { site, found, submissions, notes }, each submission with `handIn`: its files as a
 * Map of path ('/'-separated, relative to the hand-in) to bytes (empty where it could not be unpacked).
 */
export function takeInClass(listing, input, bounds, due = null) {
  return takeInDownload(listing, input, bounds, due, (s, sub) => {
    const files = new Map();
    Object.defineProperty(sub, 'handIn', { value: files, enumerable: false });
    return { put: (segments, data) => files.set(segments.join('/'), data), failed: () => files.clear() };
  });
}

/** A download zip's bytes named `input`, taken in (takeInClass); throws an IntakeError where it is not a zip the grader can read. */
export function takeInZip(bytes, input, bounds, due = null) {
  let listing;
  try {
    listing = zipListing(bytes);
  } catch (err) {
    if (err instanceof IntakeError) throw new IntakeError(`${input} could not be read as a download: ${err.message}`);
    throw err;
  }
  return takeInClass(listing, input, bounds, due);
}
