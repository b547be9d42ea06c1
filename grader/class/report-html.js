// report.html, the page a teacher reads: the class grid (a row a submission, a cell a part, sortable),
// the agreement with the labels, the similarity and the item analysis, then each part's reasons,
// pictures and numbers. Plain strings from the rows report.js sorts; every value from a hand-in escaped.
import { PARTS } from '../core/part-names.js';
import { safeName } from '../files/safe-name.js';
import { agreementHtml } from './labels.js';
import { NOT_GRADED } from '../core/verdict.js';
import { findingsOfResult } from '../core/part-result.js';
import { similarityBadges, similarityHtml, SIMILARITY_CSS } from '../similarity/report.js';
import { identityHtml, teacherMark, TEACHER_CSS } from './report-teacher.js';
import { itemAnalysisHtml } from './item-analysis.js';
import { PERCENT, CHANNEL_MAX } from '../core/units.js';
import { esc } from '../files/html.js';

const VERDICTS = ['pass', 'review', 'fail'];
/** A verdict's class name ("not graded here": not-graded). */
const cls = (v) => (v === NOT_GRADED ? 'not-graded' : v || 'fail');
const badge = (v) => `<span class="badge ${esc(cls(v))}">${esc(v || 'fail')}</span>`;

const CSS = [
  'body{font-family:system-ui,sans-serif;margin:1rem 2rem;color:#1d2330}table{border-collapse:collapse}' +
  'td,th{border:1px solid #ccd;padding:.2rem .4rem;vertical-align:top}',
  'th[data-sort]{cursor:pointer;text-decoration:underline dotted}.num{text-align:right}' +
  '.cell a{color:inherit;text-decoration:none;display:block}',
  '.cell.pass{background:#e3f6e3}.cell.review{background:#fff4d6}.cell.fail{background:#fde4e4}',
  '.badge{display:inline-block;padding:0 .4rem;border-radius:.6rem;font-size:.8rem;font-weight:600;color:#fff}' +
  '.badge.pass{background:#2a7d2a}.badge.review{background:#a66b00}.badge.fail{background:#b3261e}' +
  '.badge.not-graded{background:#667}',
  '.api{color:#556;font-size:.75rem;margin-left:.3rem}.thumbs{display:flex;gap:2px;margin-top:2px}' +
  '.thumbs img{width:64px;height:64px;object-fit:contain;border:1px solid #ccd;background:#fff}',
  '.images{display:flex;gap:.8rem;flex-wrap:wrap}figure{margin:0}' +
  'figure img{max-width:260px;border:1px solid #ccd;image-rendering:pixelated}',
  '.errors li{color:#a00}.confusion td.agree{background:#e3f6e3;font-weight:600}' +
  '.file{color:#556;font-family:monospace}' +
  'code.audit{font-size:.75rem;color:#556;background:#eef0f4;padding:0 .25rem;border-radius:.2rem}' +
  '.part{border-top:1px solid #dde;padding:.3rem 0}'
].join('\n');

/** What the grader did, said above the grid. */
const INTRO = [
  '<h1>Grading report</h1><p>Each part was opened in Chromium (WebGL, or WebGPU on SwiftShader with its frames read back), or with',
  '--browser firefox in Firefox ESR (WebGL; a WebGPU part is not graded there), with time frozen. The grader found its controls, stopped or sampled the orbit, coarsened and subdivided until the silhouette stopped',
  'changing, and judged the picture by what the slide\'s step asks for (a round sphere; normals as colours; diffuse shading for a',
  'fitted light; a highlight; sliders on the input event; shading per fragment). Verdicts: pass, review (a teacher should look),',
  'fail. Click a cell for its reasons and pictures; click a column head to sort.</p>'
].join('\n');

// a part's pictures, in the order they are shown, with their captions
const PICTURES = [
  'first', 'coarse', 'highlightPlace', 'leastS',
  'unclipped', 'brightened', 'allRoundGap', 'shownFirst',
  'shownLast', 'judged', 'reference', 'diff',
];
const CAPTIONS = {
  first: 'first frame',
  coarse: 'a coarse level',
  highlightPlace: 'the highlight, the light away from the viewer',
  leastS: 's at its least',
  unclipped: 'its own sliders lowered (it clipped to white)',
  brightened: 'its own light raised (it was too dim)',
  allRoundGap: 'from another side along the orbit: a hole',
  shownFirst: 'first frame, as the browser shows it',
  shownLast: 'at the end, as the browser shows it',
  judged: 'judged (submission)',
  reference: 'our reference',
  diff: 'difference',
};

/** Sorts the grid by the column head clicked (again: the other way). */
const SORT_SCRIPT = `<script>
for (const th of document.querySelectorAll('#grid thead th[data-sort]')) th.addEventListener('click', () => {
  const k = th.dataset.sort, body = document.querySelector('#grid tbody'), desc = th.dataset.desc = th.dataset.desc === '1' ? '0' : '1';
  const key = (tr) => k === 'name' ? tr.dataset.name : k === 'passes' ? -Number(tr.dataset.passes) : Number(tr.children[Number(k)].dataset.verdict);
  [...body.rows].sort((a, b) => { const x = key(a), y = key(b); const c = x < y ? -1 : x > y ? 1 : 0; return desc === '1' ? c : -c; }).forEach((tr) => body.append(tr));
});
</script>`;

// (a picture's path is relative to the report: the artifact's files, our reference in parts/)
const img = (r, k) =>
  r.images && r.images[k] ? `<img src="${esc(r.images[k])}" alt="${esc(`${r.part} ${k}`)}" loading="lazy">` : '';
const anchor = (s, r) => `${safeName(s.name)}-${r.part}`;
const list = (title, items, kind) =>
  items && items.length ? `<p>${title}</p><ul class="${kind}">${items.map((e) => `<li>${esc(e)}</li>`).join('')}</ul>` : '';

/** A submission's row of the grid: its name, its passes, a cell a part with its verdict and thumbnails. */
function gridRow(s, similar) {
  const name = `<a href="#${esc(safeName(s.name))}">${esc(s.name)}</a>${similar ? similarityBadges(similar, s.name) : ''}`;
  const cells = PARTS.map((p) => {
    const r = s.parts.find((x) => x.part === p);
    const order = r.verdict === NOT_GRADED ? VERDICTS.length : VERDICTS.indexOf(r.verdict);
    return `<td class="cell ${esc(cls(r.verdict))}" data-verdict="${order}"><a href="#${esc(anchor(s, r))}">${badge(r.verdict)}` +
      `${teacherMark(r)}<span class="api">${esc(r.api || '')}</span>` +
      `<span class="thumbs">${img(r, 'first')}${img(r, 'judged')}</span></a></td>`;
  });
  const head = `<tr data-name="${esc(s.name)}" data-passes="${s.passes}"><th scope="row">${name}</th>`;
  return `${head}<td class="num">${s.passes}</td>${cells.join('')}</tr>`;
}

/** A part's heading: its verdict, the teacher's mark, the API and browser, its status and seconds. */
function partHeading(r) {
  const browser = r.browserVersion || r.browser ? ` in ${esc(r.browserVersion || r.browser)}` : '';
  const seconds = r.seconds ? ` · ${r.seconds.toFixed(0)} s` : '';
  const small = `<small>${esc(r.api || 'no API')}${browser} · ${esc(r.status)}${seconds}</small>`;
  return `<h3>${r.part} ${badge(r.verdict)}${teacherMark(r, true)} ${small}</h3>`;
}

/** Each reason with its audit's id (the grader README's sentence table lists them). */
function reasonsHtml(r) {
  if (!(r.reasons && r.reasons.length)) return '';
  const items = findingsOfResult(r).map((f) => `<li>${esc(f.reason)}${f.id ? ` <code class="audit">${esc(f.id)}</code>` : ''}</li>`);
  return `<p>Reasons:</p><ul class="reasons">${items.join('')}</ul>`;
}

/** The part's pictures, each with its caption. */
function picturesHtml(r) {
  if (!r.images) return '';
  const figures = PICTURES.filter((k) => r.images[k])
    .map((k) => `<figure>${img(r, k)}<figcaption>${CAPTIONS[k]}</figcaption></figure>`);
  return `<div class="images">${figures.join('')}</div>`;
}

/** The part's numbers, and the part against our reference and how that was drawn: evidence, never the verdict. */
function numbersHtml(r) {
  const kept = (k, v) => (typeof v === 'number' ? Number(v.toFixed(4)) : v);
  const numbers = r.numbers && Object.keys(r.numbers).length
    ? `<details><summary>numbers</summary><pre>${esc(JSON.stringify(r.numbers, kept, 1))}</pre></details>` : '';
  const against = r.mismatch !== null && r.mismatch !== undefined
    ? `<p>Against our reference: ${(PERCENT * r.mismatch).toFixed(1)}% of pixels differ (${esc(r.comparison)}), ` +
      `RMSE ${(CHANNEL_MAX * r.rmse).toFixed(1)}/255 (evidence only).</p>` : '';
  const st = r.referenceState;
  const light = st && st.light
    ? `, a ${esc(st.light.kind)} light at (${esc(st.light.xyz.join(', '))}) as fitted to the student's picture` : '';
  // (a result graded before our reference was the exact sphere names the level our page drew)
  const how = st && st.level !== null ? `drawn at level ${esc(String(st.level))}` : 'the exact sphere, the slide\'s formula at each pixel';
  const drawn = st ? `<p>Our reference: ${how}${light}.</p>` : '';
  return numbers + against + drawn;
}

/** A part's section: heading, file, reasons, pictures, numbers, controls, actions, notes, errors. */
function partHtml(s, r) {
  const codes = r.regather ? r.regather.map((k) => `<code>${esc(k)}</code>`).join(', ') : '';
  const regather = r.regather
    ? `<p class="regather">Gathered under other values of ${codes} than this rubric's: ` +
      'the verdict stands on what was gathered then (<code>--audit-only … --regather-changed</code> gathers it again).</p>' : '';
  return `<div class="part" id="${esc(anchor(s, r))}">${partHeading(r)}` +
    `<p class="file">${r.file ? esc(r.file) : 'no file'}</p>` +
    regather + reasonsHtml(r) + picturesHtml(r) + numbersHtml(r) +
    list('Controls found:', Object.entries(r.controls || {}).map(([k, v]) => `${k}: ${v}`), 'controls') +
    list('What the grader did:', r.actions, 'actions') +
    list('Notes:', r.notes, 'notes') +
    list('Errors the page printed or caused:', r.errors, 'errors') +
    list('Blocked:', r.blocked, 'blocked') +
    '</div>';
}

/** A submission's section: its name, passes and identity, then its parts. */
function submissionHtml(s) {
  const heading = `<h2>${esc(s.name)} · ${s.passes} of ${PARTS.length} pass</h2>${identityHtml(s)}`;
  return `<section id="${esc(safeName(s.name))}">${heading}${s.parts.map((r) => partHtml(s, r)).join('\n')}</section>`;
}

/** Which browsers graded, or why none is named. */
function browsersText(rows, browsers) {
  if (browsers.length) return `Graded in ${browsers.map(esc).join(' and ')}.`;
  return rows.every((s) => s.parts.every((x) => x.status === 'missing'))
    ? 'No page was opened in a browser: no part was handed in.'
    : 'Graded in a browser that did not say its version (graded before the report named it).';
}

/** Each part's count of pass / review / fail (and not graded here), under the grid. */
function totalsOf(rows) {
  const count = (p, v) => rows.filter((s) => s.parts.find((x) => x.part === p).verdict === v).length;
  return PARTS.map((p) => {
    const not = count(p, NOT_GRADED);
    return VERDICTS.map((v) => count(p, v)).join(' / ') + (not ? ` (${not} not graded here)` : '');
  });
}

/**
 * report.html for the sorted `rows` (report.js's writeReport: { name, parts, passes, reviews }),
 * the `browsers` that graded, the agreement with the labels (`agreed`, or null), the similarity
 * (`similar`, or null) and the item analysis (`items`).
 */
export function reportHtml({ rows, browsers, agreed, similar, items }) {
  const heads = PARTS.map((p, i) => `<th data-sort="${i + 2}">${p}</th>`).join('');
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Grading report</title>
<style>${CSS}${SIMILARITY_CSS}${TEACHER_CSS}</style></head><body>
${INTRO}
<p class="browsers">${browsersText(rows, browsers)}</p>
<table id="grid"><thead><tr><th data-sort="name">submission</th><th data-sort="passes">passes</th>${heads}</tr></thead>
<tbody>
${rows.map((s) => gridRow(s, similar)).join('\n')}
</tbody><tfoot><tr><th>pass / review / fail</th><td></td>${totalsOf(rows).map((t) => `<td>${t}</td>`).join('')}</tr></tfoot></table>
${agreed ? agreementHtml(agreed, (r) => `#${safeName(r.submission)}-${r.part}`) : ''}
${similar ? similarityHtml(similar, (n) => `<a href="#${esc(safeName(n))}">${esc(n)}</a>`) : ''}
${itemAnalysisHtml(items)}
${rows.map(submissionHtml).join('\n')}${SORT_SCRIPT}</body></html>`;
}
