// The class page: a teacher drops the course site's download (its .zip or its folder) and, with
// nothing installed, gets what `npm run grade -- --batch` gives: each student's parts graded by the
// grader's own modules in frames of this page (grade/class-run.js), a grid of verdicts and reasons,
// and one zip of the report, the grade files and the feedback (grade/results.js). When every part
// has its verdict: window.grading = { done: true, students: [{ name, parts: [{ part, verdict, reasons }] }] }.
import { IntakeError, folderListing, takeInClass, takeInZip } from './intake.js';
import { gradeStudent } from './class-run.js';
import { classFiles, gradingOf, writeInto, zipOf } from './results.js';
import { startHost, unsupported } from '../check/host.js';
import { frameScript as makeFrameScript } from '../check/runner.js';
import { hasWebGPU } from '../check/not-checked.js';
import { dropBox, el } from '../check/dom.js';
import { entriesFromDrop } from '../check/files.js';
import { dueTime } from '../grader/class/intake/formats.js';
import { PARTS } from '../grader/core/part-names.js';
import { MS_PER_SECOND } from '../grader/core/units.js';
import { matchRoster, parseRoster } from '../grader/class/roster.js';
import { OVERRIDES_FILE, applyOverrides, overridesText } from '../grader/class/overrides.js';
import { gridOf } from './grid.js';
import { beginPart, classKey, keepOverrides, keepStudent, keptOverrides, keptStudents } from './store.js';

const $ = (id) => document.getElementById(id);
window.grading = { done: false, students: [] };
let busy = false;
// ?reference=0 leaves out our step beside each part (a quicker run)
const REFERENCE = new URLSearchParams(location.search).get('reference') !== '0';
/** The most hand-ins graded at once. */
const MOST_WORKERS = 8;
$('workers').value = String(Math.max(1, Math.min(MOST_WORKERS, Math.floor((navigator.hardwareConcurrency || 2) / 2))));

function say(text, kind = 'error') {
  $('messages').replaceChildren(el('p', { className: kind, textContent: text }));
}

/** The browser grading, as the report names it ("Chrome 131", "Firefox 128"), from its user agent. */
function browserName() {
  const ua = navigator.userAgent;
  const m = /(Firefox|Edg|Chrome)\/([\d.]+)/.exec(ua);
  if (!m) return 'this browser';
  return `${m[1] === 'Edg' ? 'Edge' : m[1]} ${m[2]} (the class page)`;
}

const clock = (s) => `${Math.floor(s / 60)}:${String(Math.floor(s % 60)).padStart(2, '0')}`;

/**
 * The download as picked or dropped: a .zip (its bytes) or a folder ([{ path, bytes }]), taken in:
 * { got (take-in's), bytes (what the class's key is made of: the zip, or each file's path and bytes) }.
 */
async function takeIn(input, rubric, due) {
  if (input.zip) {
    const bytes = new Uint8Array(await input.zip.arrayBuffer());
    return { got: takeInZip(bytes, input.zip.name, rubric.unpack, due), bytes: [bytes] };
  }
  const read = async (f) => ({ path: f.path, bytes: new Uint8Array(await f.blob.arrayBuffer()) });
  const byPath = (a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0);
  const entries = (await Promise.all(input.folder.map(read))).sort(byPath);
  const name = entries.length ? entries[0].path.split('/')[0] : 'the folder';
  const got = takeInClass(folderListing(entries), name, rubric.unpack, due);
  return { got, bytes: entries.flatMap((e) => [new TextEncoder().encode(`\n${e.path}\n`), e.bytes]) };
}

/** The hrefs and data: URLs of the pictures `rows` name. */
const picturesOf = (rows, pictures) => rows.flatMap((r) => Object.values(r.images || {}))
  .filter((h) => pictures.has(h)).map((h) => [h, pictures.get(h)]);

/**
 * Grades `students` (take-in's submissions), `workers` at once, each in a frame stage of its own;
 * each part's row shown as it ends (`show`) and the progress line kept; `pictures` (Map href → data:
 * URL) gets each part's pictures. Returns Map name → rows.
 */
async function gradeAll(students, { rubric, workers, show, started, key, pictures }) {
  const why = unsupported();
  if (why) throw new IntakeError(why);
  await startHost();
  const webgpuHere = await hasWebGPU();
  const frameScript = makeFrameScript(rubric), browserVersion = browserName();
  const all = students.length * PARTS.length;
  let done = 0, finished = 0;
  const line = (what = '') => {
    const s = (performance.now() - started) / MS_PER_SECOND;
    const left = done ? clock((s / done) * (all - done)) : '…';
    $('progress').textContent = `${done} of ${all} parts, ${finished} of ${students.length} hand-ins · ${clock(s)} so far · about ${left} left${what ? ` · ${what}` : ''}`;
  };
  const graded = new Map();
  // the hand-ins graded before a reload (kept in the browser: store.js) are not graded again
  const kept = await keptStudents(key);
  for (const s of students.filter((x) => kept.has(x.name))) {
    const { rows, pictures: theirs } = kept.get(s.name);
    for (const [href, url] of theirs) pictures.set(href, url);
    for (const r of rows) { show(r); done++; }
    graded.set(s.name, rows);
    finished++;
  }
  window.grading.resumed = [...graded.keys()];
  window.grading.gradedHere = [];
  window.grading.begun = [];
  const queue = students.filter((x) => !kept.has(x.name));
  $('stages').replaceChildren(...Array.from({ length: workers }, () => el('div', { className: 'stage' })));
  const work = async (stage) => {
    for (let s = queue.shift(); s; s = queue.shift()) {
      const progress = (part, what) => line(`${s.name} ${part}: ${what}`);
      const begin = (part) => {
        window.grading.begun.push(`${s.name} ${part}`);
        return beginPart(key, s.name, part);
      };
      const rows = await gradeStudent({ student: s, rubric, frameScript, stage, pictures, browserVersion, webgpuHere,
        reference: REFERENCE, progress, begin });
      for (const r of rows) { show(r); done++; }
      graded.set(s.name, rows);
      await keepStudent(key, s.name, rows, picturesOf(rows, pictures));
      window.grading.gradedHere.push(s.name);
      finished++;
      line();
    }
  };
  try {
    await Promise.all([...$('stages').children].map(work));
  } finally {
    $('stages').replaceChildren();
  }
  return graded;
}

/** The teacher's verdicts set in the grid: Map "name\npart" → { student, part, verdict, note }. */
const overrides = new Map();
/** The class graded last, to make its files again when the teacher sets a verdict: { got, students, graded, pictures, rubric, roster }. */
let last = null;

/**
 * The class's files made (grade/results.js) with the teacher's verdicts applied and offered as one
 * zip (overrides.tsv in it, for the command's --report-only); window.grading says the verdicts.
 */
function giveBack({ got, students, graded, pictures, rubric, roster }) {
  const submissions = students.map((s) => ({
    name: s.name, parts: structuredClone(graded.get(s.name)), identity: { ...s.identity },
    earlier: s.earlier, intakeNotes: s.notes,
  }));
  const unmatched = roster ? matchRoster(submissions, roster) : [];
  if (unmatched.length) say(`Not in the class list: ${unmatched.join(', ')}`, 'notice');
  const set = [...overrides.values()].map((o, k) => ({ ...o, line: k + 2 }));
  applyOverrides(submissions, set);
  const { made, files } = classFiles(submissions, { site: got.site, rubric, pictures });
  if (set.length) files[OVERRIDES_FILE] = overridesText(set);
  const old = $('download').querySelector('a');
  if (old) URL.revokeObjectURL(old.href);
  const url = URL.createObjectURL(new Blob([zipOf(files)], { type: 'application/zip' }));
  $('download').replaceChildren(
    el('a', { className: 'download', href: url, download: `results-${got.site}.zip`, textContent: 'Download the results (zip)' }),
    ` · the report, ${made.gradeFiles.join(', ')}, ${made.feedbackPages.length} feedback page(s) and ${made.feedbackZip}` +
    `${set.length ? `, with ${set.length} verdict(s) set by you` : ''}`, folderButton(files));
  const verdicts = gradingOf(made.rows);
  window.grading = { ...window.grading, done: true, site: got.site, students: verdicts, files: Object.keys(files) };
}

/** Where the browser can write into a folder the teacher picks (File System Access: Chromium), a button that writes `files` there. */
function folderButton(files) {
  if (!('showDirectoryPicker' in window)) return null;
  const button = el('button', { type: 'button', textContent: 'Write them into a folder…' });
  button.addEventListener('click', async () => {
    let dir;
    try {
      dir = await window.showDirectoryPicker({ mode: 'readwrite', id: 'grade-results' });
    } catch {
      return; // (the teacher closed the picker)
    }
    try {
      const n = await writeInto(dir, files);
      say(`Wrote ${n} files into the folder "${dir.name}", as npm run grade writes its out folder.`, 'notice');
      window.grading.written = n;
    } catch (err) {
      say(`The results could not be written into "${dir.name}" (${err.message}): download the zip instead.`);
    }
  });
  return el('span', {}, ' ', button);
}

/** The teacher sets (or, with null, clears) the verdict of `name`'s `part`: shown, and the results made again. */
function override(grid, name, part, o) {
  if (o) overrides.set(`${name}\n${part}`, { student: name, part, ...o });
  else overrides.delete(`${name}\n${part}`);
  grid.teacher(name, part, o);
  if (last) keepOverrides(last.key, [...overrides.values()]);
  if (last && last.graded) giveBack(last);
}

async function run(input) {
  if (busy) return say('A class is being graded: wait for it to finish (or reload the page to stop it).', 'notice');
  busy = true;
  window.grading = { done: false, students: [] };
  $('messages').replaceChildren();
  $('results').replaceChildren();
  $('download').replaceChildren();
  const started = performance.now();
  try {
    const rubricText = await (await fetch(new URL('../grader/core/rubric.json', import.meta.url))).text();
    const rubric = JSON.parse(rubricText);
    $('progress').textContent = 'reading the download…';
    const due = $('due').value ? dueTime($('due').value) : null;
    const { got, bytes } = await takeIn(await input(), rubric, due);
    const key = await classKey(bytes, `${rubricText}\nreference=${REFERENCE}\ndue=${due}`);
    const roster = $('roster').files[0] ? parseRoster(await $('roster').files[0].text()) : null;
    for (const n of got.notes) $('messages').append(el('p', { className: 'notice', textContent: n }));
    const students = got.submissions;
    if (!students.length) throw new IntakeError('The download has no hand-ins.');
    overrides.clear();
    last = { key };
    const pictures = new Map();
    for (const o of await keptOverrides(key)) overrides.set(`${o.student}\n${o.part}`, o);
    const pictureOf = (href) => pictures.get(href) ?? null;
    const grid = gridOf(students, (name, part, o) => override(grid, name, part, o), pictureOf);
    const { table, show } = grid;
    const failed = students.filter((s) => s.error).length;
    $('results').append(el('p', { textContent: `Found ${got.found}: ${students.length} hand-in(s)${failed ? `; ${failed} could not be unpacked` : ''}.` }), table);
    const workers = Math.max(1, Math.min(MOST_WORKERS, Number($('workers').value) || 1));
    for (const o of overrides.values()) grid.teacher(o.student, o.part, o);
    const graded = await gradeAll(students, { rubric, workers, show, started, key, pictures });
    $('progress').textContent = `done in ${clock((performance.now() - started) / MS_PER_SECOND)}: ${students.length * PARTS.length} parts of ${students.length} hand-ins`;
    last = { key, got, students, graded, pictures, rubric, roster };
    giveBack(last);
  } catch (err) {
    $('progress').textContent = '';
    say(err instanceof IntakeError ? err.message : `The grading stopped: ${err.message}. Reload the page and try again.`);
    window.grading = { done: true, students: [], error: err.message };
  } finally {
    busy = false;
  }
}

$('zip').addEventListener('change', (e) => {
  const [file] = e.target.files;
  if (file) run(async () => ({ zip: file }));
  e.target.value = '';
});
$('folder').addEventListener('change', (e) => {
  const list = [...e.target.files].map((f) => ({ path: f.webkitRelativePath || f.name, blob: f }));
  if (list.length) run(async () => ({ folder: list }));
  e.target.value = '';
});
/** The most files of a dropped folder read (a class of 300 at the rubric's 2000 files each is far less). */
const MOST_DROPPED = 200000;
dropBox($('drop'), (items) => {
  const [file] = items.files;
  if (items.files.length === 1 && /\.zip$/i.test(file.name)) { run(async () => ({ zip: file })); return; }
  // the entries must be read while the drop event lasts
  const gathered = entriesFromDrop(items, { most: MOST_DROPPED, zip: false });
  run(async () => {
    const folder = await gathered;
    if (folder.length > MOST_DROPPED) throw new IntakeError(`More than ${MOST_DROPPED} files were dropped: drop the download's .zip, or its own folder.`);
    return { folder };
  });
});
