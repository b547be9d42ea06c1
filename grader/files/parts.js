// Finding a submission's parts on disk: its HTML pages, walked in sorted order, named as
// grader/core/part-names.js reads them (the check page reads a dropped folder the same way).
// A page's path is kept as its folder and file names and written with `path.join` alone (never
// split or joined on a separator), so that Windows' paths work as POSIX's do: `fs` and `path`
// may be given (a made-up file system, path.win32) to test that on any machine.
import { readdirSync, statSync, openSync, readSync, closeSync } from 'node:fs';
import path from 'node:path';
import { PARTS, partNumber, partsFound, titleOfPage } from '../core/part-names.js';

export { PARTS, partNumber };

const NODE_FS = {
  readdir: (dir) => readdirSync(dir),
  isDirectory: (file) => statSync(file, { throwIfNoEntry: false })?.isDirectory() ?? null,
  head,
};

// a page's title and first heading are in its first bytes
const HEAD_BYTES = 65536;
/** The first HEAD_BYTES of `file` as text ('' where it cannot be read). */
function head(file) {
  let fd = null;
  try {
    fd = openSync(file, 'r');
    const buf = Buffer.alloc(HEAD_BYTES);
    return buf.subarray(0, readSync(fd, buf, 0, HEAD_BYTES, 0)).toString('utf8');
  } catch {
    return '';
  } finally {
    if (fd !== null) closeSync(fd);
  }
}

/**
 * The HTML pages under `root`, each as its names from `root` down ([folder, ..., file]), in the
 * order a walk of the sorted folders meets them. `fs`: { readdir(dir) → names, isDirectory(file) →
 * true | false | null (not there) }.
 */
export function htmlPages(root, { fs = NODE_FS, pathImpl = path } = {}) {
  const out = [];
  const walk = (segments) => {
    if (segments.length > 6) return; // (folders six deep at most)
    let names;
    try {
      names = fs.readdir(pathImpl.join(root, ...segments));
    } catch {
      return;
    }
    for (const name of [...names].sort()) {
      if (name.startsWith('.') || name === 'node_modules') continue;
      const here = [...segments, name];
      const dir = fs.isDirectory(pathImpl.join(root, ...here));
      if (dir === null) continue;
      if (dir) walk(here);
      else if (/\.html?$/i.test(name)) out.push(here);
    }
  };
  walk([]);
  return out;
}

/**
 * The parts of one submission: { WP04P1: 'relative/path.html' | null, ... } (relative to `root`,
 * written with `pathImpl`: Windows' separators there). A file's own name decides first
 * (week04p01.html, part1.html); an index.html takes its folder's. `overrides` ({ WP04P1: 'path' }) win.
 */
export function findParts(root, overrides = {}, { fs = NODE_FS, pathImpl = path } = {}) {
  return findPartsWithNotes(root, overrides, { fs, pathImpl }).parts;
}

/**
 * The parts of one submission and how each was found: { parts, notes: { WP04Pn: words } } (core/part-names.js's
 * partsFound), with each page's title read (`fs.head(file)`: its first bytes) where `fs` can.
 */
export function findPartsWithNotes(root, overrides = {}, { fs = NODE_FS, pathImpl = path } = {}) {
  const pages = htmlPages(root, { fs, pathImpl });
  const join = (segments) => pathImpl.join(...segments);
  const titles = {};
  if (fs.head) {
    for (const segments of pages) {
      titles[join(segments)] = titleOfPage(fs.head(pathImpl.join(root, ...segments)));
    }
  }
  return partsFound(pages, join, { overrides, titles });
}
