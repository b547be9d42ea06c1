// Which part of worksheet 4 a page is, from its path alone (pure: no file system, so the grader
// and the check page in the browser find the same parts): WP04P1 … WP04P5 by folder or file name,
// case-insensitive, in the spellings students use (WP04P1, Part1, part1, p1, p01, w4p1, week04p01,
// worksheet4/part1, W4-1, Danish Del1, ...); a course site's numbered sections (3.2.1.-Sphere …
// 3.2.5.-Phong-shading); a step's title in a name (sphere/, gouraud.html) or, where the names say
// nothing, in the page's <title> or first heading. grader/files/parts.js walks the folders on disk.

export const PARTS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];

// The part number a name stands for, or null. Tried on the file name, then its folders inward out.
const PATTERNS = [
  /wp0?4p0?([1-5])(?![0-9])/i,
  /week0?4p0?([1-5])(?![0-9])/i,
  /w0?4p0?([1-5])(?![0-9])/i,
  /part[-_ ]?0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z])del[-_ ]?0?([1-5])(?![0-9])/i, // Danish: Del1, del_3 (not model1)
  /(?:^|[^a-z])(?:opgave|opg)[-_ ]?0?([1-5])(?![0-9])/i, // Danish: opgave1, opg_2 (the exercise's parts in a week folder)
  // the worksheet's number, a separator, the part's: W4-1, wks4_1, ws04.2, uge4-4, sheet4_1
  /(?:^|[^a-z0-9])(?:w|ws|wk|wks|week|worksheet|sheet|lab|uge|ex|exercise)?0?4[-_.]0?([1-5])(?![0-9])/i,
  /(?:^|[^a-z0-9])p0?([1-5])(?![0-9])/i,
  // a folder (or page) named by the part's number alone, the loosest: week-4/01/index.html … 05/
  /^0?([1-5])$/,
];
// the patterns a page's own title may use: the part named outright, never a loose number in prose
const TITLE_PATTERNS = PATTERNS.slice(0, 6);

// The step each part's slide is titled by, most particular first ("Phong shading" before "shading").
const STEPS = [
  [5, /phong[-_ ]*shading|per[-_ ]*fragment/i],
  [4, /phong[-_ ]*(?:reflection|lighting|illumination|model)|reflection[-_ ]*model|specular/i],
  [3, /gouraud/i],
  [2, /cull|depth[-_ ]*test|hidden[-_ ]*surface|back[-_ ]*face/i],
  [1, /sphere|tetrahedron|subdivi/i],
];

/** A page's title and heading: the characters kept for a note. */
const TITLE_KEPT = 120;

/** The part whose step a title names ("Gouraud shading" → 3), or null. */
export function stepOfTitle(title) {
  const hit = STEPS.find(([, re]) => re.test(title || ''));
  return hit ? hit[0] : null;
}

// A course site's numbered section: "3.2.1.-Sphere", "2. Culling", "04_Phong-shading": the last number
// is the part's, the rest its place in the site; a section named for a worksheet, a week or a lab is
// not a part.
const SECTION = /^((?:\d{1,2}\.)*)0?(\d{1,2})\.?[-_ ]+([a-z].*)$/i;
const NOT_A_PART = /worksheet|week|sheet|lab|uge|assignment|module|chapter|lecture/i;
function sectionOf(name) {
  const m = SECTION.exec(name);
  return m && !NOT_A_PART.test(m[3]) ? { prefix: m[1], n: Number(m[2]), title: m[3] } : null;
}

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
// strengths past the names' patterns: a numbered section, a step's title in a name, a page's own title
const BY_SECTION = PATTERNS.length, BY_STEP_NAME = BY_SECTION + 1, BY_PAGE_TITLE = BY_STEP_NAME + 1;

const better = (a, b) => {
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return a[i] < b[i];
  return false;
};

/**
 * The numbered sections that are this worksheet's parts: among the sections numbered 1 … 5 that sit
 * side by side (the same folder, the same number before the last), the run whose titles name the
 * most of worksheet 4's steps (at least one). A Set of their keys (`folder/prefix`), or empty.
 */
function worksheetSections(pages) {
  const runs = new Map(); // key → the steps its titles name
  for (const segments of pages) {
    segments.forEach((name, k) => {
      const s = sectionOf(k === segments.length - 1 ? name.replace(/\.html?$/i, '') : name);
      if (!s || s.n < 1 || s.n > PARTS.length) return;
      const key = `${segments.slice(0, k).join('/')}|${s.prefix}`;
      if (!runs.has(key)) runs.set(key, new Set());
      const step = stepOfTitle(s.title);
      if (step) runs.get(key).add(`${s.n}:${step}`);
    });
  }
  let best = null;
  for (const [key, steps] of runs) if (steps.size && (!best || steps.size > runs.get(best).size)) best = key;
  return best ? new Set([best]) : new Set();
}

/**
 * How one page names its part: { n, strength, rank, note } or null. Each name from the file's inward
 * out is tried for a part's name, then (in the worksheet's run of sections) a section number, then a
 * step's title; the page's own title last.
 */
function nameOfPage(segments, sections, title) {
  const base = segments[segments.length - 1].replace(/\.html?$/i, '');
  const names = [...segments.slice(0, -1), base];
  let found = null;
  for (let k = names.length - 1; k >= 0; k--) {
    const rank = names.length - 1 - k;
    // a section of the worksheet's run is read by its last number (3.4.2.-Culling is part 2, not 4.2)
    const s = sectionOf(names[k]);
    if (s && s.n >= 1 && s.n <= PARTS.length && sections.has(`${segments.slice(0, k).join('/')}|${s.prefix}`)) {
      const step = stepOfTitle(s.title);
      const note = step && step !== s.n ? `found as ${PARTS[s.n - 1]} by its section's number (${names[k]}), though its title names the step of ${PARTS[step - 1]}: the number wins` : null;
      return { n: s.n, strength: BY_SECTION, rank, ...(note ? { note } : {}) };
    }
    const m = partName(names[k]);
    if (m) return { ...m, rank };
    const step = stepOfTitle(names[k]);
    if (step && !found) found = { n: step, strength: BY_STEP_NAME, rank };
  }
  if (found) return found;
  if (!title) return null;
  const named = TITLE_PATTERNS.map((re) => re.exec(title)).find(Boolean);
  const n = named ? Number(named[1]) : stepOfTitle(title);
  return n ? { n, strength: BY_PAGE_TITLE, rank: 0, note: `found as ${PARTS[n - 1]} by the page's title ("${title}"): its file and folder names do not name a part` } : null;
}

/**
 * The parts among a submission's HTML pages, and how each was found: { parts: { WP04P1:
 * 'relative/path.html' | null, ... }, notes: { WP04Pn: words } } (a note where a part was found by
 * its page's title, or by a section's number its title disagrees with). `pages` are their paths as
 * segments, in the order a walk of the sorted folders meets them; `join` writes a found page's
 * segments back as a path; `titles` ({ path: the page's <title> or first heading }) are read
 * where names say nothing. A file's own name decides first (week04p01.html, part1.html); an
 * index.html takes its folder's. `overrides` ({ WP04P1: 'path' }) win.
 * @param {string[][]} pages
 * @param {(segments: string[]) => string} join
 */
export function partsFound(pages, join, { overrides = {}, titles = {} } = {}) {
  const found = Object.fromEntries(PARTS.map((p) => [p, null]));
  const notes = {};
  const score = {};
  const sections = worksheetSections(pages);
  for (const segments of pages) {
    const rel = join(segments);
    const base = segments[segments.length - 1].replace(/\.html?$/i, '');
    const m = nameOfPage(segments, sections, titles[rel]);
    if (m === null) continue;
    const part = PARTS[m.n - 1];
    // prefer the exact part name (WP04P1/index.html over p1.html elsewhere), then the closest
    // name, then index.html, then the shorter path
    const key = [m.strength, m.rank, /^index$/i.test(base) ? 0 : 1, rel.length];
    if (!score[part] || better(key, score[part])) {
      score[part] = key;
      found[part] = rel;
      if (m.note) notes[part] = m.note;
      else delete notes[part];
    }
  }
  for (const part of Object.keys(overrides)) delete notes[part];
  return { parts: { ...found, ...overrides }, notes };
}

/** The parts among a submission's HTML pages: { WP04P1: 'relative/path.html' | null, ... } (partsFound's parts). */
export function partsOf(pages, join, overrides = {}, titles = {}) {
  return partsFound(pages, join, { overrides, titles }).parts;
}

/** A page's <title> and first heading, as plain words (what names a step where file names do not); null where neither says anything. */
export function titleOfPage(html) {
  const words = (re) => {
    const m = re.exec(html);
    return m ? m[1].replace(/<[^>]*>/g, ' ').replace(/&[a-z#0-9]+;/gi, ' ').replace(/\s+/g, ' ').trim().slice(0, TITLE_KEPT) : '';
  };
  const both = [words(/<title[^>]*>([\s\S]*?)<\/title>/i), words(/<h[1-3][^>]*>([\s\S]*?)<\/h[1-3]>/i)].filter(Boolean);
  return both.length ? [...new Set(both)].join(' · ') : null;
}
