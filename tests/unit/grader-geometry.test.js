// What a page sent to WebGL, summed up (grader/browser/mesh.js) and judged (core/audits/geometry.js),
// on meshes built here: our own sphere (counter-clockwise seen from outside), the same reversed
// (the textbook's winding), one face of four reversed, a hole, a colour per face, indexed and
// interleaved buffers, homogeneous w, a page that draws more every frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { meshAnalysis } from '../../grader/browser/mesh.js';
import { auditWinding } from '../../grader/core/audits/units/winding.js';
import { auditClosed } from '../../grader/core/audits/units/closed.js';
import { auditPerFace } from '../../grader/core/audits/units/per-face.js';
import { auditGrowth } from '../../grader/core/audits/units/growth.js';
import { checkList } from '../../grader/core/verdict.js';
import { sentChanges } from '../../grader/core/controls.js';
import { sliderEvent } from '../../grader/core/computed/slider-event.js';
import { tetrahedronSphere, vertexCount } from '../../common/sphere.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const thresholds = rubric.thresholds;
const { vertexShader, vertexInputs, summary } = meshAnalysis();
const FLOAT = 0x1406, TRIANGLES = 4, UNSIGNED_SHORT = 0x1403;
const GL = { FLOAT, TRIANGLES };

/** Our sphere at `level`: x,y,z per vertex, three vertices a triangle, counter-clockwise seen from outside. */
function sphere(level) {
  const p = new Float32Array(3 * vertexCount(level));
  tetrahedronSphere(level, p);
  return p;
}
/** The triangles `which` (indices) of `p` with their second and third corners swapped. */
function reversed(p, which = () => true) {
  const q = new Float32Array(p);
  for (let t = 0; t < p.length / 9; t++) {
    if (!which(t)) continue;
    q.set(p.subarray(9 * t + 6, 9 * t + 9), 9 * t + 3);
    q.set(p.subarray(9 * t + 3, 9 * t + 6), 9 * t + 6);
  }
  return q;
}
const bytes = (a) => new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
const attr = (name, a, { size = 3, stride = 0, offset = 0, position = false } = {}) => ({ name, type: size === 3 ? 'vec3' : 'vec4', position, data: { bytes: bytes(a), size, type: FLOAT, stride, offset, enabled: true } });
const draw = (count, attributes, more = {}) => ({ mode: TRIANGLES, first: 0, count, indexed: false, cull: 'back/ccw', attributes, ...more });

test('the vertex shader: gl_Position traced back to its attribute, through locals and functions', () => {
  const glsl1 = `attribute vec4 vColor; attribute vec4 vPosition; attribute mat4 M;
    uniform mat4 P, V; varying vec4 c;
    void main() { vec4 world = M * vPosition; // comment: gl_Position = vColor
      c = vColor; gl_Position = P * V * world; }`;
  assert.deepEqual(vertexShader(glsl1), { attributes: [{ type: 'vec4', name: 'vColor' }, { type: 'vec4', name: 'vPosition' }, { type: 'mat4', name: 'M' }], position: 'vPosition' });
  const glsl3 = `#version 300 es
    layout(location = 1) in vec3 normal; layout(location = 0) in highp vec3 a;
    uniform mat4 mvp; out vec3 n;
    vec4 project(vec3 q) { return mvp * vec4(q, 1.0); }
    void main() { n = normal; gl_Position = project(a); }`;
  assert.equal(vertexShader(glsl3).position, 'a');
  // none reached (gl_Position from a global the tracer cannot follow): the one named for a position
  assert.equal(vertexShader('attribute vec3 aNormal; attribute vec3 aPos; void main() { set(); }').position, 'aPos');
});

test('the WGSL vertex entry point: its inputs by location, from its parameters and the structs they are', () => {
  const wgsl = `struct VIn { @location(1) normal: vec3<f32>, @location(0) position: vec4f };
    struct VOut { @builtin(position) p: vec4f, @location(0) c: vec4f };
    @vertex fn other(@location(0) q: vec2f) -> @builtin(position) vec4f { return vec4f(q, 0, 1); }
    @vertex fn vs(v: VIn, @builtin(vertex_index) i: u32) -> VOut { var o: VOut; return o; }`;
  assert.deepEqual(vertexInputs(wgsl, 'vs'), { byLocation: { 0: { name: 'position', type: 'vec4f' }, 1: { name: 'normal', type: 'vec3<f32>' } }, position: 0 });
  assert.deepEqual(vertexInputs('@vertex fn main(@location(0) n: vec3f, @location(1) @interpolate(flat) aPos: vec3f) -> @builtin(position) vec4f {}').position, 1);
});

test('winding: our sphere is counter-clockwise seen from outside, the textbook\'s clockwise, one face in four reversed is a quarter', () => {
  const p = sphere(3), n = p.length / 3;
  const read = (q) => summary([draw(n, [attr('a_Position', q, { position: true })])], GL);
  const ours = read(p);
  assert.equal(ours.cw, 0);
  assert.equal(ours.triangles, 256);
  assert.equal(ours.analysed, 256);
  assert.deepEqual(ours.closed, { edges: 384, open: 0, over: 0 });
  assert.equal(read(reversed(p)).cw, 1);
  assert.equal(read(reversed(p, (t) => t < 64)).cw, 0.25);
  // a sphere moved away from the origin and scaled reads the same (its own centre)
  const moved = p.map((v, i) => 2 * v + [5, -1, 3][i % 3]);
  assert.equal(read(moved).cw, 0);
});

test('a hole: edges of one triangle only; sampling keeps the share; vertices past the buffer are counted, not read', () => {
  const p = sphere(2), n = p.length / 3;
  const open = summary([draw(n - 3, [attr('p', p, { position: true })])], GL);
  assert.deepEqual(open.closed, { edges: 96, open: 3, over: 0 });
  const big = sphere(6);
  const sampled = summary([draw(big.length / 3, [attr('p', reversed(big, (t) => t % 4 === 0), { position: true })])], { ...GL, maxTriangles: 1000, maxEdgeTriangles: 100 });
  assert.ok(sampled.analysed <= 1000 && sampled.analysed > 900, String(sampled.analysed));
  assert.equal(sampled.closed, null);
  assert.ok(Math.abs(sampled.cw - 0.25) < 0.02, String(sampled.cw));
  const past = summary([draw(n + 6, [attr('p', p, { position: true })])], GL);
  assert.equal(past.outside, 2);
});

test('indexed, interleaved and homogeneous positions read alike', () => {
  const p = sphere(2), n = p.length / 3;
  // interleaved: x y z w, then a colour r g b a; w = 2 everywhere with the point doubled
  const inter = new Float32Array(8 * n);
  for (let i = 0; i < n; i++) inter.set([2 * p[3 * i], 2 * p[3 * i + 1], 2 * p[3 * i + 2], 2, 0.5, 0.5, 0.5, 1], 8 * i);
  const s = summary([draw(n, [attr('vPosition', inter, { size: 4, stride: 32, offset: 0, position: true }), attr('vColor', inter, { size: 4, stride: 32, offset: 16 })])], GL);
  assert.equal(s.cw, 0);
  assert.deepEqual(s.closed, { edges: 96, open: 0, over: 0 });
  assert.deepEqual(s.perFace, [{ name: 'vColor', share: 1, distinct: 1 }]);
  // indexed: each distinct vertex once, triangles by 16-bit indices, reversed
  const key = (i) => [p[3 * i], p[3 * i + 1], p[3 * i + 2]].join();
  const uniq = new Map(), idx = [];
  for (let i = 0; i < n; i++) {
    if (!uniq.has(key(i))) uniq.set(key(i), uniq.size);
    idx.push(uniq.get(key(i)));
  }
  for (let t = 0; t < idx.length; t += 3) [idx[t + 1], idx[t + 2]] = [idx[t + 2], idx[t + 1]];
  const verts = new Float32Array(3 * uniq.size);
  for (let i = 0; i < n; i++) verts.set(p.subarray(3 * i, 3 * i + 3), 3 * uniq.get(key(i)));
  const indices = new Uint16Array(idx);
  const indexed = summary([draw(n, [attr('pos', verts, { position: true })], { indexed: true, type: UNSIGNED_SHORT, offset: 0, indices: bytes(indices) })], GL);
  assert.equal(indexed.cw, 1);
  assert.equal(indexed.closed.open, 0);
  // WebGPU's base vertex: the same triangles with their vertices one place later in the buffer
  const shifted = new Float32Array(verts.length + 3);
  shifted.set(verts, 3);
  const based = summary([draw(n, [attr('pos', shifted, { position: true })], { indexed: true, type: UNSIGNED_SHORT, offset: 0, base: 1, indices: bytes(indices) })], GL);
  assert.deepEqual([based.cw, based.closed.open, based.outside], [1, 0, 0]);
});

test('a colour per face: an attribute constant over each triangle, with many values', () => {
  const p = sphere(3), n = p.length / 3;
  const face = new Float32Array(3 * n), vertex = new Float32Array(3 * n);
  for (let t = 0; t < n / 3; t++) {
    const c = [0, 1, 2].map((k) => (p[9 * t + k] + p[9 * t + 3 + k] + p[9 * t + 6 + k]) / 6 + 0.5);
    for (let v = 0; v < 3; v++) face.set(c, 9 * t + 3 * v);
  }
  for (let i = 0; i < 3 * n; i++) vertex[i] = 0.5 * p[i] + 0.5;
  const s = summary([draw(n, [attr('a_Position', p, { position: true }), attr('a_Color', face), attr('a_Normal', vertex)])], GL);
  assert.deepEqual(s.perFace, [{ name: 'a_Color', share: 1, distinct: 64 }, { name: 'a_Normal', share: 0, distinct: 64 }]);
});

test('the audits: culled near side, a hole from some side, the slide\'s clockwise experiment, an unreadable mesh', () => {
  const judge = (facts, part = 'WP04P3') => {
    const { checks, sayAs } = checkList(rubric);
    const C = { facts: { api: 'webgl', faces: { culling: true }, ...facts }, thresholds, must: new Set(rubric.parts[part].must), sayAs, numbers: {} };
    auditWinding(C);
    auditClosed(C);
    auditPerFace(C);
    auditGrowth(C);
    return checks.map((c) => `${c.level}: ${c.reason}`);
  };
  const geo = (cw, cull = 'back/ccw', more = {}) => ({ geometry: { triangles: 256, analysed: 256, cw, cull, closed: { edges: 384, open: 0, over: 0 }, perFace: [], ...more } });
  assert.match(judge(geo(1)).join('\n'), /^review: the near side of the sphere is culled/);
  assert.match(judge(geo(0.25)).join('\n'), /^review: a hole shows from some side: 25% of the triangles/);
  assert.match(judge(geo(0)).join('\n'), /^pass: the triangles are wound so that the culling keeps the near side/);
  // culling front faces of a counter-clockwise mesh, or back faces with clockwise fronts, culls the near side too
  assert.match(judge(geo(0, 'front/ccw')).join('\n'), /^review: the near side/);
  assert.match(judge(geo(0, 'back/cw')).join('\n'), /^review: the near side/);
  assert.match(judge(geo(1, 'back/cw')).join('\n'), /^pass/);
  // P2: clockwise front faces over a counter-clockwise mesh is the slide's experiment (the normals' audit says so)
  assert.deepEqual(judge(geo(0, 'back/cw'), 'WP04P2'), []);
  // no culling: the winding shows nothing
  assert.deepEqual(judge(geo(1, 'off')), []);
  assert.match(judge({ geometry: { why: 'no WebGL draw call was seen' } }).join('\n'), /^pass: note: which way the triangles are wound was not read .*no WebGL draw call/);
  assert.match(judge(geo(0, 'off', { closed: { edges: 384, open: 12, over: 0 } })).join('\n'), /^review: the sphere is not closed: 12 of its 384 edges/);
  const faceColour = geo(0, 'off', { perFace: [{ name: 'a_Color', share: 1, distinct: 64 }] });
  assert.match(judge(faceColour, 'WP04P1').join('\n'), /^review: a colour per face, not per vertex: the attribute a_Color/);
  assert.deepEqual(judge(faceColour, 'WP04P3'), [], 'a lit step may colour per face');
});

test('the audits: a page that draws more every frame while nothing is touched', () => {
  const judge = (frames) => {
    const { checks, sayAs } = checkList(rubric);
    auditGrowth({ facts: { geometryAtFirst: { frames } }, thresholds, sayAs, numbers: {} });
    return checks.map((c) => `${c.level}: ${c.reason}`).join('\n');
  };
  assert.match(judge([192, 384, 576, 768, 960]), /^review: the page draws more every frame \(192 → 960 vertices over 5 frames/);
  assert.equal(judge([768, 768, 768, 768, 768]), '');
  assert.equal(judge([12, 768, 768, 768]), '', 'a first frame at another level is not growth');
  assert.equal(judge([192, 384]), '', 'too few frames to tell');
});

test('what the page sent: the keys a slider changed, the animated ones and buffers made anew left out', () => {
  const before = { 'uniform kd': '0.8', 'uniform view': '1,0,0', 'buffer 3': '12,0,1' };
  const after = { 'uniform kd': '0', 'uniform view': '0,1,0', 'buffer 3': '12,0,1', 'buffer 9': '12,0,1' };
  assert.deepEqual(sentChanges(before, after, ['uniform view']), ['uniform kd']);
  assert.deepEqual(sentChanges(before, { ...before, 'uniform view': '0,0,1' }, ['uniform view']), []);
  assert.equal(sentChanges(null, after), null);
  // the slider's event, one reading for the gathering and the audits: moving, what was sent decides;
  // standing still (or nothing sent recorded), how much the picture changed against sliderChange
  const thresholds = { sliderChange: 0.002 };
  const big = 0.1, none = 0;
  assert.equal(sliderEvent({ moving: true, sent: { input: [], change: [] }, changed: { input: big, change: big } }, thresholds), 'none');
  assert.equal(sliderEvent({ moving: true, sent: { input: ['uniform kd'], change: null }, changed: { input: none, change: null } }, thresholds), 'input');
  assert.equal(sliderEvent({ moving: true, sent: { input: [], change: ['uniform kd'] }, changed: { input: none, change: none } }, thresholds), 'change');
  assert.equal(sliderEvent({ moving: true, sent: { input: [], change: null }, changed: { input: big, change: null } }, thresholds), 'none', 'the change event not tried yet');
  assert.equal(sliderEvent({ changed: { input: big, change: null } }, thresholds), 'input');
  assert.equal(sliderEvent({ changed: { input: none, change: null } }, thresholds), 'none', 'the change event not tried yet');
  assert.equal(sliderEvent({ changed: { input: none, change: big } }, thresholds), 'change');
  assert.equal(sliderEvent({ changed: { input: none, change: 0.001 } }, thresholds), 'none');
  assert.equal(sliderEvent({ how: 'change' }, thresholds), 'change', 'an artifact from before the changes were kept: the gathering\'s reading');
});
