// One student of the class graded in the class page, as `npm run grade -- --batch` grades them:
// the parts found by the grader's names (check/files.js, grader/core/part-names.js), a page that
// only links to another part's page graded once (grader/class/linked-part.js), each part in a frame
// of its own with the grader's modules (check/runner.js), our reference beside it
// (grader/class/beside-ours.js), and each part's row in the command's form (grader/class/part-rows.js),
// its pictures kept here as PNG data: URLs under the names the command's out folder gives them.
import { partsOfHandIn, titlesOfHandIn } from '../check/files.js';
import { openSession } from '../check/host.js';
import { checkPart } from '../check/runner.js';
import { handInSource } from '../check/serve.js';
import { NOT_CHECKED } from '../check/not-checked.js';
import { PARTS } from '../grader/core/part-names.js';
import { NOT_GRADED } from '../grader/core/verdict.js';
import { withFindings } from '../grader/core/part-result.js';
import { linkedPage } from '../grader/core/audits/page.js';
import { beside } from '../grader/class/beside-ours.js';
import { linkedPart, POSIX_PATHS } from '../grader/class/linked-part.js';
import { missingRow, notUnpackedRow, partRow } from '../grader/class/part-rows.js';
import { safeName } from '../grader/files/safe-name.js';
import { pngURL } from '../check/dom.js';

/** A verdict the check page gives for want of WebGPU (or its own trouble), in the command's words: not graded here. */
function asNotGraded(r) {
  if (r.verdict !== NOT_CHECKED) return r;
  const findings = r.findings.map((f) => (f.level === NOT_CHECKED
    ? { ...f, level: NOT_GRADED, reason: f.reason.replace(/^not checked here/, NOT_GRADED) } : f));
  return { ...withFindings(r, findings), verdict: NOT_GRADED, status: NOT_GRADED };
}

/** The row of part `part` of student `name`, whose page `page` was graded: `r` (check/runner.js's result), `notes` first. */
function gradedRow(name, part, page, r, { notes, browserVersion }) {
  return partRow(name, part, page, {
    status: r.status, verdict: r.verdict, api: r.api, reasons: r.reasons, findings: r.findings,
    actions: r.actions, controls: r.controls, numbers: r.numbers, pass: r.verdict === 'pass',
    notes: [...notes, ...r.notes], errors: r.errors, blocked: r.blocked, images: {},
    ...(browserVersion ? { browserVersion } : {}), canvas: r.canvas, seconds: r.seconds,
  });
}

/** The parts found in `files` (Map path → Blob) as the grader finds them: { parts, notes } (none where no page is named for a part). */
async function partsOf(files) {
  try {
    return partsOfHandIn(files, await titlesOfHandIn(files));
  } catch {
    return { parts: {}, notes: {} }; // (every part is missing, as the command finds it)
  }
}

/** How often a part may take the page down (a renderer that crashed, a tab closed while it ran) before it is not graded here. */
export const MOST_LOST = 2;

/** The row of a part that took the page down MOST_LOST times: not graded here, and why. */
function lostRow(name, part, page) {
  const reason = `${NOT_GRADED}: the page was lost ${MOST_LOST} times while this part was graded (its page crashed the browser's renderer, ` +
    'or the tab was closed or reloaded then), so the class page went on without it: grade it with npm run grade, or look at it yourself';
  const row = partRow(name, part, page, { status: NOT_GRADED, verdict: NOT_GRADED });
  return withFindings(row, [{ id: 'browser-failed', level: NOT_GRADED, reason }]);
}

/**
 * The parts of `student` (take-in's submission with its handIn: Map path → bytes) graded: their
 * rows, in PARTS' order. `pictures` (Map href → data: URL) gets every picture a row names.
 * `stage`: the element the frames open in; `progress(part, what)`; `browserVersion`: the browser's
 * name and version, as the report names it; `webgpuHere`: this browser has a WebGPU adapter;
 * `begin(part)`: records that the part is begun and says how often it was begun before and lost.
 */
export async function gradeStudent(o) {
  const { student, rubric, frameScript, stage, pictures, progress = () => {}, webgpuHere = true, reference = true } = o;
  const begin = o.begin || (async () => 0);
  const { name } = student;
  if (student.error) return PARTS.map((part) => notUnpackedRow(name, part, student.error));
  const files = new Map([...student.handIn].map(([p, bytes]) => [p, new Blob([bytes])]));
  const found = await partsOf(files);
  const rows = [];
  const session = openSession(handInSource(files), frameScript, rubric.loadSeconds);
  try {
    for (const part of PARTS) {
      const page = found.parts[part] || null;
      const notes = found.notes[part] ? [found.notes[part]] : [];
      if (!page) { rows.push(missingRow(name, part, notes)); continue; }
      const linksTo = linkedPart(await files.get(page).text(), page, found.parts, { pathImpl: POSIX_PATHS });
      if (linksTo) {
        const linked = partRow(name, part, page, { status: 'linked', verdict: 'review', notes });
        rows.push(withFindings(linked, [linkedPage(part, page, linksTo)]));
        continue;
      }
      if ((await begin(part)) >= MOST_LOST) { rows.push(lostRow(name, part, page)); continue; }
      session.clearLog();
      const told = (what) => progress(part, what);
      const args = { part, page, session, rubric, stage, webgpuHere, progress: told, graderWords: true };
      const r = asNotGraded(await checkPart(args));
      const row = gradedRow(name, part, page, r, { notes, browserVersion: o.browserVersion });
      // each picture kept under the name the command's out folder gives it
      const keep = (href, img) => {
        pictures.set(href, pngURL(img));
        return href;
      };
      for (const [key, img] of Object.entries(r.images)) {
        if (img && img.data) row.images[key] = keep(`artifacts/${safeName(name)}/${part}/${key}.png`, img);
      }
      if (reference && r.images.judged && r.verdict !== 'fail' && r.verdict !== NOT_GRADED) {
        progress(part, 'drawing our reference beside it');
        const query = (rubric.parts[part] || {}).referenceQuery;
        beside(row, { part, judged: r.images.judged, numbers: r.numbers, rubric, query },
          (ours, img) => keep(`parts/${safeName(name)}/${part}-${ours}.png`, img));
      }
      rows.push(row);
    }
  } finally {
    session.close();
  }
  return rows;
}
