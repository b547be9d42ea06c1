// Grading in Firefox ESR (npm run grade -- --browser firefox) without a browser: a part that asked
// for WebGPU where the browser has none is "not graded here" (never a fail), from its artifact, so
// that --audit-only says it again; the labels' agreement and the report count it as not graded,
// not as a disagreement; the command's --browser option. (tests/browser/grade-firefox.spec.js
// grades in Firefox itself.)
import { fileURLToPath } from 'node:url';
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { readArtifact } from '../../grader/node/run/artifacts.js';
import { judged } from '../../grader/core/grade-part.js';
import { applyAudit } from '../../grader/core/part-result.js';
import { isEngineNotice } from '../../grader/node/run/firefox-page.js';
import { NOT_GRADED } from '../../grader/core/verdict.js';
import { parseLabels, agreement, agreementText } from '../../grader/node/report/labels.js';
import { writeReport } from '../../grader/node/report/report.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const RECORDED = fileURLToPath(new URL('../fixtures/artifacts/', import.meta.url));

/** The artifact of a WebGPU page in a browser without WebGPU: it asked, got no context, threw, drew nothing. */
function webgpuInFirefox(webgpuMissing = true) {
  const w = 64, data = new Uint8Array(w * w * 4).fill(255);
  return {
    facts: { part: 'WP04P3', api: null, canvas: { width: w, height: w }, tooSlow: null, actions: [], roles: {}, controls: [], trials: [], views: [], ladder: [], sliders: [],
      work: { frames: 30, draws: 0, vertices: 0 }, first: { api: null, adapter: null, draws: 0, shaderErrors: [], gpuErrors: [], ...(webgpuMissing ? { webgpuMissing } : {}) },
      errors: ['page error: can\'t access property "requestAdapter", navigator.gpu is undefined'] },
    images: { first: { width: w, height: w, data } },
  };
}

const resultOf = (artifact) => applyAudit({ name: 's', part: artifact.facts.part, errors: artifact.facts.errors }, judged(artifact, rubric), {});

test('a part that asked for WebGPU where the browser has none is not graded here, never failed; it says where to grade it', () => {
  const r = resultOf(webgpuInFirefox());
  assert.equal(r.verdict, NOT_GRADED);
  assert.equal(r.status, NOT_GRADED);
  assert.equal(r.pass, false);
  assert.match(r.reasons[0], /^not graded here: this part uses WebGPU .* this browser has no WebGPU \(Firefox ESR has none\): grade it in Chromium/);
  // what was seen stays, as what was seen, not as a verdict
  assert.match(r.reasons[1], /^\(seen here: drew nothing: the page never got a WebGL or WebGPU context/);
  // the same page where nothing says it asked for WebGPU: it drew nothing, a fail
  assert.equal(resultOf(webgpuInFirefox(false)).verdict, 'fail');
});

test('a page that asked for WebGPU and fell back to WebGL is judged as any WebGL part', () => {
  for (const part of ['WP04P1', 'WP04P3']) {
    const a = readArtifact(path.join(RECORDED, 'ada', part));
    const before = resultOf(a);
    a.facts.first = { ...a.facts.first, webgpuMissing: true };
    const after = resultOf(a);
    assert.equal(after.verdict, before.verdict, part);
    assert.notEqual(after.verdict, NOT_GRADED, part);
    assert.deepEqual(after.reasons, before.reasons, part);
  }
});

test('the labels and the report count a part not graded here as not graded, not as a disagreement', () => {
  const labels = parseLabels('submission\tpart\tlabel\treasons\nann\tWP04P1\tcorrect\tok\nann\tWP04P3\tcorrect\tWebGPU, fine\nbob\tWP04P1\tpartial\tcolours\n');
  const subs = [{ name: 'ann', parts: [{ part: 'WP04P1', verdict: 'pass', reasons: [] }, { part: 'WP04P3', verdict: NOT_GRADED, reasons: ['not graded here: WebGPU'] }] },
    { name: 'bob', parts: [{ part: 'WP04P1', verdict: 'review', reasons: [] }] }];
  const a = agreement(labels, subs);
  assert.deepEqual([a.agree, a.total, a.correctPassed, a.correct, a.partialPassed, a.partial], [2, 2, 1, 1, 0, 1]);
  assert.deepEqual(a.notGraded, ['ann WP04P3']);
  assert.equal(a.confusion.correct['not graded'], 1);
  assert.deepEqual(a.rows.filter((r) => !r.agree), []);
  const text = agreementText(a).join('\n');
  assert.match(text, /2 of 2 labelled parts/);
  assert.match(text, /not graded here \(WebGPU, which this browser does not have\), left out of the counts: ann WP04P3/);
  const out = mkdtempSync(path.join(os.tmpdir(), 'report-'));
  const filled = subs.map((s) => ({ ...s, parts: ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'].map((part) => ({ status: 'missing', verdict: 'fail', reasons: [], ...s.parts.find((p) => p.part === part), part, name: s.name })) }));
  writeReport(out, filled, labels);
  const html = readFileSync(path.join(out, 'report.html'), 'utf8');
  assert.match(html, /<td class="cell not-graded"[^>]*><a href="#ann-WP04P3"><span class="badge not-graded">not graded here<\/span>/);
  assert.match(html, /<td>0 \/ 0 \/ 1 \(1 not graded here\)<\/td>/);
});

test('--browser: chromium or firefox (2 on anything else); Firefox missing says how to install it', () => {
  const grade = (args, env = {}) => spawnSync(process.execPath, ['grader/node/cli/grade.js', ...args], { encoding: 'utf8', env: { ...process.env, ...env } });
  const bad = grade(['--browser', 'safari', '/tmp']);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /--browser takes chromium or firefox, not "safari"/);
  assert.match(grade(['--help']).stdout, /--browser B {7}chromium \(the default: WebGL and WebGPU\) or firefox/);
  const out = mkdtempSync(path.join(os.tmpdir(), 'no-firefox-'));
  const missing = grade(['--browser', 'firefox', 'tests/fixtures/handins/anna', '--out', out], { FIREFOX_PATH: '/nonexistent/firefox-esr' });
  assert.equal(missing.status, 1);
  assert.match(missing.stderr, /Firefox is not at \/nonexistent\/firefox-esr \(FIREFOX_PATH\): set FIREFOX_PATH to a browser's executable, or unset it and install one: sudo apt-get update && sudo apt-get install -y firefox-esr/);
  assert.match(missing.stderr, /or grade in Chromium/);
});

test('Firefox\'s notice on a document with no declared character encoding is the engine\'s, not a page error; a script\'s error is', () => {
  assert.equal(isEngineNotice('The character encoding of the document was not declared, so the encoding was guessed from content. The character encoding needs to be declared in the Content-Type HTTP header, using a meta tag, or using a byte order mark.'), true);
  assert.equal(isEngineNotice('The character encoding of the HTML document was not declared. The document will render with garbled text in some browser configurations if the document contains characters from outside the US-ASCII range.'), true);
  assert.equal(isEngineNotice('ReferenceError: vPosition is not defined'), false);
  assert.equal(isEngineNotice('Error: The character encoding of the document was not declared'), false);
});
