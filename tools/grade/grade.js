#!/usr/bin/env node
// npm run grade: a student's submission (or a class of them) against this site's reference parts,
// in a report a grader can read: reference | submission | difference for every part, with numbers.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PARTS, findParts } from './parts.js';
import { CHROMIUM } from '../browser.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '../..');
// the time our own reference page gets on top of the rubric's bound for the student's page
const REFERENCE_SECONDS = 30;
const HELP = `usage: npm run grade -- <submission-folder> [--part WP04P1=<path to html>]... [--rubric <file>] [--out <dir>]
       npm run grade -- --batch <folder with one submission per subfolder> [--rubric <file>] [--out <dir>]
Opens each part (WP04P1 ... WP04P5, found by folder or file name: WP04P1, Part1, p01, w4p1,
week04p01, ...) and this site's reference part in Chromium with time frozen, screenshots the
canvases and compares them (pixelmatch; the object alone where backgrounds or sizes differ).
  --part P=FILE     use FILE (relative to the submission) for part P
  --rubric FILE     JSON: {"threshold": 0.02, "timeoutSeconds": 30, "parts": {"WP04P1": {"query": {"level": 4},
                    "actions": [{"click": "/subdiv/i", "times": 3}, {"slider": "/shin/i", "value": 50}], "threshold": 0.05}}}
  --out DIR         where report.html, report.json (and grades.csv in batch mode) go
                    (default out/grade/<name>)
  --shard I/N       grade only the I-th of N shares of the parts (Playwright's sharding), to split a
                    class across machines; gather the out folders and run --report-only on them
  --report-only     rebuild the report from the parts already graded in --out
  --workers N       parts graded at once (default 2)
exit codes: 0 it ran (whatever the scores), 1 it could not run, 2 bad usage`;

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
    else if (a === '--report-only') o.reportOnly = true;
    else if (a === '--part') {
      const m = /^(WP04P[1-5])=(.+)$/i.exec(next());
      if (!m) fail(`--part takes WP04Pn=<path>\n\n${HELP}`, 2);
      o.parts[m[1].toUpperCase()] = m[2];
    } else if (a.startsWith('--')) fail(`unknown option ${a}\n\n${HELP}`, 2);
    else o.positional.push(a);
  }
  if (!o.batch && o.positional.length !== 1 && !o.reportOnly) fail(`give one submission folder or --batch <folder>\n\n${HELP}`, 2);
  return o;
}

const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
const safeName = (s) => s.replace(/[^A-Za-z0-9._-]+/g, '_');

function readRubric(file) {
  const base = { threshold: 0.02, timeoutSeconds: 30, parts: {} };
  if (!file) return base;
  let r;
  try {
    r = JSON.parse(readFileSync(file, 'utf8'));
  } catch (err) {
    fail(`cannot read the rubric ${file}: ${err.message}`, 2);
  }
  return { ...base, ...r, parts: { ...(r.parts || {}) } };
}

/** The score of a submission: the mean mismatch of its parts, a part that did not run counting 1. */
function score(parts) {
  return parts.reduce((s, p) => s + (p.status === 'ok' ? p.mismatch : 1), 0) / PARTS.length;
}

function writeReport(out, submissions) {
  const rows = submissions.map((s) => ({ ...s, score: score(s.parts) })).sort((a, b) => a.score - b.score);
  writeFileSync(path.join(out, 'report.json'), JSON.stringify({ generated: new Date().toISOString(), submissions: rows }, null, 1));
  const pct = (x) => (x === null || x === undefined ? '–' : `${(100 * x).toFixed(1)}%`);
  const summary = rows.map((s) => `<tr><td><a href="#${esc(safeName(s.name))}">${esc(s.name)}</a></td><td>${pct(s.score)}</td>` +
    PARTS.map((p) => {
      const r = s.parts.find((x) => x.part === p);
      return `<td class="${r.status === 'ok' ? (r.pass ? 'pass' : 'fail') : 'bad'}">${r.status === 'ok' ? pct(r.mismatch) : esc(r.status)}</td>`;
    }).join('') + '</tr>').join('\n');
  const details = rows.map((s) => `<section id="${esc(safeName(s.name))}"><h2>${esc(s.name)} · score ${pct(s.score)}</h2>` +
    s.parts.map((r) => `<div class="part"><h3>${r.part}: ${esc(r.status)}${r.status === 'ok' ? ` · ${pct(r.mismatch)} of pixels differ (${esc(r.comparison)}), RMSE ${(255 * r.rmse).toFixed(1)}/255 · ${r.pass ? 'pass' : 'fail'}` : ''}</h3>` +
      `<p class="file">${r.file ? esc(r.file) : 'no file'}</p>` +
      (r.images ? `<div class="images">${['reference', 'submission', 'diff'].map((k) => `<figure><img src="${esc(`parts/${safeName(s.name)}/${r.images[k]}`)}" alt="${k}"><figcaption>${k}</figcaption></figure>`).join('')}</div>` : '') +
      (r.notes && r.notes.length ? `<ul class="notes">${r.notes.map((n) => `<li>${esc(n)}</li>`).join('')}</ul>` : '') +
      (r.errors.length ? `<p>Errors the page printed or caused:</p><ul class="errors">${r.errors.map((e) => `<li>${esc(e)}</li>`).join('')}</ul>` : '') +
      (r.blocked.length ? `<p>Blocked:</p><ul class="blocked">${r.blocked.map((e) => `<li>${esc(e)}</li>`).join('')}</ul>` : '') +
      '</div>').join('\n') + '</section>').join('\n');
  writeFileSync(path.join(out, 'report.html'), `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Grading report</title>
<style>body{font-family:system-ui,sans-serif;margin:1rem 2rem;color:#1d2330}table{border-collapse:collapse}td,th{border:1px solid #ccd;padding:.2rem .6rem;text-align:right}
td:first-child{text-align:left}.pass{background:#e3f6e3}.fail{background:#fde4e4}.bad{background:#eee;color:#555}.images{display:flex;gap:.8rem;flex-wrap:wrap}
figure{margin:0}img{max-width:300px;border:1px solid #ccd;image-rendering:pixelated}.errors li{color:#a00}.file{color:#556;font-family:monospace}</style></head><body>
<h1>Grading report</h1><p>Each part and this site's reference part were opened in Chromium with time frozen and the same
second of animation; the canvases were compared with pixelmatch (anti-aliasing aware). "object-only": the backgrounds
differ, so each picture's background (from its corners) was masked out. Score: the mean share of differing pixels over
the five parts, a part that did not run counting 100%. Sorted by score, best first.</p>
<table><tr><th>submission</th><th>score</th>${PARTS.map((p) => `<th>${p}</th>`).join('')}</tr>
${summary}</table>
${details}</body></html>`);
  return rows;
}

function main() {
  const o = parseArgs(process.argv.slice(2));
  const rubric = readRubric(o.rubric);
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

  if (!o.reportOnly) {
    if (!existsSync(CHROMIUM)) fail(`Chromium is missing at ${CHROMIUM}: run "sudo apt-get update && sudo apt-get install -y chromium"`);
    const items = [];
    for (const s of submissions) {
      const parts = findParts(s.root, o.batch ? {} : o.parts);
      for (const part of PARTS) {
        const cfg = rubric.parts[part] || {};
        const page = parts[part] && existsSync(path.join(s.root, parts[part])) ? parts[part] : null;
        items.push({ name: s.name, part, root: s.root, page, actions: cfg.actions || [], referenceQuery: cfg.query || {},
          threshold: cfg.threshold ?? rubric.threshold, resultFile: path.join(out, 'parts', safeName(s.name), `${part}.json`) });
      }
    }
    const planFile = path.join(out, 'plan.json');
    writeFileSync(planFile, JSON.stringify({ repo, out, timeoutSeconds: rubric.timeoutSeconds, referenceSeconds: REFERENCE_SECONDS, items }, null, 1));
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
      if (!s.parts.some((p) => p.part === part)) s.parts.push({ name: s.name, part, status: 'not graded here', mismatch: null, rmse: null, pass: false, errors: [], blocked: [] });
    }
    s.parts.sort((a, b) => a.part.localeCompare(b.part));
  }
  const rows = writeReport(out, [...byName.values()]);
  if (o.batch) {
    const csv = ['name,score,' + PARTS.map((p) => `${p}_status,${p}_mismatch`).join(',')]
      .concat(rows.map((s) => [JSON.stringify(s.name), s.score.toFixed(4), ...PARTS.flatMap((p) => {
        const r = s.parts.find((x) => x.part === p);
        return [r.status, r.mismatch === null ? '' : r.mismatch.toFixed(4)];
      })].join(','))).join('\n') + '\n';
    writeFileSync(path.join(out, 'grades.csv'), csv);
  }
  for (const s of rows) {
    console.log(`${s.name}: score ${(100 * s.score).toFixed(1)}% · ` + s.parts.map((p) => `${p.part} ${p.status === 'ok' ? `${(100 * p.mismatch).toFixed(1)}%` : p.status}`).join(', '));
  }
  console.log(`grade: report at ${path.join(out, 'report.html')}`);
}

main();
