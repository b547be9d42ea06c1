// Which part of worksheet 4 a page is, from its path alone (pure: no file system, so the grader
// and the check page in the browser find the same parts): WP04P1 … WP04P5 by folder or file name,
// case-insensitive, in the spellings students use (WP04P1, Part1, part1, p1, p01, w4p1, week04p01,
// worksheet4/part1, W4-1, Danish Del1, ...). grader/node/parts.js walks the folders on disk.

export const PARTS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];

// The part number a name stands for, or null. Tried on the file name, then its folders inward out.
const PATTERNS = [
  /wp0?4p0?([1-5])(?![0-9])/i,
  /week0?4p0?([1-5])(?![0-9])/i,
  /w0?4p0?([1-5])(?![0-9])/i,
  /part[-_ ]?0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z])del[-_ ]?0?([1-5])(?![0-9])/i, // Danish: Del1, del_3 (not model1)
  /(?:^|[^a-z])(?:opgave|opg)[-_ ]?0?([1-5])(?![0-9])/i, // Danish: opgave1, opg_2 (the exercise's parts in a week folder)
  // the worksheet's number, a separator, the part's: W4-1, wks4_1, ws04.2, uge4-1, sheet4_1
  /(?:^|[^a-z0-9])(?:w|ws|wk|wks|week|worksheet|sheet|lab|uge|ex|exercise)?0?4[-_.]0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z0-9])p0?([1-5])(?![0-9])/i,
  // a folder (or page) named by the part's number alone, the loosest: week-4/01/index.html … 05/
  /^0?([1-5])$/,
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

const better = (a, b) => {
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return a[i] < b[i];
  return false;
};

/**
 * The parts among a submission's HTML pages: { WP04P1: 'relative/path.html' | null, ... }.
 * `pages` are their paths as segments, in the order a walk of the sorted folders meets them;
 * `join` writes a found page's segments back as a path. A file's own name decides first
 * (week04p01.html, part1.html); an index.html takes its folder's. `overrides` ({ WP04P1: 'path' }) win.
 * @param {string[][]} pages
 * @param {(segments: string[]) => string} join
 */
export function partsOf(pages, join, overrides = {}) {
  const found = Object.fromEntries(PARTS.map((p) => [p, null]));
  const score = {};
  for (const segments of pages) {
    const rel = join(segments);
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
