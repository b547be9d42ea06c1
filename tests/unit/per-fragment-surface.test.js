// Per vertex against per fragment read on the page's own surface at a coarse level
// (grader/core/computed/coarse-reading.js, audits/units/per-fragment.js): pictures made here of a
// coarse mesh (an octahedron subdivided once, its vertices on the unit sphere), each pixel's
// normal interpolated between its triangle's vertices as a rasteriser interpolates it, shaded by
// the slide's Phong model per fragment (at the normalised interpolated normal) or per vertex (the
// vertices' colours interpolated: Gouraud), beside the judged picture of the exact sphere.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { exactLighting } from '../../grader/core/computed/lighting.js';
import { coarseReading } from '../../grader/core/computed/coarse-reading.js';
import { auditPerFragment, perFragmentOnSurface } from '../../grader/core/audits/units/per-fragment.js';
import { analyse } from '../../grader/core/measure.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

const eye = [0, 0, 3.5];
const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10),
  mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));
const wi = unit([0.5, 0.4, 1]);

/** The slides' L_o at a point p with normal n: ka La + kd Le max(n·w_i, 0) + ks Le max(w_r·w_o, 0)^s. */
function phong(p, n) {
  const c = dot(n, wi), wo = unit(eye.map((e, k) => e - p[k]));
  const wr = n.map((v, j) => 2 * c * v - wi[j]);
  return 0.1 + 0.6 * Math.max(c, 0) + (c > 0 ? 0.6 * Math.max(dot(wr, wo), 0) ** 40 : 0);
}

/** An octahedron subdivided once: 32 triangles, their vertices on the unit sphere. */
function coarseMesh() {
  const v = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]];
  const faces = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]].map((f) => f.map((i) => v[i]));
  return faces.flatMap(([a, b, c]) => {
    const ab = unit(a.map((x, k) => x + b[k])), bc = unit(b.map((x, k) => x + c[k])), ca = unit(c.map((x, k) => x + a[k]));
    return [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]];
  });
}

/** The triangle of `mesh` that the direction of p passes through, with p's barycentric weights on it. */
function onMesh(mesh, p) {
  for (const [a, b, c] of mesh) {
    // the ray from the centre through p meets the triangle's plane at t·p; its weights by areas
    const n = cross(b.map((x, k) => x - a[k]), c.map((x, k) => x - a[k])), t = dot(n, a) / dot(n, p);
    if (!(t > 0)) continue;
    const q = p.map((x) => x * t);
    const w = [[b, c], [c, a], [a, b]].map(([u, v]) => dot(n, cross(u.map((x, k) => x - q[k]), v.map((x, k) => x - q[k]))) / dot(n, n));
    if (w.every((x) => x >= -1e-9)) return { tri: [a, b, c], w };
  }
  return null;
}

const mesh = coarseMesh();
const interpolated = (p) => { const m = onMesh(mesh, p); return unit([0, 1, 2].map((k) => m.w.reduce((s, x, i) => s + x * m.tri[i][k], 0))); };
const gouraud = (p) => { const m = onMesh(mesh, p); return m.w.reduce((s, x, i) => s + x * phong(m.tri[i], m.tri[i]), 0); };

/** surfaceUnder's surface and picture, the background black (the highlight clips to white). */
function drawn(opts) {
  const u = surfaceUnder(pv, eye, opts);
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  return u;
}

/** The judged view (the exact sphere per fragment) and the coarse level drawn with `shade`, as an artifact's facts and images. */
function part(shade) {
  const fine = drawn({ shade: (p) => phong(p, p) });
  const coarse = drawn({ normal: interpolated, shade });
  const images = { ...fine.images, cn: coarse.images.n, cp: coarse.images.p, coarse: coarse.picture, judged: fine.picture };
  const facts = {
    surface: fine.facts, coarseSurface: { level: 0, surface: { ...coarse.facts, normals: 'cn', points: 'cp' } },
    ladder: [{ roundness: 0.05, blank: false, image: 'coarse' }, { roundness: 0.005, blank: false, image: 'judged' }],
    judgedLevel: 1, stopped: true, viewMoved: false, level: { coarsen: 0 }, sources: { glsl: [], wgsl: [] },
  };
  const judged = { img: fine.picture, an: analyse(fine.picture, T), raw: analyse(fine.picture, T) };
  return { facts, images, judged, coarse: coarse.picture, exact: exactLighting(facts, images, judged, T) };
}

const perFragment = part((p) => phong(p, interpolated(p)));
const perVertex = part(gouraud);

test('the coarse level read on the surface: the model per pixel explains it per fragment, not per vertex', () => {
  const read = (x) => coarseReading({ facts: x.facts, images: x.images, thresholds: T }, { exact: x.exact, judged: x.judged.img }, 0, x.coarse);
  const f = read(perFragment), v = read(perVertex);
  assert.ok(!f.why && !v.why, `${f.why || v.why}`);
  assert.equal(perFragmentOnSurface(f, T).perFragment, true, `per fragment adds ${perFragmentOnSurface(f, T).added}`);
  assert.equal(perFragmentOnSurface(v, T).perFragment, false, `per vertex adds ${perFragmentOnSurface(v, T).added}`);
  // read at another level than the one compared: not read
  assert.match(coarseReading({ facts: perFragment.facts, images: perFragment.images, thresholds: T }, { exact: perFragment.exact, judged: perFragment.judged.img }, 1, perFragment.coarse).why, /another level/);
});

test('the per-fragment audit says so from the surface, and falls back to the pictures without it', () => {
  const said = (x, { surface = true } = {}) => {
    const out = [];
    const facts = surface ? x.facts : { ...x.facts, coarseSurface: undefined };
    auditPerFragment({ facts, images: x.images, thresholds: T, must: new Set(['per-fragment']), numbers: {}, imagesShown: {},
      sayAs: (id) => (level, reason) => out.push(`${id} ${level}: ${reason}`) }, x.judged, { fit: {} }, x.exact);
    return out.join('\n');
  };
  assert.match(said(perFragment), /^per-fragment pass: .*per fragment, read on the page's own surface$/);
  assert.match(said(perVertex), /^per-fragment mistake: .*shading is per vertex, not per fragment.*read on the page's own surface$/);
  assert.doesNotMatch(said(perVertex, { surface: false }), /page's own surface/);
});
