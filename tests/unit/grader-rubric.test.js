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

// A number that decides a verdict lives in the rubric, or is a constant of
// mathematics, of the slides or of a unit. Every number literal in grader/core/ and check/ is read,
// and every default parameter with a number in grader/ and check/; what is left is listed below,
// file by file, with why it is not the rubric's.
const CONSTANTS = new Set([
  0, 1, 2, 3, 4, 0.5, // counting, halves, x y z, RGBA; the slides' 0.5·p + 0.5
]);
// every other number is named for what it is: a unit in core/units.js (per cent, milliseconds, a
// channel's 255, degrees, ...), or at its place, listed below by file with why it is not the rubric's
const GUARD = 'a guard against dividing by (nearly) zero';
const MECHANICS = 'the mechanics of a fit or a search (indices, grid sizes, steps), not a bound on what a page shows';
const PAGE = 'the check page\'s own plumbing (key codes, sizes of files, HTTP statuses, waits for the browser)';
const ALLOWED = {
  'core/units.js': { numbers: [100, 1000, 16, 255, 180, 90, 360, 1e6, 1024], why: 'the units themselves, each named once for what it is (per cent, milliseconds, a frame at 60 Hz, a channel\'s greatest byte, degrees, a 4×4 matrix\'s entries, roundings, a kibibyte)' },
  'core/audits/surface.js': { numbers: [8], why: 'how many of the fitted variants the numbers keep (what the report shows, not a bound)' },
  'core/controls.js': { numbers: [60], why: 'the characters of a control\'s words kept to name it in the report' },
  'core/gather/params.js': { numbers: [100], why: 'HTML\'s default max of a range input (RANGE_DEFAULT_MAX)' },
  'core/measure/highlight.js': { numbers: [1e-6], why: GUARD },
  'core/measure/perspective.js': { numbers: [1e-9, 45], why: `${GUARD}; the rim angles searched, 0° to 45° from the view direction (${MECHANICS})` },
  'core/measure/point-light.js': { numbers: [1.25, 1.5, 1.75, 2.5, 5, 7, 10, 20, 10000, 0.1, 0.005, 1.05, 1e-12], why: `the distance grid and its refinement (${MECHANICS}); ${GUARD}` },
  'core/part-names.js': { numbers: [5, 6, 120], why: 'the worksheet\'s five parts, the six patterns that name a part outright (a page\'s title may use those only), a title\'s words kept for a note: names, never a bound on what a page shows' },
  'core/computed/surface.js': { numbers: [7, 12, 1e-9], why: `a fit sample's indices (${MECHANICS}); ${GUARD}` },
  'core/gather/geometry.js': { numbers: [7], why: `a fit sample's indices (${MECHANICS})` },
  'core/measure/surface-fit.js': { numbers: [5, 10, 20, 40, 80, 160, 320, 0.15, 0.05, 0.015, 0.005, 30, 8, 10000, 100000], why: `the shininesses tried, the light's refinement steps, the least pixels a fit is solved on (30 in all, 8 a channel), and the rounding of what is kept (${MECHANICS})` },
  'core/computed/camera.js': { numbers: [5, 6, 8, 9, 10], why: 'the 3×3 rotation inside a column-major 4×4 matrix' },
  'core/measure/linear.js': { numbers: [12, 1e-9, 1e-12, 1e-15], why: `${MECHANICS}; ${GUARD}` },
  'core/reference-state.js': { numbers: [500, 30, 100], why: 'how long our own reference page runs before its picture is taken, and a real wait of 100 ms between looks: our page, never a bound on a student\'s' },
  'core/measure/directions.js': { numbers: [5, 500], why: `the golden angle's √5, and the fibonacci directions searched: ${MECHANICS}` },
  'core/measure/tint-added.js': { numbers: [6, 7, 1e-6, 1e-9, 1e-12], why: `${MECHANICS} (the fit's indices); ${GUARD}` },
  'core/measure/diffuse.js': { numbers: [0.1, 0.005, 1e-9], why: `the refinement steps: ${MECHANICS}; ${GUARD}` },
  'core/measure/tint.js': { numbers: [0.05, 1e-6, 1e-12], why: `the albedo's floor, which keeps a division by it finite: ${MECHANICS}; ${GUARD}` },
  'core/measure/silhouette.js': { numbers: [63, 72, 36, 10, 8, 16], why: `63: a mask's bits; 8, 16: a colour's bytes packed in one number; 72, 36, 10: bins of the outline (${MECHANICS})` },
  'core/gather/session.js': { numbers: [10], why: 'a real wait of 10 ms for the page\'s promises' },
  '../check/files.js': { numbers: [5000, 10, 7, 5, 65536, 100], why: PAGE },
  '../check/frame-page.js': { numbers: [37, 38, 39, 40, 33, 34, 187, 189, 32, 13, 27], why: PAGE },
  '../check/frame-watch.js': { numbers: [1023, 100, 1000], why: `${PAGE}; a script put into the frame as text, which can import nothing: its milliseconds a second are its own` },
  '../check/host.js': { numbers: [400, 500, 5000, 50, 8, 16], why: PAGE },
  '../check/runner.js': { numbers: [200, 500, 5000, 30, 1000], why: PAGE },
  '../check/serve.js': { numbers: [200, 404], why: PAGE },
  '../check/sw.js': { numbers: [15000, 2000, 503], why: PAGE },
};
// a number a default parameter gives, allowed where it is not the rubric's (in grader/ outside core/ too)
const DEFAULTS_ALLOWED = {
  'browser/mesh.js': [60000, 65536],
  'node/run/browser-version.js': [5000],
  'node/cli/progress-line.js': [2000], // how often a log (not a terminal) gets a progress line
  '../check/host.js': [500, 5000],
  '../check/sw.js': [15000],
};

/** The number literals of `src` that are neither constants nor allowed: [{ value, line }]. */
function bareNumbers(src, allowed = []) {
  const out = [];
  for (const t of acorn.tokenizer(src, { ecmaVersion: 'latest', sourceType: 'module', locations: true })) {
    if (t.type === acorn.tokTypes.num && !CONSTANTS.has(t.value) && !allowed.includes(t.value)) out.push({ value: t.value, line: t.loc.start.line });
  }
  return out;
}

/** The default parameters (and destructuring defaults) of `src` that give a number outside CONSTANTS and `allowed`. */
function numberDefaults(src, allowed = []) {
  const out = [];
  const walk = (n) => {
    if (!n || typeof n.type !== 'string') return;
    if (n.type === 'AssignmentPattern' && n.right.type === 'Literal' && typeof n.right.value === 'number' && !CONSTANTS.has(n.right.value) && !allowed.includes(n.right.value)) {
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

test('the number scans find what they look for (a bare 0.7 in measure/highlight.js, loadSeconds = 20)', () => {
  const highlight = read('core/measure/highlight.js');
  const allowed = ALLOWED['core/measure/highlight.js'].numbers;
  assert.deepEqual(bareNumbers(highlight, allowed), [], 'measure/highlight.js as it is');
  const planted = highlight.replace('thresholds.highlightPlaceRise * rise', '0.7 * rise');
  assert.notEqual(planted, highlight);
  assert.deepEqual(bareNumbers(planted, allowed).map((n) => n.value), [0.7]);
  assert.deepEqual(numberDefaults('export function open({ root, loadSeconds = 20 }, d = 2) { return [root, loadSeconds, d]; }').map((d) => d.text), ['loadSeconds = 20']);
});

test('no number decides a verdict outside the rubric in grader/core/ and check/ (constants and the listed ones aside)', () => {
  const files = sources();
  const found = [];
  for (const rel of files.filter((f) => f.startsWith('core/') || f.startsWith('../check/'))) {
    found.push(...bareNumbers(read(rel), (ALLOWED[rel] || {}).numbers).map((n) => `${rel}:${n.line}: ${n.value}`));
  }
  assert.deepEqual(found, [], 'numbers to put in rubric.json (or, a constant, in CONSTANTS; not a verdict\'s, in ALLOWED with why)');
});

test('no default parameter gives a number the rubric should in grader/ and check/', () => {
  const found = sources().flatMap((rel) => numberDefaults(read(rel), DEFAULTS_ALLOWED[rel]).map((d) => `${rel}:${d.line}: ${d.text}`));
  assert.deepEqual(found, [], 'defaults that belong in rubric.json');
});
