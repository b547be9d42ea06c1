// The grading report of an out folder: report.json (the verdicts, reasons and numbers of every
// part, and the agreement with a teacher's labels) and report.html (the class grid, then each
// part's reasons, pictures and numbers), as npm run grade writes them.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { PARTS } from '../../files/parts.js';
import { safeName } from '../../files/layout.js';
import { agreement, agreementHtml } from './labels.js';
import { NOT_GRADED } from '../../core/verdict.js';
import { findingsOfResult } from '../../core/part-result.js';
import { similarityJson, similarityBadges, similarityHtml, SIMILARITY_CSS } from '../../similarity/run.js';
import { identityHtml, teacherMark, TEACHER_CSS } from './report-teacher.js';
import { itemAnalysis, itemAnalysisHtml } from './item-analysis.js';

const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);

const VERDICTS = ['pass', 'review', 'fail'];
/** The passes of a submission, then its reviews (a count a reader can read: more is better). */
function passes(parts) {
  return parts.filter((p) => p.verdict === 'pass').length;
}
/** A verdict's class name ("not graded here": not-graded). */
const cls = (v) => (v === NOT_GRADED ? 'not-graded' : v || 'fail');
const badge = (v) => `<span class="badge ${esc(cls(v))}">${esc(v || 'fail')}</span>`;

/**
 * Writes report.json and report.html into `out` for the graded `submissions` ({ name, parts }),
 * with the agreement with `labels` (readLabels) where given; returns the submissions sorted as the
 * grid shows them (with their passes and reviews) and the agreement.
 */
export function writeReport(out, submissions, labels = null, similar = null) {
  const rows = submissions.map((s) => ({ ...s, passes: passes(s.parts), reviews: s.parts.filter((p) => p.verdict === 'review').length }))
    .sort((a, b) => b.passes - a.passes || b.reviews - a.reviews || a.name.localeCompare(b.name));
  const agreed = labels ? agreement(labels, rows) : null;
  // the browsers that graded, with their versions (a class graded on two machines may name two)
  const browsers = [...new Set(rows.flatMap((s) => s.parts.map((p) => p.browserVersion).filter(Boolean)))].sort();
  const items = itemAnalysis(rows, PARTS);
  // (the labels' rows with the reasons each part was said to give)
  const labelled = agreed && agreed.rows.map(({ asking, ...r }) => ({ ...r, reasons: asking }));
  const said = agreed ? { labels: { ...agreed, rows: labelled } } : {};
  const report = { generated: new Date().toISOString(), browsers, submissions: rows,
    ...(similar ? { similarity: similarityJson(similar) } : {}), itemAnalysis: items, ...said };
  writeFileSync(path.join(out, 'report.json'), JSON.stringify(report, null, 1));
  // (a picture's path is relative to the report: the artifact's files, our reference in parts/)
  const img = (s, r, k) => (r.images && r.images[k] ? `<img src="${esc(r.images[k])}" alt="${esc(`${r.part} ${k}`)}" loading="lazy">` : '');
  const anchor = (s, r) => `${safeName(s.name)}-${r.part}`;
  const grid = rows.map((s) => `<tr data-name="${esc(s.name)}" data-passes="${s.passes}"><th scope="row"><a href="#${esc(safeName(s.name))}">${esc(s.name)}</a>${similar ? similarityBadges(similar, s.name) : ''}</th><td class="num">${s.passes}</td>` +
    PARTS.map((p) => {
      const r = s.parts.find((x) => x.part === p);
      return `<td class="cell ${esc(cls(r.verdict))}" data-verdict="${r.verdict === NOT_GRADED ? VERDICTS.length : VERDICTS.indexOf(r.verdict)}"><a href="#${esc(anchor(s, r))}">${badge(r.verdict)}${teacherMark(r)}` +
        `<span class="api">${esc(r.api || '')}</span><span class="thumbs">${img(s, r, 'first')}${img(s, r, 'judged')}</span></a></td>`;
    }).join('') + '</tr>').join('\n');
  const list = (title, items, cls) => (items && items.length ? `<p>${title}</p><ul class="${cls}">${items.map((e) => `<li>${esc(e)}</li>`).join('')}</ul>` : '');
  const details = rows.map((s) => `<section id="${esc(safeName(s.name))}"><h2>${esc(s.name)} · ${s.passes} of ${PARTS.length} pass</h2>${identityHtml(s)}` +
    s.parts.map((r) => `<div class="part" id="${esc(anchor(s, r))}"><h3>${r.part} ${badge(r.verdict)}${teacherMark(r, true)} <small>${esc(r.api || 'no API')}${r.browserVersion || r.browser ? ` in ${esc(r.browserVersion || r.browser)}` : ''} · ${esc(r.status)}${r.seconds ? ` · ${r.seconds.toFixed(0)} s` : ''}</small></h3>` +
      `<p class="file">${r.file ? esc(r.file) : 'no file'}</p>` +
      (r.regather ? `<p class="regather">Gathered under other values of ${r.regather.map((k) => `<code>${esc(k)}</code>`).join(', ')} than this rubric's: the verdict stands on what was gathered then (<code>--audit-only … --regather-changed</code> gathers it again).</p>` : '') +
      // each reason with its audit's id (the grader README's sentence table lists them)
      (r.reasons && r.reasons.length ? `<p>Reasons:</p><ul class="reasons">${findingsOfResult(r).map((f) => `<li>${esc(f.reason)}${f.id ? ` <code class="audit">${esc(f.id)}</code>` : ''}</li>`).join('')}</ul>` : '') +
      (r.images ? `<div class="images">${['first', 'coarse', 'highlightPlace', 'leastS', 'unclipped', 'brightened', 'allRoundGap', 'shownFirst', 'shownLast', 'judged', 'reference', 'diff'].filter((k) => r.images[k]).map((k) => `<figure>${img(s, r, k)}<figcaption>${{ first: 'first frame', coarse: 'a coarse level', highlightPlace: 'the highlight, the light away from the viewer', leastS: 's at its least', unclipped: 'its own sliders lowered (it clipped to white)', brightened: 'its own light raised (it was too dim)', allRoundGap: 'from another side along the orbit: a hole', shownFirst: 'first frame, as the browser shows it', shownLast: 'at the end, as the browser shows it', judged: 'judged (submission)', reference: 'our reference', diff: 'difference' }[k]}</figcaption></figure>`).join('')}</div>` : '') +
      (r.numbers && Object.keys(r.numbers).length ? `<details><summary>numbers</summary><pre>${esc(JSON.stringify(r.numbers, (k, v) => (typeof v === 'number' ? Number(v.toFixed(4)) : v), 1))}</pre></details>` : '') +
      (r.mismatch !== null && r.mismatch !== undefined ? `<p>Against our reference: ${(100 * r.mismatch).toFixed(1)}% of pixels differ (${esc(r.comparison)}), RMSE ${(255 * r.rmse).toFixed(1)}/255 (evidence only).</p>` : '') +
      (r.referenceState ? `<p>Our reference drawn at level ${esc(String(r.referenceState.level))}${r.referenceState.light ? `, a ${esc(r.referenceState.light.kind)} light at (${esc(r.referenceState.light.xyz.join(', '))}) as fitted to the student's picture` : ''}.</p>` : '') +
      list('Controls found:', Object.entries(r.controls || {}).map(([k, v]) => `${k}: ${v}`), 'controls') +
      list('What the grader did:', r.actions, 'actions') +
      list('Notes:', r.notes, 'notes') +
      list('Errors the page printed or caused:', r.errors, 'errors') +
      list('Blocked:', r.blocked, 'blocked') +
      '</div>').join('\n') + '</section>').join('\n');
  const sortScript = `<script>
for (const th of document.querySelectorAll('#grid thead th[data-sort]')) th.addEventListener('click', () => {
  const k = th.dataset.sort, body = document.querySelector('#grid tbody'), desc = th.dataset.desc = th.dataset.desc === '1' ? '0' : '1';
  const key = (tr) => k === 'name' ? tr.dataset.name : k === 'passes' ? -Number(tr.dataset.passes) : Number(tr.children[Number(k)].dataset.verdict);
  [...body.rows].sort((a, b) => { const x = key(a), y = key(b); const c = x < y ? -1 : x > y ? 1 : 0; return desc === '1' ? c : -c; }).forEach((tr) => body.append(tr));
});
</script>`;
  const count = (p, v) => rows.filter((s) => s.parts.find((x) => x.part === p).verdict === v).length;
  const totals = PARTS.map((p) => VERDICTS.map((v) => count(p, v)).join(' / ') + (count(p, NOT_GRADED) ? ` (${count(p, NOT_GRADED)} not graded here)` : ''));
  writeFileSync(path.join(out, 'report.html'), `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Grading report</title>
<style>body{font-family:system-ui,sans-serif;margin:1rem 2rem;color:#1d2330}table{border-collapse:collapse}td,th{border:1px solid #ccd;padding:.2rem .4rem;vertical-align:top}
th[data-sort]{cursor:pointer;text-decoration:underline dotted}.num{text-align:right}.cell a{color:inherit;text-decoration:none;display:block}
.cell.pass{background:#e3f6e3}.cell.review{background:#fff4d6}.cell.fail{background:#fde4e4}
.badge{display:inline-block;padding:0 .4rem;border-radius:.6rem;font-size:.8rem;font-weight:600;color:#fff}.badge.pass{background:#2a7d2a}.badge.review{background:#a66b00}.badge.fail{background:#b3261e}.badge.not-graded{background:#667}
.api{color:#556;font-size:.75rem;margin-left:.3rem}.thumbs{display:flex;gap:2px;margin-top:2px}.thumbs img{width:64px;height:64px;object-fit:contain;border:1px solid #ccd;background:#fff}
.images{display:flex;gap:.8rem;flex-wrap:wrap}figure{margin:0}figure img{max-width:260px;border:1px solid #ccd;image-rendering:pixelated}
.errors li{color:#a00}.confusion td.agree{background:#e3f6e3;font-weight:600}.file{color:#556;font-family:monospace}code.audit{font-size:.75rem;color:#556;background:#eef0f4;padding:0 .25rem;border-radius:.2rem}.part{border-top:1px solid #dde;padding:.3rem 0}${SIMILARITY_CSS}${TEACHER_CSS}</style></head><body>
<h1>Grading report</h1><p>Each part was opened in Chromium (WebGL, or WebGPU on SwiftShader with its frames read back), or with
--browser firefox in Firefox ESR (WebGL; a WebGPU part is not graded there), with time frozen. The grader found its controls, stopped or sampled the orbit, coarsened and subdivided until the silhouette stopped
changing, and judged the picture by what the slide's step asks for (a round sphere; normals as colours; diffuse shading for a
fitted light; a highlight; sliders on the input event; shading per fragment). Verdicts: pass, review (a teacher should look),
fail. Click a cell for its reasons and pictures; click a column head to sort.</p>
<p class="browsers">${browsers.length ? `Graded in ${browsers.map(esc).join(' and ')}.`
    : rows.every((s) => s.parts.every((x) => x.status === 'missing')) ? 'No page was opened in a browser: no part was handed in.'
      : 'Graded in a browser that did not say its version (graded before the report named it).'}</p>
<table id="grid"><thead><tr><th data-sort="name">submission</th><th data-sort="passes">passes</th>${PARTS.map((p, i) => `<th data-sort="${i + 2}">${p}</th>`).join('')}</tr></thead>
<tbody>
${grid}
</tbody><tfoot><tr><th>pass / review / fail</th><td></td>${totals.map((t) => `<td>${t}</td>`).join('')}</tr></tfoot></table>
${agreed ? agreementHtml(agreed, (r) => `#${safeName(r.submission)}-${r.part}`) : ''}
${similar ? similarityHtml(similar, (n) => `<a href="#${esc(safeName(n))}">${esc(n)}</a>`) : ''}
${itemAnalysisHtml(items)}
${details}${sortScript}</body></html>`);
  return { rows, agreed };
}
