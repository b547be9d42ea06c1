// Bench only: two other ways to build the same sphere, measured beside common/sphere.js.
//  - classicSphere: the textbook way, arrays of vec4 objects pushed one by one, then flattened;
//  - indexedSphere: shared vertices (2·4^n + 2 instead of 12·4^n) and an index list, the same
//    triangles in the same order and winding, for gl.drawElements.
// And the two level changes a page makes (arriveByClick, arriveCold), for both bench pages.
import { MAX_LEVEL, TETRAHEDRON, builtLevels, forgetMeshes, sphereMesh } from '../common/sphere.js';

const { corners: CORNERS, faces: FACES } = TETRAHEDRON; // counter-clockwise seen from outside

/** The classic way: one [x, y, z, 1] array per vertex, new arrays at every step, then one copy. */
export function classicSphere(level) {
  const points = [];
  const unit = (p) => {
    const l = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return [p[0] / l, p[1] / l, p[2] / l, 1];
  };
  const mix = (a, b) => unit([(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2]);
  const divide = (a, b, c, n) => {
    if (n === 0) {
      points.push(a, b, c);
      return;
    }
    const ab = mix(a, b), ac = mix(a, c), bc = mix(b, c);
    divide(a, ab, ac, n - 1);
    divide(ab, b, bc, n - 1);
    divide(ac, bc, c, n - 1);
    divide(ab, bc, ac, n - 1);
  };
  const v = CORNERS.map((p) => [...p, 1]);
  for (const [a, b, c] of FACES) divide(v[a], v[b], v[c], level);
  // flatten: a new Float32Array from the nested arrays (x, y, z only, as our buffer holds)
  const out = new Float32Array(points.length * 3);
  for (let i = 0; i < points.length; i++) {
    out[3 * i] = points[i][0];
    out[3 * i + 1] = points[i][1];
    out[3 * i + 2] = points[i][2];
  }
  return out;
}

/**
 * Shared vertices: each edge midpoint is made once (looked up by its two end vertices).
 * @returns {{positions: Float32Array, indices: Uint16Array|Uint32Array}}
 */
export function indexedSphere(level) {
  if (level > MAX_LEVEL) throw new RangeError(`level ${level} > ${MAX_LEVEL}`);
  const vertexCount = 2 * 4 ** level + 2; // Euler: V = E − F + 2 = 6·4^n − 4·4^n + 2
  const at = new Float64Array(3 * vertexCount); // built in double precision, as common/sphere.js
  const indices = vertexCount <= 65536 ? new Uint16Array(12 * 4 ** level) : new Uint32Array(12 * 4 ** level);
  let nv = 0, ni = 0;
  const add = (x, y, z) => {
    const k = 1 / Math.sqrt(x * x + y * y + z * z);
    at[3 * nv] = x * k; at[3 * nv + 1] = y * k; at[3 * nv + 2] = z * k;
    return nv++;
  };
  const midpoints = new Map();
  const mid = (a, b) => {
    const key = a < b ? a * vertexCount + b : b * vertexCount + a;
    let m = midpoints.get(key);
    if (m === undefined) {
      m = add(at[3 * a] + at[3 * b], at[3 * a + 1] + at[3 * b + 1], at[3 * a + 2] + at[3 * b + 2]);
      midpoints.set(key, m);
    }
    return m;
  };
  const divide = (a, b, c, n) => {
    if (n === 0) {
      indices[ni++] = a; indices[ni++] = b; indices[ni++] = c;
      return;
    }
    const ab = mid(a, b), ac = mid(a, c), bc = mid(b, c);
    divide(a, ab, ac, n - 1);
    divide(ab, b, bc, n - 1);
    divide(ac, bc, c, n - 1);
    divide(ab, bc, ac, n - 1);
  };
  for (const p of CORNERS) add(p[0], p[1], p[2]);
  for (const [a, b, c] of FACES) divide(a, b, c, level);
  return { positions: Float32Array.from(at), indices };
}

/** Per vertex, the centroid of its triangle (flat shading's one normal per face). */
export function faceCentroids(positions, count, out) {
  for (let t = 0; t < count * 3; t += 9) {
    const x = (positions[t] + positions[t + 3] + positions[t + 6]) / 3;
    const y = (positions[t + 1] + positions[t + 4] + positions[t + 7]) / 3;
    const z = (positions[t + 2] + positions[t + 5] + positions[t + 8]) / 3;
    for (let v = 0; v < 9; v += 3) {
      out[t + v] = x; out[t + v + 1] = y; out[t + v + 2] = z;
    }
  }
  return out;
}

/** Resolves when the browser is next idle. */
export function idle() {
  return new Promise((resolve) => requestIdleCallback(resolve));
}

/**
 * The pause before every timed level change, the same for every way measured: 80 ms (about the
 * least time between two clicks; common/sphere.js builds ahead from 50 ms on), then an idle
 * period. A change timed after a short pause and another after a long one would differ by how
 * long the GPU side took to wake up (0.1 against 0.5 ms here), not by their own work.
 */
export async function settle() {
  await new Promise((resolve) => setTimeout(resolve, 80));
  await idle();
}

/**
 * A click on Subdivide (Coarsen at level 0) as a page just opened makes it, first visit included:
 * forget every built level, show the level before (`show(mesh)` uploads it), let the browser be
 * idle as it is between two clicks, so that common/sphere.js builds `level` ahead, then time the
 * click: `show(sphereMesh(level))` to the end of the upload (`sync`). ms.
 */
export async function arriveByClick(level, show, sync) {
  forgetMeshes();
  show(sphereMesh(level > 0 ? level - 1 : 1));
  await sync();
  for (let k = 0; k < 20 && !builtLevels()[level]; k++) await settle();
  if (!builtLevels()[level]) throw new Error(`level ${level} was not built ahead in 20 pauses between clicks`);
  await settle();
  const t0 = performance.now();
  show(sphereMesh(level));
  await sync();
  return performance.now() - t0;
}

/** A jump to a level nobody built yet (the URL, or a level no click led next to): built on the spot. ms. */
export async function arriveCold(level, show, sync) {
  forgetMeshes();
  await settle();
  const t0 = performance.now();
  show(sphereMesh(level));
  await sync();
  return performance.now() - t0;
}
