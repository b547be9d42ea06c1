// Every threshold lives in the rubric and nowhere else: each threshold the grader's
// source reads is a key of grader/core/rubric.json, no rubric value has a number written beside
// it as a fallback, and a teacher's rubric is merged over the default one key by key.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as acorn from 'acorn';
import { AUDITS } from '../../grader/core/audits/index.js';
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
  assert.ok(files.some((rel) => rel.startsWith('core/measure/')) && files.some((rel) => rel.startsWith('core/gather/')) && files.includes('node/run/harness.js') && files.includes('../check/runner.js'), 'the measurements, the gatherers, the harness and the check page\'s runner are scanned');
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

test('a part\'s must lists audit ids: an older rubric\'s names are read as their ids, an id no audit has is refused with the ids there are', () => {
  for (const [part, p] of Object.entries(rubric.parts)) for (const id of p.must) assert.ok(AUDITS[id], `${part}: ${id}`);
  const older = mergeRubric(rubric, { parts: { WP04P2: { must: ['subdivideControls', 'normalColours', 'perspective', 'frontFaces', 'depthCulling'] }, WP04P4: { must: ['diffuse', 'highlight', 'sliders', 'sliderEffects'] } } });
  assert.deepEqual(older.parts.WP04P2.must, rubric.parts.WP04P2.must);
  assert.deepEqual(older.parts.WP04P4.must, rubric.parts.WP04P4.must);
  assert.throws(() => mergeRubric(rubric, { parts: { WP04P3: { must: ['diffuse', 'difuse'] } } }), /parts\.WP04P3\.must names "difuse", which no audit has: a part's must lists audit ids \(grader\/README\.md, the table of audit units\), such as level-controls/);
  assert.throws(() => mergeRubric(rubric, { parts: { WP04P3: { must: 'diffuse' } } }), /parts\.WP04P3\.must is not a list of audit ids \(it is "diffuse"\)/);
});

// A number that decides a verdict lives in the rubric, or is a constant of mathematics, of the
// slides or of a unit. Every number literal in grader/core/ and check/ is read, and every default
// parameter with a number in grader/ and check/. A number is allowed by what it is, never by its
// value: one of CONSTANTS, an index (a[7]), or named at its place, in the value of a constant whose
// name is in capitals (`const SWEEPS = 12;`, with a comment saying what it is: core/units.js's
// units, a fit's steps, a guard against dividing by zero, the check page's HTTP statuses).
const CONSTANTS = new Set([
  0, 1, 2, 3, 4, 0.5, // counting, halves, x y z, RGBA; the slides' 0.5·p + 0.5
]);
const NAMED = /^[A-Z][A-Z0-9_]*$/;

/** The number literals of `src` that are neither CONSTANTS, an index nor inside a named constant's value: [{ value, line }]. */
function bareNumbers(src) {
  const out = [];
  const walk = (n, named, index) => {
    if (!n || typeof n.type !== 'string') return;
    if (n.type === 'Literal' && typeof n.value === 'number' && !CONSTANTS.has(n.value) && !named && !index) {
      out.push({ value: n.value, line: n.loc.start.line });
    }
    const inName = named || (n.type === 'VariableDeclarator' && n.id.type === 'Identifier' && NAMED.test(n.id.name));
    for (const [k, v] of Object.entries(n)) {
      const isIndex = n.type === 'MemberExpression' && n.computed && k === 'property';
      if (Array.isArray(v)) v.forEach((c) => walk(c, inName, false));
      else if (v && typeof v.type === 'string') walk(v, inName, isIndex);
    }
  };
  walk(acorn.parse(src, { ecmaVersion: 'latest', sourceType: 'module', locations: true }), false, false);
  return out;
}

/** The default parameters (and destructuring defaults) of `src` that give a number outside CONSTANTS. */
function numberDefaults(src) {
  const out = [];
  const walk = (n) => {
    if (!n || typeof n.type !== 'string') return;
    if (n.type === 'AssignmentPattern' && n.right.type === 'Literal' && typeof n.right.value === 'number' && !CONSTANTS.has(n.right.value)) {
      out.push({ text: src.slice(n.start, n.end), line: n.loc.start.line });
    }
    for (const v of Object.values(n)) {
      if (Array.isArray(v)) v.forEach(walk);
      else if (v && typeof v.type === 'string') walk(v);
    }
  };
  walk(acorn.parse(src, { ecmaVersion: 'latest', sourceType: 'module', locations: true }));
  return out;
}

test('the number scans find what they look for (a bare 0.7 in measure/highlight.js, loadSeconds = 20), and allow a number by what it is', () => {
  const highlight = read('core/measure/highlight.js');
  assert.deepEqual(bareNumbers(highlight), [], 'measure/highlight.js as it is');
  const planted = highlight.replace('thresholds.highlightPlaceRise * rise', '0.7 * rise');
  assert.notEqual(planted, highlight);
  assert.deepEqual(bareNumbers(planted).map((n) => n.value), [0.7]);
  // an index, and a constant named at its place (however deep its value), are what they are; a
  // number in a constant named in lower case, or beside an index, is bare
  assert.deepEqual(bareNumbers('const SWEEPS = 12, STEPS = [0.15, { at: 7 }]; const x = m[12] + m[k + 1]; const sweeps = 12; const y = m[5] * 9;').map((n) => n.value), [12, 9]);
  assert.deepEqual(numberDefaults('export function open({ root, loadSeconds = 20 }, d = 2, e = LIMIT) { return [root, loadSeconds, d, e]; }').map((d) => d.text), ['loadSeconds = 20']);
});

test('no number decides a verdict outside the rubric in grader/core/ and check/ (constants, indices and named constants aside)', () => {
  const files = sources();
  const found = [];
  for (const rel of files.filter((f) => f.startsWith('core/') || f.startsWith('../check/'))) {
    found.push(...bareNumbers(read(rel)).map((n) => `${rel}:${n.line}: ${n.value}`));
  }
  assert.deepEqual(found, [], 'numbers to put in rubric.json (or, not a verdict\'s, named at their place: a constant in capitals with a comment saying what it is)');
});

test('no default parameter gives a number the rubric should in grader/ and check/', () => {
  const found = sources().flatMap((rel) => numberDefaults(read(rel)).map((d) => `${rel}:${d.line}: ${d.text}`));
  assert.deepEqual(found, [], 'defaults that belong in rubric.json (or, not a verdict\'s, a constant named at its place)');
});
