// Which part of worksheet 4 a page is, from its path alone (pure: no file system; browser-safe):
// WP04P1 … WP04P5 by folder or file name, case-insensitive, in the spellings students use
// (WP04P1, Part1, part1, p1, p01, w4p1, week04p01, worksheet4/part1, Danish Del1, ...).

export const PARTS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];

// The part number a name stands for, or null. Tried on the file name, then its folders inward out.
const PATTERNS = [
  /wp0?4p0?([1-5])(?![0-9])/i,
  /week0?4p0?([1-5])(?![0-9])/i,
  /w0?4p0?([1-5])(?![0-9])/i,
  /part[-_ ]?0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z])del[-_ ]?0?([1-5])(?![0-9])/i, // Danish: Del1, del_3 (not model1)
  /(?:^|[^a-z0-9])p0?([1-5])(?![0-9])/i,
];
export function partNumber(name) {
  for (const re of PATTERNS) {
    const m = re.exec(name);
    if (m) return Number(m[1]);
  }
  return null;
}

const better = (a, b) => {
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return a[i] < b[i];
  return false;
};

/**
 * The parts among a submission's HTML pages: { WP04P1: 'relative/path.html' | null, ... }.
 * `pages` are relative paths split into their segments, in the order a walk of the folders
 * meets them (names sorted). A file's own name decides first (week04p01.html, part1.html); an
 * index.html takes its folder's. `overrides` ({ WP04P1: 'path' }) win.
 * @param {string[][]} pages
 * @param {(segments: string[]) => string} join how a found page's path is written back
 */
export function partsOf(pages, join, overrides = {}) {
  const found = Object.fromEntries(PARTS.map((p) => [p, null]));
  const score = {};
  for (const segments of pages) {
    const base = segments[segments.length - 1].replace(/\.html?$/i, '');
    let n = partNumber(base), rank = 0;
    for (let k = segments.length - 2; n === null && k >= 0; k--) {
      n = partNumber(segments[k]);
      rank = segments.length - 1 - k;
    }
    if (n === null) continue;
    const part = PARTS[n - 1];
    const rel = join(segments);
    // prefer the closest name, then index.html, then the shorter path
    const key = [rank, /^index$/i.test(base) ? 0 : 1, rel.length];
    if (!score[part] || better(key, score[part])) {
      score[part] = key;
      found[part] = rel;
    }
  }
  return { ...found, ...overrides };
}
