// Which side of the sphere the visible pixels are, read on the page's own surface after its own
// projection (computed/surface.js): a pixel shows the near half's outside where its normal faces
// the camera that the page's matrices set up (n · w_o > 0, w_o towards the camera's centre, or
// along its direction for an orthographic projection), whatever the winding in the model's space.
import { dot, cross, unit } from './vectors.js';

/** A step along the sphere's surface, in the model's units, small against any sphere drawn (the mechanics of a derivative). */
const STEP = 1e-3;
/** The most |u| along an axis for that axis to make a second one across u (the mechanics of a cross product). */
const ACROSS = 0.9;

/**
 * The surface's samples ([{ n, w_o }]) read for their side: { share (of the samples whose normal
 * faces the camera), samples }, or null where there are none.
 */
export function nearSide(samples) {
  if (!samples.length) return null;
  const facing = samples.filter((q) => dot(q.n, q.w_o) > 0).length;
  return { share: facing / samples.length, samples: samples.length };
}

/**
 * Why the far side shows, from the clip matrix A (rows of P·V·M) and the camera (cameraOfClip):
 * 'mirrored' where a face toward the camera is wound the other way on the screen than seen from
 * the camera (the projection turns the picture over, so culling the back faces takes the near
 * ones), 'depth' where nearer points get a greater depth (the depth test keeps the far ones), or
 * null. `c` is a point of the sphere's centre region, `u` the unit direction from it to the camera.
 */
export function farSideCause(A, c, u) {
  const at = (q) => A.map((r) => r[0] * q[0] + r[1] * q[1] + r[2] * q[2] + r[3]);
  const ndc = (q) => { const v = at(q); return [v[0] / v[3], v[1] / v[3], v[2] / v[3]]; };
  // depth along the line to the camera: a point a little nearer than c, and one a little farther
  const near = ndc(c.map((x, k) => x + STEP * u[k])), far = ndc(c.map((x, k) => x - STEP * u[k]));
  if (near[2] > far[2]) return 'depth';
  // a small triangle through c facing the camera, counter-clockwise seen from the camera: its winding on the screen
  const a = Math.abs(u[0]) < ACROSS ? [1, 0, 0] : [0, 1, 0];
  const s = cross(u, a), t = cross(u, s);
  const p0 = ndc(c), p1 = ndc(c.map((x, k) => x + STEP * s[k])), p2 = ndc(c.map((x, k) => x + STEP * t[k]));
  const area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
  return area < 0 ? 'mirrored' : null;
}

/**
 * The side the surface (computed/surface.js's surfaceOf) shows: { share, samples, cause } (cause:
 * farSideCause's, read where the share is short of all), or null where it has no samples.
 */
export function sideSeen(s) {
  const side = nearSide(s.samples);
  if (!side || side.share === 1) return side && { ...side, cause: null };
  const c = [0, 1, 2].map((k) => s.samples.reduce((a, q) => a + q.p[k], 0) / s.samples.length);
  const u = s.camera.eye ? unit(s.camera.eye.map((x, k) => x - c[k])) : s.camera.towards;
  return { ...side, cause: u ? farSideCause(s.clip, c, u) : null };
}
