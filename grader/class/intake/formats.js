// Which course site a download comes from, told by its shape, and who handed in what: each site
// names a hand-in after the student, and that name is where the identity (name, user id,
// submission id, time, late) is read, never from a folder someone renamed afterwards. How each site
// names its hand-ins is its adapter's (grader/class/adapters/brightspace.js, canvas.js, moodle.js,
// folders.js: a folder a student, named as the teacher likes).
import { SITE_ADAPTERS, siteAdapter } from '../adapters/index.js';

export { SITES } from '../adapters/index.js';
export { brightspaceTime } from '../adapters/brightspace.js';

/**
 * A due date as the teacher writes it ("2025-10-10 23:59" or "2025-10-10T23:59", the course site's
 * local time, as its names give hand-in times) in the form brightspaceTime gives, or null.
 */
export function dueTime(text) {
  const m = /^(\d{4})-(\d{2})-(\d{2})[ T](\d{1,2}):(\d{2})$/.exec(String(text).trim());
  if (
    !m ||
    Number(m[2]) < 1 ||
    Number(m[2]) > 12 ||
    Number(m[3]) < 1 ||
    Number(m[3]) > 31 ||
    Number(m[4]) > 23 ||
    Number(m[5]) > 59
  ) {
    return null;
  }
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
 * The site of a download from its top-level names ([{ top, isFile }]): the site whose shape most
 * names have (at least half of them), else 'folders'.
 */
export function detectSite(tops) {
  let best = SITE_ADAPTERS.find((a) => a.fallback).id, most = 0;
  for (const site of SITE_ADAPTERS.filter((a) => !a.fallback)) {
    const considered = tops.filter((t) => !(site.siteFile && t.isFile && site.siteFile.test(t.top)));
    const n = considered.filter((t) => site.parseTopName(t.top, t.isFile)).length;
    if (n > most && n * 2 >= considered.length) { best = site.id; most = n; }
  }
  return best;
}

/** The tops of `files` (their first segments), each once: { top, isFile }. */
const topsOf = (files) =>
  [...new Map(files.map((f) => [f.segments[0], { top: f.segments[0], isFile: f.segments.length === 1 }])).values()];

/**
 * The download's hand-ins: `files` ([{ segments, ... }], paths in the download) grouped by student;
 * `site`: the download's site, as detectSite tells it from the names at the top when not given.
 * Returns { site, students: [{ identity, files (segments relative to the hand-in), earlier }], notes }.
 * A student with several hand-ins (Brightspace keeps each one) is graded on the latest; the
 * earlier ones are listed with their times.
 */
export function groupBySite(files, site = detectSite(topsOf(files).filter((t) => !t.top.startsWith('.')))) {
  const notes = [];
  const byUser = new Map();
  const adapter = siteAdapter(site);
  for (const f of files) {
    const top = f.segments[0], isFile = f.segments.length === 1;
    if (top.startsWith('.')) continue; // .git/, .vscode/, .gitignore beside the hand-ins: nobody's
    const id = adapter.parseTopName(top, isFile);
    if (!id) {
      if (!(adapter.siteFile && isFile && adapter.siteFile.test(top))) notes.push(`left out "${top}": ${adapter.leftOut}`);
      continue;
    }
    if (id.plugin && id.plugin !== 'file') continue; // Moodle's online text and comments: not files handed in
    const user = id.userId ?? `folder:${top}`;
    if (!byUser.has(user)) byUser.set(user, new Map());
    const subs = byUser.get(user);
    const subKey = `${id.submissionId}|${id.time}|${adapter.fallback ? top : ''}`;
    if (!subs.has(subKey)) {
      subs.set(subKey, {
        identity: {
          site,
          name: id.name,
          userId: id.userId,
          submissionId: id.submissionId,
          time: id.time,
          late: id.late,
          source: [],
          ...(id.fileId ? { fileIds: [] } : {}),
        },
        files: [],
      });
    }
    const sub = subs.get(subKey);
    const source = isFile ? top : `${top}/`;
    if (!sub.identity.source.includes(source)) sub.identity.source.push(source);
    if (id.fileId && !sub.identity.fileIds.includes(id.fileId)) sub.identity.fileIds.push(id.fileId);
    sub.files.push({ ...f, segments: isFile ? [id.rest] : f.segments.slice(1) });
  }
  const students = [];
  for (const subs of byUser.values()) {
    // the latest first: by time, then by submission id (a later submission has a larger id)
    const order = [...subs.values()].sort(
      (a, b) =>
        String(b.identity.time).localeCompare(String(a.identity.time)) ||
        Number(b.identity.submissionId) - Number(a.identity.submissionId),
    );
    const [latest, ...rest] = order;
    students.push({
      ...latest,
      earlier: rest.map((s) => ({
        time: s.identity.time,
        late: s.identity.late,
        submissionId: s.identity.submissionId,
        source: s.identity.source,
        files: s.files.length,
      })),
    });
  }
  return { site, students, notes };
}
