// Surfaces as grader/browser/surface.js reads them from a page, made here from gl-matrix's
// matrices and the exact unit sphere, for the unit tests of core/computed/surface.js and
// core/measure/surface-fit.js.
import { mat4, vec4 } from 'gl-matrix';
import { clipMatrix } from '../../grader/core/computed/surface.js';

/**
 * A surface as grader/browser/surface.js gives it, at 64×64: a unit sphere seen through `pv` from
 * `eye`, each pixel the sphere point it shows (its normal `normal(p)`, else p), with fit samples;
 * and `picture`, each pixel `shade(p, channel)` (white where nothing is drawn).
 */
export function surfaceUnder(pv, eye, { normal = null, shade = null } = {}) {
  const W = 64, normals = { width: W, height: W, data: new Uint8Array(W * W * 4) }, points = { width: W, height: W, data: new Uint8Array(W * W * 4) };
  const fit = [];
  let covered = 0;
  const picture = { width: W, height: W, data: new Uint8Array(W * W * 4).fill(255) };
  const inv = mat4.invert(mat4.create(), pv);
  for (let y = 0; y < W; y++) {
    for (let x = 0; x < W; x++) {
      // the pixel's ray: the points of its centre at NDC depth −1 and 1
      const ndc = [(2 * (x + 0.5)) / W - 1, 1 - (2 * (y + 0.5)) / W];
      const a = vec4.transformMat4(vec4.create(), [...ndc, -1, 1], inv), b = vec4.transformMat4(vec4.create(), [...ndc, 1, 1], inv);
      const o = [0, 1, 2].map((k) => a[k] / a[3]), e = [0, 1, 2].map((k) => b[k] / b[3]);
      const d = [0, 1, 2].map((k) => e[k] - o[k]), dd = d[0] ** 2 + d[1] ** 2 + d[2] ** 2;
      const od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2], oo = o[0] ** 2 + o[1] ** 2 + o[2] ** 2;
      const disc = od * od - dd * (oo - 1);
      if (disc < 0) continue;
      const t = (-od - Math.sqrt(disc)) / dd;
      const p = [0, 1, 2].map((k) => o[k] + t * d[k]);
      const n = normal ? normal(p) : p, l = Math.hypot(...n);
      const i = 4 * (y * W + x);
      for (let k = 0; k < 3; k++) {
        normals.data[i + k] = Math.round((0.5 * (n[k] / l) + 0.5) * 255);
        points.data[i + k] = Math.round(((p[k] + 1) / 2) * 255);
      }
      normals.data[i + 3] = points.data[i + 3] = 255;
      covered++;
      if (shade) for (let k = 0; k < 3; k++) picture.data[i + k] = Math.round(Math.max(0, Math.min(1, shade(p, k))) * 255);
      if ((x + y) % 7 === 0) fit.push([...p, ...vec4.transformMat4(vec4.create(), [...p, 1], pv)]);
    }
  }
  return { facts: { width: W, height: W, position: 'a', normal: normal ? 'n' : null, box: [[-1, -1, -1], [1, 1, 1]], covered, fit, clip: clipMatrix(fit.map((f) => ({ p: f.slice(0, 3), clip: f.slice(3, 7) }))), normals: 'n', points: 'p' }, images: { n: normals, p: points }, picture };
}

