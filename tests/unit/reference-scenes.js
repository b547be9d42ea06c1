// Scenes and helpers shared by the reference renderer's unit tests (reference-*.test.js).
// The camera of most tests: eye (0, 0, 3) looking at the unit sphere's centre, fovy 45°, so
// tan(fovy/2) = tan 22.5° = √2 − 1 ≈ 0.414214, and r = (1, 0, 0), u = (0, 1, 0), f = (0, 0, −1).
import assert from 'node:assert/strict';
import { toRGBA8 } from '../../tools/reference/png.js';

export const camera = { eye: [0, 0, 3], at: [0, 0, 0], up: [0, 1, 0], fovy: 45, aspect: 1, near: 0.1, far: 100 };
/** A lit scene: directional light from the eye's side (position (0,0,−1,0), so w_i = (0,0,1)). */
export const lit = (over = {}) => ({
  exercise: 'WP04P5', camera, shading: 'phong', model: 'phong', depthTest: true, cullFace: true, frontFace: 'ccw',
  light: { position: [0, 0, -1, 0], Le: 1, La: 0.1 },
  material: { kd: 0.5, ka: 0.5, ks: 0.2, s: 40 },
  ...over,
});
export const normals = (over = {}) => ({ exercise: 'WP04P1', camera, shading: 'normals', ...over });
/** The colour of pixel (i, j) of a reference, row 0 at the top. */
export const at = (ref, i, j) => [0, 1, 2].map((c) => ref.rgb[3 * (j * ref.width + i) + c]);
export const covered = (ref, i, j) => ref.coverage[j * ref.width + i] === 1;
export function close(actual, expected, eps = 1e-12, what = '') {
  const a = [].concat(actual), e = [].concat(expected);
  assert.equal(a.length, e.length);
  a.forEach((v, k) => assert.ok(Math.abs(v - e[k]) <= eps, `${what} channel ${k}: ${v}, expected ${e[k]} ± ${eps}`));
}
export const grey = (v) => [v, v, v];
/** The reference as an image object, as pngjs decodes a screenshot. */
export const asImage = (ref) => ({ width: ref.width, height: ref.height, data: Buffer.from(toRGBA8(ref).buffer) });
