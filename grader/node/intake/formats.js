// Which course site a download comes from, told by its shape, and who handed in what: each site
// names a hand-in after the student, and that name is where the identity (name, user id,
// submission id, time, late) is read, never from a folder someone renamed afterwards.
//   Brightspace (Assignments → Download): a folder a submission,
//     "<submission id>-<user id> - <First Last> - <Mon D, YYYY H:MM AM>" (the colon left out in
//     downloads since about 2020: "Oct 10, 2025 1022 AM"), and an index.html listing them;
//     older downloads put the files loose: "<same> - <original name>".
//   Canvas (Download Submissions): files "<lastfirst>[_late]_<user id>_<file id>_<original name>"
//     (canvas-lms lib/content_zipper.rb: the student's sortable name with all but letters, digits
//     and "_" taken out, lower-cased; "late" when the submission is late; then the user id, and for
//     each file handed in its own attachment id). Only the latest submission is in the download, so
//     a student's files, each with its own id, are one hand-in.
//   Moodle (Download all submissions): folders "<Full Name>_<participant id>_assignsubmission_file"
//     (older versions end it with "_"; without "download as folders", files
//     "<Full Name>_<participant id>_assignsubmission_file_<original name>").
//   Otherwise a folder a student, named as the teacher likes.

const MONTHS = ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'];
const BRIGHTSPACE = new RegExp(`^(\\d+)-(\\d+) - (.+?) - ((?:${MONTHS.join('|')}) \\d{1,2}, \\d{4} \\d{1,2}:?\\d{2} [AP]M)(?: - (.+))?$`);
const CANVAS = /^([^_/]+?)(_late)?_(\d+)_(\d+)_(.+)$/i;
const MOODLE = /^(.+)_(\d+)_assignsubmission_([a-z]+)(?:_(.*))?$/;

export const SITES = {
  brightspace: 'Brightspace (D2L) download: a folder a submission, "<submission id>-<user id> - <name> - <date time>"',
  canvas: 'Canvas download: files "<lastfirst>_<user id>_<file id>_<name>" (late: "_late_")',
  moodle: 'Moodle download: folders "<Full Name>_<participant id>_assignsubmission_file"',
  folders: 'a folder a student',
};

/** "Oct 10, 2025 1022 AM" (or "10:22 AM") as "2025-10-10T10:22" (the course site's local time), or null. */
export function brightspaceTime(text) {
  const m = /^([A-Z][a-z]{2}) (\d{1,2}), (\d{4}) (\d{1,2}):?(\d{2}) ([AP])M$/.exec(text);
  if (!m) return null;
  let h = Number(m[4]) % 12;
  if (m[6] === 'P') h += 12;
  const two = (n) => String(n).padStart(2, '0');
  return `${m[3]}-${two(MONTHS.indexOf(m[1]) + 1)}-${two(m[2])}T${two(h)}:${m[5]}`;
}

/**
 * A due date as the teacher writes it ("2025-10-10 23:59" or "2025-10-10T23:59", the course site's
 * local time, as its names give hand-in times) in the form brightspaceTime gives, or null.
 */
export function dueTime(text) {
  const m = /^(\d{4})-(\d{2})-(\d{2})[ T](\d{1,2}):(\d{2})$/.exec(String(text).trim());
  if (!m || Number(m[2]) < 1 || Number(m[2]) > 12 || Number(m[3]) < 1 || Number(m[3]) > 31 || Number(m[4]) > 23 || Number(m[5]) > 59) return null;
  return `${m[1]}-${m[2]}-${m[3]}T${m[4].padStart(2, '0')}:${m[5]}`;
}

/**
 * Late, from the hand-in's time and the due date (both as dueTime gives them): a hand-in after the
 * due minute is late. Where the site's name said it (Canvas's "_late"), that stands; where there is
 * no time or no due date, it is not known (null).
 */
export function lateOf(identity, due) {
  if (identity.late !== null && identity.late !== undefined) return identity.late;
  if (!due || !identity.time) return null;
  return identity.time > due;
}

/**
 * What one top-level name of a download says, for `site`: { userId, name, submissionId, time, late,
 * rest } (rest: the original file name when the site puts files loose), or null when it is not of
 * that site's shape. `isFile`: the name is a file at the top of the download.
 */
export function parseTopName(site, top, isFile) {
  if (site === 'brightspace') {
    const m = BRIGHTSPACE.exec(top);
    if (!m || (isFile && !m[5]) || (!isFile && m[5])) return null;
    return { submissionId: m[1], userId: m[2], name: m[3], time: brightspaceTime(m[4]), late: null, rest: m[5] || null };
  }
  if (site === 'canvas') {
    const m = isFile ? CANVAS.exec(top) : null;
    return m ? { name: m[1], late: Boolean(m[2]), userId: m[3], submissionId: null, fileId: m[4], time: null, rest: m[5] } : null;
  }
  if (site === 'moodle') {
    const m = MOODLE.exec(top);
    if (!m || (isFile && !m[4])) return null;
    return { name: m[1], userId: m[2], submissionId: null, time: null, late: null, plugin: m[3], rest: isFile ? m[4] : null };
  }
  return null;
}

/** Files of a download the site adds beside the hand-ins (Brightspace's index.html listing them). */
const SITE_FILES = { brightspace: /^index\.html?$/i };

/**
 * The site of a download from its top-level names ([{ top, isFile }]): the site whose shape most
 * names have (at least half of them), else 'folders'.
 */
export function detectSite(tops) {
  let best = 'folders', most = 0;
  for (const site of ['brightspace', 'canvas', 'moodle']) {
    const considered = tops.filter((t) => !(SITE_FILES[site] && t.isFile && SITE_FILES[site].test(t.top)));
    const n = considered.filter((t) => parseTopName(site, t.top, t.isFile)).length;
    if (n > most && n * 2 >= considered.length) { best = site; most = n; }
  }
  return best;
}

/**
 * The download's hand-ins: `files` ([{ segments, ... }], paths in the download) grouped by student;
 * `site`: the download's site, as detectSite tells it from the names at the top when not given.
 * Returns { site, students: [{ identity, files (segments relative to the hand-in), earlier }], notes }.
 * A student with several hand-ins (Brightspace keeps each one) is graded on the latest; the
 * earlier ones are listed with their times.
 */
export function groupBySite(files, site = detectSite([...new Map(files.map((f) => [f.segments[0], { top: f.segments[0], isFile: f.segments.length === 1 }])).values()].filter((t) => !t.top.startsWith('.')))) {
  const notes = [];
  const byUser = new Map();
  for (const f of files) {
    const top = f.segments[0], isFile = f.segments.length === 1;
    if (top.startsWith('.')) continue; // .git/, .vscode/, .gitignore beside the hand-ins: nobody's
    let id;
    if (site === 'folders') {
      if (isFile) { notes.push(`left out "${top}": a file at the top of the download, not a student's folder`); continue; }
      id = { name: top, userId: null, submissionId: null, time: null, late: null, rest: null };
    } else {
      id = parseTopName(site, top, isFile);
      if (!id) {
        if (!(SITE_FILES[site] && isFile && SITE_FILES[site].test(top))) notes.push(`left out "${top}": not named as ${site} names a hand-in`);
        continue;
      }
      if (id.plugin && id.plugin !== 'file') continue; // Moodle's online text and comments: not files handed in
    }
    const user = id.userId ?? `folder:${top}`;
    if (!byUser.has(user)) byUser.set(user, new Map());
    const subs = byUser.get(user);
    const subKey = `${id.submissionId}|${id.time}|${site === 'folders' ? top : ''}`;
    if (!subs.has(subKey)) subs.set(subKey, { identity: { site, name: id.name, userId: id.userId, submissionId: id.submissionId, time: id.time, late: id.late, source: [], ...(id.fileId ? { fileIds: [] } : {}) }, files: [] });
    const sub = subs.get(subKey);
    const source = isFile ? top : `${top}/`;
    if (!sub.identity.source.includes(source)) sub.identity.source.push(source);
    if (id.fileId && !sub.identity.fileIds.includes(id.fileId)) sub.identity.fileIds.push(id.fileId);
    sub.files.push({ ...f, segments: isFile ? [id.rest] : f.segments.slice(1) });
  }
  const students = [];
  for (const subs of byUser.values()) {
    // the latest first: by time, then by submission id (a later submission has a larger id)
    const order = [...subs.values()].sort((a, b) => String(b.identity.time).localeCompare(String(a.identity.time)) || Number(b.identity.submissionId) - Number(a.identity.submissionId));
    const [latest, ...rest] = order;
    students.push({ ...latest, earlier: rest.map((s) => ({ time: s.identity.time, late: s.identity.late, submissionId: s.identity.submissionId, source: s.identity.source, files: s.files.length })) });
  }
  return { site, students, notes };
}
