// The page's surface per pixel (grader/core/computed/surface.js): the camera solved exactly from
// where the page's matrices put its positions, against gl-matrix's lookAt, perspective and ortho.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { surfaceOf, cameraOfClip, clipMatrix, degreesBetween } from '../../grader/core/computed/surface.js';
import { readFileSync } from 'node:fs';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;

test('the camera from gl_Position: its centre under a perspective, its direction under an orthographic projection, and its axes', () => {
  const eye = [2.5 * Math.sin(0.7), 0.8, 2.5 * Math.cos(0.7)];
  const V = mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]);
  const P = mat4.perspective(mat4.create(), Math.PI / 4, 1.3, 0.1, 10);
  const pv = mat4.multiply(mat4.create(), P, V);
  const u = surfaceUnder(pv, eye);
  const s = surfaceOf(u.facts, u.images, T);
  assert.ok(!s.why, s.why);
  for (let k = 0; k < 3; k++) assert.ok(Math.abs(s.camera.eye[k] - eye[k]) < 1e-6, `eye ${k}: ${s.camera.eye[k]}`);
  // the eye space's axes are the rows of V's rotation
  assert.ok(degreesBetween(s.camera.right, [V[0], V[4], V[8]]) < 1e-4);
  assert.ok(degreesBetween(s.camera.up, [V[1], V[5], V[9]]) < 1e-4);
  assert.ok(degreesBetween(s.camera.back, [V[2], V[6], V[10]]) < 1e-4);
  // w_o from each position to the eye
  const q = s.samples[40];
  const wo = [eye[0] - q.p[0], eye[1] - q.p[1], eye[2] - q.p[2]], l = Math.hypot(...wo);
  assert.ok(degreesBetween(q.w_o, wo.map((x) => x / l)) < 0.5);

  const O = mat4.ortho(mat4.create(), -1.5, 1.5, -1.5, 1.5, 0.1, 10);
  const A = clipMatrix(surfaceUnder(mat4.multiply(mat4.create(), O, V), eye).facts.fit.map((x) => ({ p: x.slice(0, 3), clip: x.slice(3, 7) })));
  const cam = cameraOfClip(A);
  assert.equal(cam.eye, null);
  const l2 = Math.hypot(...eye);
  assert.ok(degreesBetween(cam.towards, eye.map((x) => x / l2)) < 1e-4);
});

test('the normal attribute where the page has one, normalised per pixel; too few pixels or none say why', () => {
  const eye = [0, 0, 3];
  const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), 1, 1, 0.5, 5), mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));
  const u = surfaceUnder(pv, eye, { normal: (p) => p.map((x) => 2 * x) });
  const s = surfaceOf(u.facts, u.images, T);
  assert.ok(s.samples.length > T.surfacePixels / 2, `${s.samples.length} samples`);
  // (8-bit pictures: within a degree)
  for (const q of s.samples) assert.ok(degreesBetween(q.n, q.p.map((x) => x / Math.hypot(...q.p))) < 1, `${q.n} ${q.p}`);
  assert.match(surfaceOf({ why: 'no separate triangles' }, {}, T).why, /no separate triangles/);
  assert.match(surfaceOf({ ...u.facts, clip: undefined }, u.images, T).why, /was not read/);
  assert.match(surfaceOf(u.facts, {}, T).why, /pictures are missing/);
});
