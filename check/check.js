// The self-check page: a student picks or drops a worksheet folder (or its .zip) and sees, part
// by part, what `npm run grade` would say: the verdict, the reasons, the pictures, what was
// clicked, and for a review or a fail the slide's sentence the part misses. The files stay in the
// browser (check/files.js reads them, check/host.js serves them to the frames through
// check/sw.js); each part is checked by check/runner.js with the grader's own modules. When all
// parts have their verdicts: window.check = { done: true, parts: [{ part, verdict, reasons, api }] }.
import { CheckInputError, entriesFromDrop, entriesFromInput, handInFrom, partsOfHandIn, titlesOfHandIn } from './files.js';
import { openSession, startHost, unsupported } from './host.js';
import { checkPart, drawReference, frameScript } from './runner.js';
import { handInSource } from './serve.js';
import { missedSlides, stepLink } from './slides.js';
import { AUDITS } from '../grader/core/audits/index.js';
import { NOT_CHECKED, NO_WEBGPU_HERE, hasWebGPU } from './not-checked.js';
import { dropBox, el, pngURL } from './dom.js';
import { PARTS } from '../grader/core/part-names.js';
import { withFindings, findingsOfResult } from '../grader/core/part-result.js';
import { missingPage } from '../grader/core/audits/page.js';
import { MS_PER_SECOND } from '../grader/core/units.js';
import { NOT_GRADED } from '../grader/core/verdict.js';

const $ = (id) => document.getElementById(id);
window.check = { done: false, parts: [] };
let busy = false;
// ?reference=0 leaves out our step beside each part (a quicker run, for comparing many hand-ins)
const REFERENCE = new URLSearchParams(location.search).get('reference') !== '0';

function say(text, kind = 'error') {
  $('messages').replaceChildren(el('p', { className: kind, textContent: text }));
}

const CAPTIONS = { first: 'first frame', coarse: 'a coarse level', judged: 'judged', leastS: 's at its least', reference: 'our step, same size and light' };

const BADGES = { [NOT_CHECKED]: 'not checked here' };

/** A reason's audit in words, for its id's tooltip: what it checks, titled as passed or as missed (its failureTitle). */
function auditTooltip(f) {
  const a = AUDITS[f.id];
  if (!a) return '';
  return `${f.level === 'fail' || f.level === 'review' ? a.failureTitle : a.title}: ${a.description}`;
}

function card(r, index, total, file) {
  const findings = findingsOfResult(r);
  const slides = r.verdict === 'pass' || r.verdict === NOT_CHECKED || r.verdict === NOT_GRADED ? [] : missedSlides(findings);
  const list = (title, items) => (items && items.length ? el('details', {}, el('summary', { textContent: `${title} (${items.length})` }),
    el('ul', {}, ...items.map((t) => el('li', { textContent: t })))) : null);
  const images = Object.entries(r.images || {}).filter(([k, im]) => CAPTIONS[k] && im && im.data);
  // (no verdict here, the check's or the grader's own: grey)
  const kind = r.verdict === NOT_CHECKED || r.verdict === NOT_GRADED ? 'unchecked' : r.verdict;
  return el('article', { className: `card ${kind}`, id: `card-${r.part}` },
    el('h2', {}, el('span', { textContent: r.part }), el('span', { className: `badge ${kind}`, textContent: BADGES[r.verdict] || r.verdict }),
      el('small', { textContent: `${file || 'not found'}${r.api ? ` · ${r.api}` : ''}${r.seconds ? ` · ${r.seconds.toFixed(0)} s` : ''} · part ${index + 1} of ${total}` })),
    // each reason with its audit's id (the grader's README lists them, with the sentence each checks)
    el('ul', { className: 'reasons' }, ...findings.map((f) => el('li', { dataset: { audit: f.id || '' } }, `${f.reason} `,
      f.id ? el('code', { className: 'audit', textContent: f.id, title: auditTooltip(f) }) : null))),
    ...slides.map((s) => el('p', { className: 'slide', dataset: { audit: s.id } }, el('b', { textContent: 'The slide asks: ' }), `${s.slide} `,
      s.note ? el('i', { textContent: `(${s.note}) ` }) : null, el('a', { href: stepLink(r.part), textContent: `See our ${r.part}` }))),
    images.length ? el('div', { className: 'pictures' }, ...images.map(([k, im]) => el('figure', {},
        el('img', { src: pngURL(im), alt: `${r.part}: ${CAPTIONS[k]}`, width: im.width, height: im.height }),
        el('figcaption', { textContent: CAPTIONS[k] })))) : null,
    el('p', {}, el('a', { href: stepLink(r.part), textContent: `Our ${r.part}, which does it as the slide asks` })),
    list('What the check did', r.actions),
    list('Errors the page printed or caused', r.errors),
    list('Blocked (other hosts, popups)', r.blocked),
    list('Notes', r.notes));
}

async function run(gather) {
  if (busy) return say('A check is running: wait for it to finish (or reload the page to stop it).', 'notice');
  busy = true;
  window.check = { done: false, parts: [] };
  $('messages').replaceChildren();
  $('results').replaceChildren();
  const started = performance.now();
  try {
    const why = unsupported();
    if (why) throw new CheckInputError(why);
    $('progress').textContent = 'reading your files…';
    const files = handInFrom(await gather());
    const { parts, notes } = partsOfHandIn(files, await titlesOfHandIn(files));
    const webgpuHere = await hasWebGPU();
    await startHost().catch((err) => {
      throw new CheckInputError(`This browser would not start the service worker the self-check needs to show your pages to the grader (${err.message}). ` +
        'Service workers may be off in a private window or by a setting: try a normal window of a current Chrome, Edge or Firefox.');
    });
    const rubric = await (await fetch(new URL('../grader/core/rubric.json', import.meta.url))).json();
    const session = openSession(handInSource(files), frameScript(rubric), rubric.loadSeconds);
    const results = [];
    try {
      for (const [k, part] of PARTS.entries()) {
        const file = parts[part];
        const where = `part ${k + 1} of ${PARTS.length}: ${part}${file ? ` (${file})` : ''}`;
        $('progress').textContent = where;
        const progress = (what) => { $('progress').textContent = `${where}: ${what}`; };
        const r = file ? await checkPart({ part, page: file, session, rubric, stage: $('stage'), webgpuHere, progress })
          : withFindings({ part, verdict: 'fail', api: null }, [missingPage(part)]);
        // said once, at the top: the browser, not the student's work
        if (r.notChecked === 'webgpu' && !results.some((x) => x.notChecked === 'webgpu')) say(NO_WEBGPU_HERE, 'notice');
        if (file && REFERENCE && r.verdict !== NOT_CHECKED) {
          $('progress').textContent = `${where}: drawing our ${part} beside it`;
          let reference = null;
          try {
            reference = drawReference({ result: r, rubric });
          } catch {
            // (no reference beside it: the check goes on)
          }
          if (reference) r.images.reference = reference;
        }
        if (notes[part]) (r.notes || (r.notes = [])).unshift(notes[part]);
        results.push(r);
        $('results').append(card(r, k, PARTS.length, file));
        session.clearLog();
      }
    } finally {
      session.close();
      $('stage').replaceChildren();
    }
    const passes = results.filter((r) => r.verdict === 'pass').length;
    const unchecked = results.filter((r) => r.verdict === NOT_CHECKED).length;
    $('progress').textContent = `done in ${((performance.now() - started) / MS_PER_SECOND).toFixed(0)} s: ${passes} of ${PARTS.length} parts pass` +
      `${unchecked ? `, ${unchecked} not checked here` : ''}`;
    window.check = {
      done: true,
      parts: results.map(({ part, verdict, reasons, findings, api }) => ({ part, verdict, reasons, findings, api })),
    };
  } catch (err) {
    $('progress').textContent = '';
    say(err instanceof CheckInputError ? err.message : `The check stopped: ${err.message}. Reload the page and try again; if it happens again, tell your teacher.`);
    window.check = { done: true, parts: [], error: err.message };
  } finally {
    busy = false;
  }
}

$('folder').addEventListener('change', (e) => {
  const list = [...e.target.files];
  if (list.length) run(() => entriesFromInput(list));
  e.target.value = '';
});
$('zip').addEventListener('change', (e) => {
  const list = [...e.target.files];
  const notZip = () => Promise.reject(new CheckInputError(`${list[0].name} is not a .zip: pick the folder above instead.`));
  if (list.length) run(() => (/\.zip$/i.test(list[0].name) ? entriesFromInput(list) : notZip()));
  e.target.value = '';
});
dropBox($('drop'), (items) => {
  const gathered = entriesFromDrop(items); // the entries must be read while the drop event lasts
  run(() => gathered);
});
const why = unsupported();
if (why) say(why);
