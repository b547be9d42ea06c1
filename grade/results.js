// What the class page gives back: every file of the graded class as the command writes it into its
// out folder (grader/class/outputs.js: report.json, report.html, grades.csv, grades-points.csv, the
// course site's import file, each feedback page, the feedback zip) and the pictures the report
// shows, in one zip ("Download the results"), and what the page publishes as window.grading.
import { zipSync } from 'fflate';
import { classOutputs } from '../grader/class/outputs.js';

/** A data: URL's bytes. */
function bytesOfDataURL(url) {
  const b64 = url.slice(url.indexOf(',') + 1);
  const s = atob(b64);
  const out = new Uint8Array(s.length);
  for (let k = 0; k < s.length; k++) out[k] = s.charCodeAt(k);
  return out;
}

/**
 * The class's files: classOutputs' (`submissions`: [{ name, parts: rows, identity, earlier,
 * intakeNotes }], `site`, `rubric`) with `pictures` (Map href → data: URL). Returns { made
 * (classOutputs' result), files: { path: text | bytes }, pictures included }.
 */
export function classFiles(submissions, { site, rubric, pictures, generated = new Date().toISOString() }) {
  const pictureOf = (href) => pictures.get(href) ?? null;
  const made = classOutputs(submissions, { aClass: true, site, rubric, generated, pictureOf });
  const files = { ...made.files };
  for (const [href, url] of pictures) files[href] = bytesOfDataURL(url);
  return { made, files };
}

/** `files` ({ path: text | bytes }) as one zip's bytes, the pictures stored as they are (PNG is compressed). */
export function zipOf(files) {
  const entries = {};
  for (const [p, data] of Object.entries(files)) {
    const bytes = typeof data === 'string' ? new TextEncoder().encode(data) : data;
    entries[p] = /\.(png|zip)$/i.test(p) ? [bytes, { level: 0 }] : bytes;
  }
  return zipSync(entries);
}

/** window.grading's students: the names as the report gives them, each part's verdict and reasons. */
export function gradingOf(rows) {
  const partOf = ({ part, verdict, reasons }) => ({ part, verdict, reasons });
  return rows.map((s) => ({ name: s.name, parts: s.parts.map(partOf) }));
}

/**
 * Writes `files` ({ path: text | bytes }) into the folder `dir` (a FileSystemDirectoryHandle the
 * teacher picked), as the command writes its out folder: folders made as the paths need, feedback/
 * made anew (a student no longer in the class leaves no page behind). Returns how many were written.
 */
export async function writeInto(dir, files) {
  await dir.removeEntry('feedback', { recursive: true }).catch(() => {}); // (not there yet: nothing to remove)
  let n = 0;
  for (const [p, data] of Object.entries(files)) {
    const segments = p.split('/');
    let folder = dir;
    for (const s of segments.slice(0, -1)) folder = await folder.getDirectoryHandle(s, { create: true });
    const handle = await folder.getFileHandle(segments[segments.length - 1], { create: true });
    const out = await handle.createWritable();
    await out.write(data);
    await out.close();
    n++;
  }
  return n;
}
