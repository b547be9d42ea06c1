// Where a download's own layout starts, however it was wrapped: the course site's download as it
// came, unpacked into a folder, or zipped again one folder down (macOS's "Compress" adds __MACOSX/
// beside it; names.js leaves such junk out before this). The rules, as a teacher would say them:
//   - a course site's names at the top (formats.js) are that site's download;
//   - one folder alone at the top (loose files beside it aside) is a wrapping, looked through when
//     what it holds is a site's download or a folder per student; a folder that holds a site's
//     download is never a student;
//   - a folder per student: folders at the top, at least one of them holding a hand-in (a zip, or a
//     page the grader finds as one of the worksheet's parts: p1.html, week4/part2/index.html);
//   - folders and pages named as parts at the top (p1/, WP04P1/, part1.html) are one student's
//     hand-in, not a class, and a top where nothing is a hand-in is no download: both are refused, saying what
//     was found and what each site's download looks like, never graded as one student.
import { detectSite, SITES } from './formats.js';
import { IntakeError } from './zip.js';
import { partNumber, partsOf } from '../../core/part-names.js';

const PAGE = /\.html?$/i;
const ZIP = /\.zip$/i;

/** The top of `files` ([{ segments }]): its folders and its files, hidden names left out. */
function topOf(files) {
  const folders = new Map(), loose = [];
  for (const f of files) {
    const [top] = f.segments;
    if (top.startsWith('.')) continue; // .git/, .vscode/, .gitignore: nobody's
    if (f.segments.length === 1) loose.push(top);
    else {
      if (!folders.has(top)) folders.set(top, []);
      folders.get(top).push({ ...f, segments: f.segments.slice(1) });
    }
  }
  return { folders, loose };
}

/** What the top of `files` is: a site's name, 'folders' (a folder per student), 'handin' (one student's) or 'unknown'. */
function kindOf(files) {
  const { folders, loose } = topOf(files);
  const site = detectSite([
    ...[...folders.keys()].map((top) => ({ top, isFile: false })),
    ...loose.map((top) => ({ top, isFile: true })),
  ]);
  if (site !== 'folders') return site;
  // folders and pages at the top named as parts (p1/, WP04P2/, part3.html): one student's, when at least half are
  const named = [...folders.keys(), ...loose.filter((name) => PAGE.test(name))];
  const parts = named.filter((name) => partNumber(name.replace(PAGE, '')) !== null);
  if (parts.length && parts.length * 2 >= named.length) return 'handin';
  return studentFolders(folders).length ? 'folders' : 'unknown';
}

/** Whether `files` hold a hand-in: a zip, or a page found as a part of the worksheet. */
function holdsHandin(files) {
  if (files.some((f) => ZIP.test(f.segments[f.segments.length - 1]))) return true;
  const pages = files.filter((f) => PAGE.test(f.segments[f.segments.length - 1])).map((f) => f.segments);
  return Object.values(partsOf(pages, (segments) => segments.join('/'))).some(Boolean);
}

/** The folders of `folders` (a Map of name → its files) that hold a hand-in. */
const studentFolders = (folders) =>
  [...folders.entries()].filter(([, inside]) => holdsHandin(inside)).map(([name]) => name);

/** Some of `names`, sorted and quoted, for a message. */
const some = (names, n = 4) =>
  [...names].sort().slice(0, n).map((x) => `"${x}"`).join(', ') + (names.length > n ? `, … (${names.length} in all)` : '');

/** What each site's download looks like, for a message. */
const LOOKS = `${SITES.brightspace}; ${SITES.canvas}; ${SITES.moodle}; or ${SITES.folders}, each holding the student's zip or pages named as parts`;

/** The teacher's message for a top of `files` that is no class's download. */
function refusal(kind, files, where) {
  const { folders, loose } = topOf(files);
  const found = [
    folders.size ? `${folders.size} folder(s) (${some([...folders.keys()])})` : '',
    loose.length ? `${loose.length} file(s) (${some(loose)})` : '',
  ].filter(Boolean).join(' and ') || 'nothing but junk (__MACOSX/, .DS_Store, hidden files)';
  const why = kind === 'handin'
    ? 'folders or pages named as parts at the top: one student\'s hand-in, not a class (grade it with npm run grade -- <its folder>)'
    : 'no folder holding a zip or a page named as a part of the worksheet, and no course site\'s names: not a download the grader knows';
  return new IntakeError(`${where} holds ${found}: ${why}. A download is one of: ${LOOKS}. One folder around any of these is looked through (with __MACOSX/ beside it); __MACOSX/, .DS_Store, Thumbs.db and hidden files are left out`);
}

/**
 * The download's own layout in `files` ([{ segments, ... }], junk already left out): { site,
 * prefix (the folders looked through, outermost first), files (relative to the layout), notes }.
 * Throws an IntakeError naming what was found when the layout is no download's. `where` names the
 * input in that message.
 */
export function findLayout(files, where = 'the download') {
  let inside = files;
  const prefix = [], notes = [];
  for (;;) {
    const kind = kindOf(inside);
    const { folders, loose } = topOf(inside);
    if (kind !== 'folders' && kind !== 'handin' && kind !== 'unknown') return { site: kind, prefix, files: inside, notes };
    const [only] = folders.keys();
    const within = folders.size === 1 ? kindOf(folders.get(only)) : null;
    const wraps = within && within !== 'handin' && within !== 'unknown' &&
      (within !== 'folders' || studentFolders(topOf(folders.get(only)).folders).length >= 2);
    if (wraps) {
      // one folder around the download: looked through (loose files beside it are nobody's)
      notes.push(`looked through "${[...prefix, only].join('/')}/": one folder around the download`);
      for (const name of loose) notes.push(`left out "${[...prefix, name].join('/')}": a file beside the download's folder`);
      prefix.push(only);
      inside = folders.get(only);
      continue;
    }
    if (kind !== 'folders') throw refusal(kind, inside, prefix.length ? `"${prefix.join('/')}/" in ${where}` : where);
    // a folder per student, where no folder holds a site's download
    const downloads = [...folders.entries()].filter(([, f]) => !['folders', 'handin', 'unknown'].includes(kindOf(f))).map(([name]) => name);
    if (downloads.length) throw new IntakeError(`${where} holds ${some(downloads)}, each a course site's download, beside other folders: a download is never one student; give --batch one download at a time`);
    return { site: 'folders', prefix, files: inside, notes };
  }
}
