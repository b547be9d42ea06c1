// The similarity check (grader/similarity/): the template rule, the shader tokenising, pairing
// across parts, and the planted copies of tests/fixtures/similar/ against their sources.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { tokenStreams } from '../../grader/similarity/tokens.js';
import { compareClass } from '../../grader/similarity/compare.js';
import { findParts } from '../../grader/files/parts.js';
import { copyHandins } from '../fixtures/handins.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const values = (source) => tokenStreams(source).map((s) => s.tokens.map((t) => t.v).join(' '));

test('shaders are tokenised without their names, whitespace and comments', () => {
  const a = 'precision mediump float;\nvarying vec3 vN; // the normal\nuniform vec3 lightDir;\nvoid main() { gl_FragColor = vec4(max(dot(normalize(vN), lightDir), 0.0) * vec3(1.0), 1.0); }';
  const b = 'precision mediump float;  varying vec3 normalV;\n/* light */ uniform vec3 w_i;\n\nvoid main()\n{\n  gl_FragColor = vec4(max(dot(normalize(normalV), w_i), 0.0) * vec3(1.0), 1.0);\n}';
  assert.deepEqual(values({ format: 'glsl', line: 1, text: a }), values({ format: 'glsl', line: 1, text: b }));
  // what the shader does still counts: another operator is another token
  assert.notDeepEqual(values({ format: 'glsl', line: 1, text: a }), values({ format: 'glsl', line: 1, text: a.replace(' * vec3', ' + vec3') }));
  const w = '@vertex fn vs(@location(0) p: vec3f) -> @builtin(position) vec4f { let n = normalize(p); return vec4f(n, 1.0); }';
  const w2 = w.replace(/\bn\b/g, 'normal').replace(/\bp\b/g, 'pos').replace(/\bvs\b/g, 'vertexMain');
  assert.deepEqual(values({ format: 'wgsl', line: 1, text: w }), values({ format: 'wgsl', line: 1, text: w2 }));
});

test('a shader in a JavaScript string is a stream of its own, with the lines of its file', () => {
  const js = 'const fs = `\nprecision mediump float;\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}`;\nconst x = 1;';
  const streams = tokenStreams({ format: 'javascript', line: 10, text: js });
  assert.equal(streams.length, 2);
  assert.equal(streams[1].format, 'glsl');
  assert.ok(streams[1].tokens.some((t) => t.v === 'precision'));
  assert.equal(streams[1].tokens.find((t) => t.v === 'void').line, 12);
});

// a class of hand-ins written here: each a page per part with a script of its own
function writeClass(students) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'similar-'));
  for (const [name, parts] of Object.entries(students)) {
    for (const [n, code] of Object.entries(parts)) {
      mkdirSync(path.join(dir, name, `part${n}`), { recursive: true });
      writeFileSync(path.join(dir, name, `part${n}`, 'index.html'), `<html><body><canvas></canvas><script>\n${code}\n</script></body></html>`);
    }
  }
  return dir;
}
const own = (seed) => Array.from({ length: 12 }, (_, i) =>
  `function f${i}(a, b) { const t = a ${'+-*/'[(seed + i) % 4]} ${seed + i}; if (t > ${i}) { return [t, b, ${seed * i}]; } while (b < ${i}) b += ${seed}; return a; }`).join('\n');
const helper = Array.from({ length: 10 }, (_, i) => `function h${i}(m, v) { return [m[0] * v[${i % 3}], m[1] + v[1] * ${i}, Math.sqrt(m[2] - ${i})]; }`).join('\n');

test('the template rule: a fragment most of the class shares is not a reason for a score', async () => {
  const students = Object.fromEntries(Array.from({ length: 6 }, (_, k) => [`s${k}`, { 3: `${helper}\n${own(10 * k + 1)}` }]));
  const dir = writeClass(students);
  try {
    const r = await compareClass(Array.from({ length: 6 }, (_, k) => ({ name: `s${k}`, root: path.join(dir, `s${k}`) })), findParts, { minPartTokens: 20 });
    assert.ok(r.given > 0, 'the helper is taken as given');
    assert.ok(r.pairs.every((p) => p.score < 0.2), JSON.stringify(r.pairs.map((p) => [p.a, p.b, p.score])));
    assert.ok(r.pairs.every((p) => p.fragments.every((f) => !f.a.lines.some((l) => /function h\d/.test(l.text)))), 'no fragment from the helper');
    // the same helper in two hand-ins only is their own code, and it is found
    const two = writeClass({ a: { 3: `${helper}\n${own(1)}` }, b: { 3: `${helper}\n${own(2)}` }, c: { 3: own(3) }, d: { 3: own(4) }, e: { 3: own(5) } });
    const r2 = await compareClass(['a', 'b', 'c', 'd', 'e'].map((n) => ({ name: n, root: path.join(two, n) })), findParts, { minPartTokens: 20 });
    assert.equal(r2.pairs[0]?.a, 'a');
    assert.equal(r2.pairs[0]?.b, 'b');
    assert.ok(r2.pairs[0].score > 0.2, String(r2.pairs[0].score));
    assert.ok(r2.pairs[0].fragments[0].a.lines.some((l) => /function h\d/.test(l.text)));
    rmSync(two, { recursive: true });
  } finally {
    rmSync(dir, { recursive: true });
  }
});

test('pairs across parts: one hand-in\'s P4 copied, renamed, as another\'s P5', async () => {
  const p4 = own(7);
  const renamed = p4.replace(/\bf(\d+)\b/g, 'step$1').replace(/\ba\b/g, 'x').replace(/\bb\b/g, 'y').replace(/\bt\b/g, 'tmp');
  const dir = writeClass({ src: { 4: p4, 1: own(20) }, copy: { 5: renamed, 1: own(30) }, other: { 4: own(40), 5: own(50) } });
  try {
    const r = await compareClass(['src', 'copy', 'other'].map((n) => ({ name: n, root: path.join(dir, n) })), findParts, { minPartTokens: 20 });
    const top = r.pairs[0];
    assert.deepEqual([top.a, top.b].sort(), ['copy', 'src']);
    const [fromCopy, fromSrc] = top.a === 'copy' ? ['a', 'b'] : ['b', 'a'];
    assert.ok(top.listed && top.parts.WP04P5 > 0.9 && top.parts.WP04P4 > 0.9, JSON.stringify(top.parts));
    const f = top.fragments[0];
    assert.deepEqual([f[fromCopy].parts, f[fromSrc].parts], [['WP04P5'], ['WP04P4']]);
    assert.match(f[fromCopy].file, /part5\/index.html/);
    assert.ok(f[fromCopy].lines.some((l) => /step\d/.test(l.text)) && f[fromSrc].lines.some((l) => /\bf\d/.test(l.text)), 'the fragments show each side\'s own lines');
  } finally {
    rmSync(dir, { recursive: true });
  }
});

test('the planted copies are each the top pair of their hand-in, against their source', async () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'planted-'));
  try {
    copyHandins(dir);
    cpSync(path.join(here, '../fixtures/similar'), dir, { recursive: true });
    const names = ['anna', 'bjorn', 'carla', 'dmitri', 'emma', 'finn', 'jonas', 'kaja', 'lars', 'mona', 'olga', 'peter', 'rasmus', 'sofie', 'tobias', 'ulla', 'vera', 'quinn', 'wendy'];
    const r = await compareClass(names.map((n) => ({ name: n, root: path.join(dir, n) })), findParts);
    for (const [copy, source, part] of [['quinn', 'carla', 'WP04P4'], ['wendy', 'jonas', 'WP04P5']]) {
      const top = r.pairs.find((p) => p.a === copy || p.b === copy);
      assert.deepEqual([top.a, top.b].sort(), [copy, source].sort());
      assert.ok(top.listed && top.parts[part] >= 0.5, `${copy}: ${JSON.stringify(top.parts)}`);
      assert.ok(top.fragments.length > 0);
    }
  } finally {
    rmSync(dir, { recursive: true });
  }
});
