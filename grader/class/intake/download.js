// A course site's download read from its files (a zip's bytes, or a folder's listing the caller
// made): the site's layout found through any folder around it (wrapping.js), the hand-ins grouped
// by student (formats.js), each late or not against the due time, and each student's name as the
// report shows it (the site's name, with the user id where two share one; distinct as a file
// name). No files are read or written here: the command does that (grader/node/sites/intake/).
import { entryData, zipEntries } from './zip.js';
import { isJunk, safeSegments } from './names.js';
import { groupBySite, lateOf } from './formats.js';
import { findLayout } from './wrapping.js';
import { safeName } from '../../files/safe-name.js';

/** The files of a download zip's `bytes`: { files: [{ segments, read(cap) }], notes (what was left out) }. */
export function zipListing(bytes) {
  const entries = zipEntries(bytes);
  const files = [], notes = [];
  for (const e of entries) {
    if (e.dir) continue;
    const safe = safeSegments(e.name);
    if (safe.unsafe || e.symlink) { notes.push(`left out "${e.name}" of the download: ${safe.unsafe || 'a symbolic link'}`); continue; }
    if (isJunk(safe.segments)) continue;
    files.push({ segments: safe.segments, read: (cap) => entryData(bytes, e, cap) });
  }
  return { files, notes };
}

/**
 * The download's students, from its listing (`files`: [{ segments, read(cap) }]) named `input`:
 * { site, layout (findLayout's: prefix, notes), students: [{ name, identity, earlier, files }]
 * (sorted by name), notes }. `due`: the due time (dueTime's form) that makes a timed hand-in late.
 */
export function downloadStudents(files, input, due = null) {
  // the site's own layout, looked for through any folder around it (wrapping.js)
  const layout = findLayout(files, input);
  const { site, students, notes } = groupBySite(layout.files, layout.site);
  for (const s of students) {
    s.identity.late = lateOf(s.identity, due);
    for (const e of s.earlier) e.late = lateOf(e, due);
  }
  if (due && students.some((s) => !s.identity.time && s.identity.late === null)) notes.push(`--due ${due.replace('T', ' ')}: this download's names carry no hand-in time, so late is not known`);
  // the name the report shows: the site's name for the student, with the user id when two share one
  const count = new Map();
  for (const s of students) count.set(s.identity.name, (count.get(s.identity.name) || 0) + 1);
  const used = new Set();
  const named = students.sort((a, b) => a.identity.name.localeCompare(b.identity.name)).map((s) => {
    let name = count.get(s.identity.name) > 1 && s.identity.userId ? `${s.identity.name} (${s.identity.userId})` : s.identity.name;
    while (used.has(safeName(name))) name = `${name}+`;
    used.add(safeName(name));
    return { ...s, name };
  });
  return { site, layout, students: named, notes };
}
