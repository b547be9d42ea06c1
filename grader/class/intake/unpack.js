// One student's hand-in unpacked: the files as they came, every .zip among them unpacked where it
// lies (a zip inside a zip too, up to the rubric's unpack.maxDepth), the junk zip tools add left
// out, and the whole bounded by the rubric's unpack.maxBytes and unpack.maxFiles, so that a zip
// bomb stops at the bound with a message for that student alone. An entry whose name climbs out,
// is absolute or is a symbolic link is left out and said; two entries of the same name are both
// kept ("a (2).js"). Each file is handed, as it is read, to a `put` of the caller's (the command
// writes it into the student's folder: grader/node/sites/intake/unpack-folder.js; a page keeps it).
import { IntakeError, TooBig, entryData, zipEntries } from './zip.js';
import { distinct, isJunk, safeSegments } from './names.js';

const isZip = (name) => /\.zip$/i.test(name);

/**
 * Unpacks a hand-in. `files`: [{ segments, read(cap) }], where read gives the file's bytes (at most
 * cap of them, else it throws TooBig). `bounds`: the rubric's unpack ({ maxBytes, maxFiles,
 * maxDepth }). `put(segments, data, shown)`: each file, under its own distinct path (segments), as
 * it is read. Returns { files, bytes, notes }; throws an IntakeError with a message for the teacher
 * when the hand-in cannot be unpacked.
 */
export function unpackFiles(files, bounds, put) {
  const state = { put, bounds, files: 0, bytes: 0, notes: [], names: new Map(), dirs: new Map() };
  for (const f of files) {
    if (isJunk(f.segments)) continue;
    place(state, f.segments, (cap) => f.read(cap), 0, f.segments.join('/'));
  }
  return { files: state.files, bytes: state.bytes, notes: state.notes };
}

function tooBig(state) {
  const mb = (n) => `${(n / 1048576).toFixed(0)} MB`;
  return new IntakeError(`it unpacks to more than ${mb(state.bounds.maxBytes)} (the rubric's unpack.maxBytes): a zip bomb, or far more than the worksheet needs; nothing of it was graded`);
}

/** Reads a file's bytes within what is left of the hand-in's byte bound. */
function readBounded(state, read) {
  try {
    return read(state.bounds.maxBytes - state.bytes);
  } catch (err) {
    if (err instanceof TooBig) throw tooBig(state);
    throw err;
  }
}

/** Places the file at `segments` (relative to the hand-in): a zip is unpacked into its folder, anything else handed on. */
function place(state, segments, read, depth, shown) {
  const name = segments[segments.length - 1];
  if (isZip(name)) return unzipInto(state, segments.slice(0, -1), readBounded(state, read), depth + 1, shown);
  const data = readBounded(state, read);
  if (++state.files > state.bounds.maxFiles) throw new IntakeError(`it has more than ${state.bounds.maxFiles} files (the rubric's unpack.maxFiles); nothing of it was graded`);
  state.bytes += data.length;
  if (state.bytes > state.bounds.maxBytes) throw tooBig(state);
  handOn(state, segments, data, shown);
}

function unzipInto(state, folder, bytes, depth, shown) {
  if (depth > state.bounds.maxDepth) throw new IntakeError(`"${shown}" is a zip nested more than ${state.bounds.maxDepth} deep (the rubric's unpack.maxDepth); nothing of it was graded`);
  let entries;
  try {
    entries = zipEntries(bytes);
  } catch (err) {
    if (err instanceof IntakeError) throw new IntakeError(`"${shown}": ${err.message}`);
    throw err;
  }
  // a zip's declared sizes, before anything is inflated (entryData still holds each one to the bound)
  const declared = entries.reduce((n, e) => n + e.size, 0);
  if (state.bytes + declared > state.bounds.maxBytes) throw tooBig(state);
  for (const e of entries) {
    if (e.dir) continue;
    const where = `"${e.name}" in "${shown}"`;
    if (e.symlink) { state.notes.push(`left out ${where}: a symbolic link`); continue; }
    const safe = safeSegments(e.name);
    if (safe.unsafe) { state.notes.push(`left out ${where}: ${safe.unsafe}`); continue; }
    if (isJunk(safe.segments)) continue;
    const read = (cap) => {
      try {
        return entryData(bytes, e, cap);
      } catch (err) {
        if (err instanceof IntakeError) throw new IntakeError(`"${shown}": ${err.message}`);
        throw err;
      }
    };
    place(state, [...folder, ...safe.segments], read, depth, `${shown}/${safe.segments.join('/')}`);
  }
}

/** The children's names taken in the folder `key` (a Set). */
function namesIn(state, key) {
  if (!state.names.has(key)) state.names.set(key, new Set());
  return state.names.get(key);
}

/** Hands `data` on at `segments`, keeping both when a name is taken (by a file or a folder). */
function handOn(state, segments, data, shown) {
  let folderKey = '';
  const real = [];
  for (const seg of segments.slice(0, -1)) {
    const taken = namesIn(state, folderKey);
    const key = folderKey ? `${folderKey}/${seg}` : seg;
    // a folder of the same name as a file already written: the folder gets a distinct name
    const dir = state.dirs.get(key) ?? (taken.has(seg) ? distinct(seg, taken) : seg);
    if (!state.dirs.has(key)) { state.dirs.set(key, dir); taken.add(dir); }
    real.push(dir);
    folderKey = key;
  }
  const taken = namesIn(state, folderKey);
  const file = distinct(segments[segments.length - 1], taken);
  if (file !== segments[segments.length - 1]) state.notes.push(`two files named "${shown}": the second kept as "${file}"`);
  taken.add(file);
  real.push(file);
  state.put(real, data, shown);
}
