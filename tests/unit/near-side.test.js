// The side of the sphere that shows, read per pixel on the page's own surface after its own
// projection (grader/core/measure/near-side.js), on surfaces made with gl-matrix's matrices.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mat4 } from 'gl-matrix';
import { readFileSync } from 'node:fs';
import { surfaceUnder } from './surface-scenes.js';
import { surfaceOf } from '../../grader/core/computed/surface.js';
import { sideSeen, farSideCause } from '../../grader/core/measure/near-side.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const eye = [1.2, 0.7, 3.1];
const V = mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]);
const P = mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.1, 10);
const times = (...ms) => ms.reduce((a, b) => mat4.multiply(mat4.create(), a, b));
const seen = (pv) => {
  const u = surfaceUnder(pv, eye);
  const s = surfaceOf(u.facts, u.images, T);
  assert.ok(!s.why, s.why);
  return sideSeen(s);
};
const rows = (m) => [0, 1, 2, 3].map((r) => [m[r], m[4 + r], m[8 + r], m[12 + r]]);

test('a perspective view: every pixel read shows the near half, and nothing is wrong with the projection', () => {
  const side = seen(times(P, V));
  assert.ok(side.share >= T.nearSideShare, `share ${side.share}`);
  assert.equal(side.cause, null);
  const O = mat4.ortho(mat4.create(), -2, 2, -2, 2, 0.1, 10);
  assert.ok(seen(times(O, V)).share >= T.nearSideShare);
});

test('a projection that gives nearer points a greater depth: the far half shows, and the depth is named', () => {
  // (the depth test keeps the smaller depth: z turned over, the far intersection is the one kept)
  const flipZ = mat4.fromScaling(mat4.create(), [1, 1, -1]);
  const side = seen(times(flipZ, P, V));
  assert.ok(side.share <= 1 - T.nearSideShare, `share ${side.share}`);
  assert.equal(side.cause, 'depth');
});

test('perspective times ortho turns the picture over: a face toward its camera is wound clockwise on the screen', () => {
  const A = rows(times(P, mat4.ortho(mat4.create(), -8, 8, -8, 8, 0.1, 10), mat4.fromTranslation(mat4.create(), [0, 0, -3])));
  // (its camera, where x, y and w are zero, sits behind the sphere: the model's z = −2.05, so u = −z)
  assert.equal(farSideCause(A, [0, 0, 0], [0, 0, -1]), 'mirrored');
  // the same sphere through the slide's perspective alone is wound as seen
  assert.equal(farSideCause(rows(times(P, mat4.fromTranslation(mat4.create(), [0, 0, -3]))), [0, 0, 0], [0, 0, 1]), null);
  // a mirror in x alone
  assert.equal(farSideCause(rows(times(mat4.fromScaling(mat4.create(), [-1, 1, 1]), P, V)), [0, 0, 0], eye.map((x) => x / Math.hypot(...eye))), 'mirrored');
});
