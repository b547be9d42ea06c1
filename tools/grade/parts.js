// Finding a submission's parts: WP04P1 … WP04P5 by folder or file name, case-insensitive, in the
// spellings students use (WP04P1, Part1, part1, p1, p01, w4p1, week04p01, worksheet4/part1, Danish Del1, ...).
import { readdirSync, statSync } from 'node:fs';
import path from 'node:path';

export const PARTS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];

// The part number a name stands for, or null. Tried on the file name, then its folders inward out.
const PATTERNS = [
  /wp0?4p0?([1-5])(?![0-9])/i,
  /week0?4p0?([1-5])(?![0-9])/i,
  /w0?4p0?([1-5])(?![0-9])/i,
  /part[-_ ]?0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z])del[-_ ]?0?([1-5])(?![0-9])/i, // Danish: Del1, del_3 (not model1)
  // the worksheet's number, a separator, the part's: W4-1, wks4_1, ws04.2, uge4-1, sheet4_1
  /(?:^|[^a-z0-9])(?:w|ws|wk|wks|week|worksheet|sheet|lab|uge|ex|exercise)?0?4[-_.]0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z0-9])p0?([1-5])(?![0-9])/i,
];
export function partNumber(name) {
  const m = partName(name);
  return m ? m.n : null;
}
/** { n, strength }: the part number and how exactly the name says it (0: WP04P1, the slide's own name; higher: looser). */
function partName(name) {
  for (let k = 0; k < PATTERNS.length; k++) {
    const m = PATTERNS[k].exec(name);
    if (m) return { n: Number(m[1]), strength: k };
  }
  return null;
}

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

const better = (a, b) => {
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return a[i] < b[i];
  return false;
};

/**
 * The parts of one submission: { WP04P1: 'relative/path.html' | null, ... }.
 * A file's own name decides first (week04p01.html, part1.html); an index.html takes its folder's.
 * `overrides` ({ WP04P1: 'path' }) win.
 */
export function findParts(root, overrides = {}) {
  const found = Object.fromEntries(PARTS.map((p) => [p, null]));
  const score = {};
  for (const rel of htmlFiles(root)) {
    const segments = rel.split(path.sep);
    const base = segments[segments.length - 1].replace(/\.html?$/i, '');
    let m = partName(base), rank = 0;
    for (let k = segments.length - 2; m === null && k >= 0; k--) {
      m = partName(segments[k]);
      rank = segments.length - 1 - k;
    }
    if (m === null) continue;
    const part = PARTS[m.n - 1];
    // prefer the exact part name (WP04P1/index.html over p1.html elsewhere), then the closest
    // name, then index.html, then the shorter path
    const key = [m.strength, rank, /^index$/i.test(base) ? 0 : 1, rel.length];
    if (!score[part] || better(key, score[part])) {
      score[part] = key;
      found[part] = rel;
    }
  }
  return { ...found, ...overrides };
}
