// Finding a submission's parts on disk: its HTML pages, walked in sorted order, named as
// grader/core/part-names.js reads them (the check page reads a dropped folder the same way).
import { readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { PARTS, partNumber, partsOf } from '../core/part-names.js';

export { PARTS, partNumber };

function htmlFiles(root, dir = '', out = [], depth = 0) {
  if (depth > 6) return out;
  let entries;
  try {
    entries = readdirSync(path.join(root, dir));
  } catch {
    return out;
  }
  for (const name of entries.sort()) {
    if (name.startsWith('.') || name === 'node_modules') continue;
    const rel = path.join(dir, name);
    const st = statSync(path.join(root, rel), { throwIfNoEntry: false });
    if (!st) continue;
    if (st.isDirectory()) htmlFiles(root, rel, out, depth + 1);
    else if (/\.html?$/i.test(name)) out.push(rel);
  }
  return out;
}

/**
 * The parts of one submission: { WP04P1: 'relative/path.html' | null, ... }.
 * A file's own name decides first (week04p01.html, part1.html); an index.html takes its folder's.
 * `overrides` ({ WP04P1: 'path' }) win.
 */
export function findParts(root, overrides = {}) {
  return partsOf(htmlFiles(root).map((rel) => rel.split(path.sep)), (segments) => segments.join(path.sep), overrides);
}
