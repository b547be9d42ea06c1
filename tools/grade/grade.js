#!/usr/bin/env node
// npm run grade: a student's submission (or a class of them) against this site's reference parts,
// in a report a grader can read: reference | submission | difference for every part, with numbers.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PARTS, findParts } from './parts.js';
import { readLabels, agreement, agreementText, agreementHtml } from './labels.js';
import { CHROMIUM } from '../browser.js';
import { runSimilarity, writeSimilarityReport, similarityJson, similarityBadges, similarityHtml, SIMILARITY_CSS, SIMILARITY_HELP, parseBound } from '../../grader/similarity/run.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '../..');
// the time our own reference page gets on top of the rubric's bound for the student's page
const REFERENCE_SECONDS = 30;
const HELP = `usage: npm run grade -- <submission-folder> [--part WP04P1=<path to html>]... [--rubric <file>] [--out <dir>]
       npm run grade -- --batch <folder with one submission per subfolder> [--rubric <file>] [--out <dir>]
Opens each part (WP04P1 ... WP04P5, found by folder or file name: WP04P1, Part1, p01, w4p1,
week04p01, ...) in Chromium (WebGL or WebGPU) with time frozen, finds its controls, stops the
orbit, subdivides until the silhouette settles, and gives each part a verdict (pass, review,
fail) with reasons, from what the slide's step asks for. Our reference part is drawn beside it.
  --part P=FILE     use FILE (relative to the submission) for part P
  --rubric FILE     a rubric in place of tools/grade/rubric.json (copy that file and edit it: time bounds,
                    thresholds, control patterns, what each part must show)
  --out DIR         where report.html, report.json (and grades.csv in batch mode) go
                    (default out/grade/<name>)
  --shard I/N       grade only the I-th of N shares of the parts (Playwright's sharding), to split a
                    class across machines; gather the out folders and run --report-only on them
  --report-only     rebuild the report from the parts already graded in --out
  --workers N       parts graded at once (default 2)
  --labels FILE     your own labels (TSV: submission, part, label = correct | partial | broken, reasons):
                    the report and stdout add the agreement per part, a label × verdict table and
                    every disagreement with both sides' reasons (correct → pass, partial → review,
                    broken → fail)
${SIMILARITY_HELP}
exit codes: 0 it ran (whatever the verdicts), 1 it could not run, 2 bad usage`;

function fail(message, code = 1) {
  console.error(`grade: ${message}`);
  process.exit(code);
}

function parseArgs(argv) {
  const o = { parts: {}, positional: [] };
  for (let k = 0; k < argv.length; k++) {
    const a = argv[k];
    const next = () => (k + 1 < argv.length ? argv[++k] : fail(`${a} needs a value\n\n${HELP}`, 2));
    if (a === '--help' || a === '-h') { console.log(HELP); process.exit(0); }
    else if (a === '--batch') o.batch = next();
    else if (a === '--rubric') o.rubric = next();
    else if (a === '--out') o.out = next();
    else if (a === '--shard') o.shard = next();
    else if (a === '--workers') o.workers = next();
    else if (a === '--labels') o.labels = next();
    else if (a === '--report-only') o.reportOnly = true;
    else if (a === '--similarity-only') o.similarityOnly = true;
    else if (a === '--similarity-bound') o.similarityBound = parseBound(next()) ?? fail(`--similarity-bound takes a number in (0, 1]\n\n${HELP}`, 2);
    else if (a === '--part') {
      const m = /^(WP04P[1-5])=(.+)$/i.exec(next());
      if (!m) fail(`--part takes WP04Pn=<path>\n\n${HELP}`, 2);
      o.parts[m[1].toUpperCase()] = m[2];
    } else if (a.startsWith('--')) fail(`unknown option ${a}\n\n${HELP}`, 2);
    else o.positional.push(a);
  }
  if (o.similarityOnly && !o.batch) fail(`--similarity-only compares a class: give --batch <folder>\n\n${HELP}`, 2);
  if (!o.batch && o.positional.length !== 1 && !o.reportOnly) fail(`give one submission folder or --batch <folder>\n\n${HELP}`, 2);
  return o;
}

const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
const safeName = (s) => s.replace(/[^A-Za-z0-9._-]+/g, '_');

const DEFAULT_RUBRIC = path.join(here, 'rubric.json');

/** The rubric: tools/grade/rubric.json, or the teacher's file in its place (keys it leaves out keep the defaults). */
function readRubric(file) {
  const load = (f) => {
    try {
      return JSON.parse(readFileSync(f, 'utf8'));
    } catch (err) {
      return fail(`cannot read the rubric ${f}: ${err.message}`, 2);
    }
  };
  const base = load(DEFAULT_RUBRIC);
  if (!file) return base;
  const r = load(file);
  const parts = { ...base.parts };
  for (const [k, v] of Object.entries(r.parts || {})) parts[k] = { ...(base.parts[k] || {}), ...v };
  return { ...base, ...r, thresholds: { ...base.thresholds, ...(r.thresholds || {}) }, controls: { ...base.controls, ...(r.controls || {}) }, parts };
}

const VERDICTS = ['pass', 'review', 'fail'];
/** The passes of a submission, then its reviews (a count a reader can read: more is better). */
function passes(parts) {
  return parts.filter((p) => p.verdict === 'pass').length;
}
const badge = (v) => `<span class="badge ${esc(v || 'fail')}">${esc(v || 'fail')}</span>`;

function writeReport(out, submissions, labels = null, similar = null) {
  const rows = submissions.map((s) => ({ ...s, passes: passes(s.parts), reviews: s.parts.filter((p) => p.verdict === 'review').length }))
    .sort((a, b) => b.passes - a.passes || b.reviews - a.reviews || a.name.localeCompare(b.name));
  const agreed = labels ? agreement(labels, rows) : null;
  writeFileSync(path.join(out, 'report.json'), JSON.stringify({ generated: new Date().toISOString(), submissions: rows,
    ...(similar ? { similarity: similarityJson(similar) } : {}),
    ...(agreed ? { labels: { ...agreed, rows: agreed.rows.map(({ reasons, ...r }) => ({ ...r, reasons: reasons.filter((x) => /^(FAIL|REVIEW)/.test(x)) })) } } : {}) }, null, 1));
  const img = (s, r, k) => (r.images && r.images[k] ? `<img src="${esc(`parts/${safeName(s.name)}/${r.images[k]}`)}" alt="${esc(`${r.part} ${k}`)}" loading="lazy">` : '');
  const anchor = (s, r) => `${safeName(s.name)}-${r.part}`;
  const grid = rows.map((s) => `<tr data-name="${esc(s.name)}" data-passes="${s.passes}"><th scope="row"><a href="#${esc(safeName(s.name))}">${esc(s.name)}</a>${similar ? similarityBadges(similar, s.name) : ''}</th><td class="num">${s.passes}</td>` +
    PARTS.map((p) => {
      const r = s.parts.find((x) => x.part === p);
      return `<td class="cell ${esc(r.verdict)}" data-verdict="${VERDICTS.indexOf(r.verdict)}"><a href="#${esc(anchor(s, r))}">${badge(r.verdict)}` +
        `<span class="api">${esc(r.api || '')}</span><span class="thumbs">${img(s, r, 'first')}${img(s, r, 'judged')}</span></a></td>`;
    }).join('') + '</tr>').join('\n');
  const list = (title, items, cls) => (items && items.length ? `<p>${title}</p><ul class="${cls}">${items.map((e) => `<li>${esc(e)}</li>`).join('')}</ul>` : '');
  const details = rows.map((s) => `<section id="${esc(safeName(s.name))}"><h2>${esc(s.name)} · ${s.passes} of ${PARTS.length} pass</h2>` +
    s.parts.map((r) => `<div class="part" id="${esc(anchor(s, r))}"><h3>${r.part} ${badge(r.verdict)} <small>${esc(r.api || 'no API')} · ${esc(r.status)}${r.seconds ? ` · ${r.seconds.toFixed(0)} s` : ''}</small></h3>` +
      `<p class="file">${r.file ? esc(r.file) : 'no file'}</p>` +
      list('Reasons:', r.reasons, 'reasons') +
      (r.images ? `<div class="images">${['first', 'coarse', 'highlightPlace', 'judged', 'reference', 'diff'].filter((k) => r.images[k]).map((k) => `<figure>${img(s, r, k)}<figcaption>${{ first: 'first frame', coarse: 'a coarse level', highlightPlace: 'the highlight, the light away from the viewer', judged: 'judged (submission)', reference: 'our reference', diff: 'difference' }[k]}</figcaption></figure>`).join('')}</div>` : '') +
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
  const totals = PARTS.map((p) => VERDICTS.map((v) => rows.filter((s) => s.parts.find((x) => x.part === p).verdict === v).length).join(' / '));
  writeFileSync(path.join(out, 'report.html'), `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Grading report</title>
<style>body{font-family:system-ui,sans-serif;margin:1rem 2rem;color:#1d2330}table{border-collapse:collapse}td,th{border:1px solid #ccd;padding:.2rem .4rem;vertical-align:top}
th[data-sort]{cursor:pointer;text-decoration:underline dotted}.num{text-align:right}.cell a{color:inherit;text-decoration:none;display:block}
.cell.pass{background:#e3f6e3}.cell.review{background:#fff4d6}.cell.fail{background:#fde4e4}
.badge{display:inline-block;padding:0 .4rem;border-radius:.6rem;font-size:.8rem;font-weight:600;color:#fff}.badge.pass{background:#2a7d2a}.badge.review{background:#a66b00}.badge.fail{background:#b3261e}
.api{color:#556;font-size:.75rem;margin-left:.3rem}.thumbs{display:flex;gap:2px;margin-top:2px}.thumbs img{width:64px;height:64px;object-fit:contain;border:1px solid #ccd;background:#fff}
.images{display:flex;gap:.8rem;flex-wrap:wrap}figure{margin:0}figure img{max-width:260px;border:1px solid #ccd;image-rendering:pixelated}
.errors li{color:#a00}.confusion td.agree{background:#e3f6e3;font-weight:600}.file{color:#556;font-family:monospace}.part{border-top:1px solid #dde;padding:.3rem 0}${SIMILARITY_CSS}</style></head><body>
<h1>Grading report</h1><p>Each part was opened in Chromium (WebGL, or WebGPU on SwiftShader with its frames read back), with time
frozen. The grader found its controls, stopped or sampled the orbit, coarsened and subdivided until the silhouette stopped
changing, and judged the picture by what the slide's step asks for (a round sphere; normals as colours; diffuse shading for a
fitted light; a highlight; sliders on the input event; shading per fragment). Verdicts: pass, review (a teacher should look),
fail. Click a cell for its reasons and pictures; click a column head to sort.</p>
<table id="grid"><thead><tr><th data-sort="name">submission</th><th data-sort="passes">passes</th>${PARTS.map((p, i) => `<th data-sort="${i + 2}">${p}</th>`).join('')}</tr></thead>
<tbody>
${grid}
</tbody><tfoot><tr><th>pass / review / fail</th><td></td>${totals.map((t) => `<td>${t}</td>`).join('')}</tr></tfoot></table>
${agreed ? agreementHtml(agreed, (r) => `#${safeName(r.submission)}-${r.part}`) : ''}
${similar ? similarityHtml(similar, (n) => `<a href="#${esc(safeName(n))}">${esc(n)}</a>`) : ''}
${details}${sortScript}</body></html>`);
  return { rows, agreed };
}

async function main() {
  const o = parseArgs(process.argv.slice(2));
  const rubric = readRubric(o.rubric);
  let labels = null;
  if (o.labels) {
    try {
      labels = readLabels(o.labels);
    } catch (err) {
      fail(`cannot read the labels: ${err.message}`, 2);
    }
  }
  let submissions;
  if (o.batch) {
    const root = path.resolve(o.batch);
    if (!existsSync(root) || !statSync(root).isDirectory()) fail(`no such folder: ${o.batch}`);
    submissions = readdirSync(root).filter((n) => !n.startsWith('.') && statSync(path.join(root, n)).isDirectory()).sort()
      .map((n) => ({ name: n, root: path.join(root, n) }));
    if (!submissions.length) fail(`${o.batch} has no submission folders`);
  } else if (!o.reportOnly) {
    const root = path.resolve(o.positional[0]);
    if (!existsSync(root) || !statSync(root).isDirectory()) fail(`no such folder: ${o.positional[0]}`);
    submissions = [{ name: path.basename(root), root }];
  }
  const out = path.resolve(o.out || path.join(repo, 'out/grade', o.batch ? path.basename(path.resolve(o.batch)) : path.basename(path.resolve(o.positional[0] || 'report'))));
  mkdirSync(out, { recursive: true });

  if (!o.reportOnly && !o.similarityOnly) {
    if (!existsSync(CHROMIUM)) fail(`Chromium is missing at ${CHROMIUM}: run "sudo apt-get update && sudo apt-get install -y chromium"`);
    const items = [];
    for (const s of submissions) {
      const parts = findParts(s.root, o.batch ? {} : o.parts);
      for (const part of PARTS) {
        const cfg = rubric.parts[part] || {};
        const page = parts[part] && existsSync(path.join(s.root, parts[part])) ? parts[part] : null;
        items.push({ name: s.name, part, root: s.root, page, referenceQuery: cfg.referenceQuery || {}, resultFile: path.join(out, 'parts', safeName(s.name), `${part}.json`) });
      }
    }
    // the parts that try the most first (the sliders, then the orbit's), so that the workers end
    // together on the short ones: a class's time is then near its sum over the workers
    const FIRST = ['WP04P4', 'WP04P3', 'WP04P5', 'WP04P2', 'WP04P1'];
    items.sort((a, b) => FIRST.indexOf(a.part) - FIRST.indexOf(b.part));
    const planFile = path.join(out, 'plan.json');
    writeFileSync(planFile, JSON.stringify({ repo, out, rubric, timeoutSeconds: rubric.timeoutSeconds, referenceSeconds: REFERENCE_SECONDS, items }, null, 1));
    console.log(`grade: ${submissions.length} submission(s), ${items.length} parts; ${o.workers || 2} at a time, at most ${rubric.timeoutSeconds} s for each student page, and ${REFERENCE_SECONDS} s more for our reference`);
    const args = ['test', '-c', path.join(here, 'playwright.config.js')];
    if (o.shard) args.push('--shard', o.shard);
    rmSync(path.join(out, 'blob-report'), { recursive: true, force: true });
    const run = spawnSync(process.execPath, [path.join(repo, 'node_modules/@playwright/test/cli.js'), ...args], {
      cwd: here, stdio: 'inherit', env: { ...process.env, GRADE_PLAN: planFile, GRADE_WORKERS: o.workers || '2' },
    });
    if (run.error) fail(`could not start Playwright: ${run.error.message}`);
  }

  // gather every part graded in this out folder (all shards, once they are copied together)
  const partsDir = path.join(out, 'parts');
  const similar = o.batch ? await runSimilarity(submissions, out, { bound: o.similarityBound ?? undefined }) : null;
  if (o.similarityOnly && !existsSync(partsDir)) {
    writeSimilarityReport(out, similar, submissions.map((s) => s.name));
    console.log(`grade: similarity report at ${path.join(out, 'report.html')}`);
    return;
  }
  if (!existsSync(partsDir)) fail(`nothing graded in ${out} yet`);
  const byName = new Map();
  for (const dir of readdirSync(partsDir).sort()) {
    for (const part of PARTS) {
      const f = path.join(partsDir, dir, `${part}.json`);
      if (!existsSync(f)) continue;
      const r = JSON.parse(readFileSync(f, 'utf8'));
      if (!byName.has(r.name)) byName.set(r.name, { name: r.name, parts: [] });
      byName.get(r.name).parts.push(r);
    }
  }
  for (const s of byName.values()) {
    for (const part of PARTS) {
      if (!s.parts.some((p) => p.part === part)) s.parts.push({ name: s.name, part, status: 'not graded here', verdict: 'fail', reasons: ['not graded in this run'], api: null, actions: [], mismatch: null, rmse: null, pass: false, errors: [], blocked: [] });
    }
    s.parts.sort((a, b) => a.part.localeCompare(b.part));
  }
  const { rows, agreed } = writeReport(out, [...byName.values()], labels, similar);
  if (o.batch) {
    const csv = ['name,passes,' + PARTS.join(',') + ',' + PARTS.map((p) => `${p}_reasons`).join(',')]
      .concat(rows.map((s) => [JSON.stringify(s.name), s.passes, ...PARTS.map((p) => s.parts.find((x) => x.part === p).verdict),
        ...PARTS.map((p) => JSON.stringify((s.parts.find((x) => x.part === p).reasons || []).filter((r) => /^(FAIL|REVIEW)|nothing|timeout|not |no /i.test(r)).join('; ')))].join(','))).join('\n') + '\n';
    writeFileSync(path.join(out, 'grades.csv'), csv);
  }
  for (const s of rows) {
    console.log(`${s.name}: ${s.passes} of ${PARTS.length} pass · ` + s.parts.map((p) => `${p.part} ${p.verdict}${p.api ? ` (${p.api})` : ''}`).join(', '));
  }
  if (agreed) for (const line of agreementText(agreed)) console.log(line);
  console.log(`grade: report at ${path.join(out, 'report.html')}`);
}

main().catch((err) => fail(err.message));
