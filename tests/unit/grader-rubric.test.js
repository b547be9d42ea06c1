// Every threshold lives in the rubric and nowhere else (issue 28): each threshold the grader's
// source reads is a key of grader/core/rubric.json, no rubric value has a number written beside
// it as a fallback, and a teacher's rubric is merged over the default one key by key.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { mergeRubric } from '../../grader/core/rubric.js';

const grader = fileURLToPath(new URL('../../grader/', import.meta.url));
// the check page runs the grader's core in the browser with the same rubric: its runner is held too
const check = fileURLToPath(new URL('../../check/', import.meta.url));
const rubric = JSON.parse(readFileSync(path.join(grader, 'core/rubric.json'), 'utf8'));

/** The grader's and the check page's JavaScript files, by path relative to grader/. */
function sources(dir = grader) {
  const files = readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const f = path.join(dir, e.name);
    if (e.isDirectory()) return sources(f).map((rel) => path.relative(grader, path.join(grader, rel)));
    return e.name.endsWith('.js') ? [path.relative(grader, f)] : [];
  });
  return dir === grader ? [...files, ...sources(check)] : files;
}
const read = (rel) => readFileSync(path.join(grader, rel), 'utf8');

// how the source names the thresholds: T (gather.js, controls.js, the measurements), thresholds,
// rubric.thresholds
const THRESHOLDS = String.raw`(?:\bT|\bthresholds|\brubric\.thresholds)`;
const KEY = String.raw`[A-Za-z_$][\w$]*`;
// passed to a measurement with the thresholds, not a threshold: pointLightFit's `around` (the
// fitted light direction gather.js hands it as { ...T, around })
const NOT_THRESHOLDS = new Set(['around']);

/** The keys `src` reads: thresholds (T.x, const { x } = T, ...) and top-level rubric keys (rubric.x). */
function keysRead(src) {
  const thresholds = new Set(), top = new Set();
  for (const m of src.matchAll(new RegExp(`${THRESHOLDS}\\.(${KEY})`, 'g'))) thresholds.add(m[1]);
  for (const m of src.matchAll(new RegExp(`(?:const|let|var)\\s*\\{([^}]*)\\}\\s*=\\s*${THRESHOLDS}\\b(?!\\.)`, 'g'))) {
    for (const part of m[1].split(',')) {
      const name = part.trim().replace(/^\.\.\..*$/, '').split(/[:=]/)[0].trim();
      if (name) thresholds.add(name);
    }
  }
  // (a path's rubric.json or rubric.js is a file, not a key)
  for (const m of src.matchAll(new RegExp(`(?<![/\\w])rubric\\.(${KEY})`, 'g'))) top.add(m[1]);
  return { thresholds, top };
}

/** The places `src` writes a number beside a rubric value: `T.x ?? 30`, `rubric.x || 20`, `const { x = 2 } = T`. */
function numericFallbacks(src) {
  const found = [];
  const value = String.raw`(?:${THRESHOLDS}|\brubric)\.${KEY}\)?\s*(?:\?\?|\|\|)\s*\(?\s*[-+]?(?:\d[\d.]*|\.\d+)`;
  for (const m of src.matchAll(new RegExp(value, 'g'))) found.push(m[0]);
  for (const m of src.matchAll(new RegExp(`\\{([^}]*)\\}\\s*=\\s*${THRESHOLDS}\\b(?!\\.)`, 'g'))) {
    for (const d of m[1].matchAll(/(\w+)\s*=\s*[-+]?(?:\d[\d.]*|\.\d+)/g)) found.push(`{ ${d[0]} } = ...`);
  }
  return found;
}

test('the helpers find what they look for (a planted read and fallbacks)', () => {
  const planted = 'const tol = T.backgroundTolerance ?? 30;\nconst { thinLine = 2, fill } = T;\nif (x > (rubric.thresholds.roundness || 0.09)) y(rubric.loadSeconds ?? 20);';
  const { thresholds, top } = keysRead(planted);
  assert.deepEqual([...thresholds].sort(), ['backgroundTolerance', 'fill', 'roundness', 'thinLine']);
  assert.deepEqual([...top], ['thresholds', 'loadSeconds']);
  assert.equal(numericFallbacks(planted).length, 4, numericFallbacks(planted).join(' | '));
  assert.deepEqual(numericFallbacks('const w = o.workers || 2; const t = T.x; const r = rubric.around || null;'), []);
});

test('every threshold the grader reads is in grader/core/rubric.json, every top-level key too', () => {
  const missing = [], seen = new Set();
  for (const rel of sources()) {
    const { thresholds, top } = keysRead(read(rel));
    for (const k of thresholds) {
      seen.add(k);
      if (!(k in rubric.thresholds) && !NOT_THRESHOLDS.has(k)) missing.push(`${rel}: thresholds.${k}`);
    }
    for (const k of top) if (!(k in rubric)) missing.push(`${rel}: rubric.${k}`);
  }
  assert.deepEqual(missing, [], 'read in the source but not in rubric.json');
  // the scan reads the measurements' and the gatherer's thresholds (else it would pass on nothing)
  for (const k of ['backgroundTolerance', 'minCoverage', 'thinLine', 'highlightMargin', 'darkSpotMargin', 'silhouetteSettled', 'diffuseR2']) {
    assert.ok(seen.has(k), `${k} is read somewhere`);
  }
});

test('no rubric value has a number written beside it as a fallback in grader/ and check/', () => {
  const files = sources();
  assert.ok(files.some((rel) => rel.startsWith('core/measure/')) && files.some((rel) => rel.startsWith('core/gather/')) && files.includes('node/harness.js') && files.includes('../check/runner.js'), 'the measurements, the gatherers, the harness and the check page\'s runner are scanned');
  const found = files.flatMap((rel) => numericFallbacks(read(rel)).map((f) => `${rel}: ${f}`));
  assert.deepEqual(found, [], 'numbers that belong in rubric.json');
});

test('a teacher\'s rubric is merged over the default key by key (mergeRubric)', () => {
  assert.equal(mergeRubric(rubric, null), rubric);
  const teacher = { timeoutSeconds: 30, thresholds: { roundness: 0.2 }, controls: { kd: 'diffus' }, parts: { WP04P4: { requiredSliders: ['La'] }, WP04P9: { must: ['sphere'] } } };
  const r = mergeRubric(rubric, teacher);
  assert.equal(r.timeoutSeconds, 30);
  assert.equal(r.loadSeconds, rubric.loadSeconds);
  assert.deepEqual(r.thresholds, { ...rubric.thresholds, roundness: 0.2 });
  assert.deepEqual(r.controls, { ...rubric.controls, kd: 'diffus' });
  assert.deepEqual(r.parts.WP04P4, { ...rubric.parts.WP04P4, requiredSliders: ['La'] });
  assert.deepEqual(r.parts.WP04P1, rubric.parts.WP04P1);
  assert.deepEqual(r.parts.WP04P9, { must: ['sphere'] });
  assert.equal(rubric.thresholds.roundness, 0.09, 'the default is left as it was');
});
