// The sphere of the slides: a regular tetrahedron whose triangles are subdivided `level` times,
// every new vertex pushed out to the unit sphere (Angel & Shreiner 6.6). Written straight into one
// Float32Array of x,y,z triples: no per-vertex objects, no flatten. Unit sphere at the origin, so
// a vertex position p is also its normal n (slide "Exercise (WP04P1)": n_xyz = p_xyz).
//
// Winding: every triangle is counter-clockwise seen from outside, so gl.CULL_FACE with the
// default gl.frontFace(gl.CCW) removes the far side (the book's own face order is clockwise).

import { MAX_DEVIATION, SHININESS, SHADING_TABLE } from './shading-table.js';

/** The largest level the exercises offer: 12·4^8 = 786,432 vertices, 9.4 MB of positions. */
export const MAX_LEVEL = 8;

/** Vertices of a sphere at a subdivision level: 4 faces · 4^level triangles · 3 vertices. */
export function vertexCount(level) {
  return 12 * 4 ** level;
}

/** Bytes of vertex data (3 float32 per vertex) at a level. */
export function vertexBytes(level) {
  return vertexCount(level) * 3 * Float32Array.BYTES_PER_ELEMENT;
}

const S2 = Math.SQRT2, S6 = Math.sqrt(6);
/**
 * The regular tetrahedron inscribed in the unit sphere: its four corners, and its four faces as
 * corner indices, each listed counter-clockwise seen from outside (the book's order is clockwise).
 */
export const TETRAHEDRON = {
  corners: [[0, 0, -1], [0, (2 * S2) / 3, 1 / 3], [-S6 / 3, -S2 / 3, 1 / 3], [S6 / 3, -S2 / 3, 1 / 3]],
  faces: [[0, 2, 1], [3, 1, 2], [0, 1, 3], [0, 3, 2]],
};
const FACES = TETRAHEDRON.faces.map((face) => face.map((k) => TETRAHEDRON.corners[k]));

let out = null; // the array being filled, and the next free float in it
let at = 0;

function emit(ax, ay, az, bx, by, bz, cx, cy, cz) {
  out[at] = ax; out[at + 1] = ay; out[at + 2] = az;
  out[at + 3] = bx; out[at + 4] = by; out[at + 5] = bz;
  out[at + 6] = cx; out[at + 7] = cy; out[at + 8] = cz;
  at += 9;
}

// Splits triangle abc into four (a ab ac, ab b bc, ac bc c, ab bc ac: the same winding as abc),
// with each edge midpoint normalised onto the unit sphere; scalars only, so nothing is allocated.
function divideTriangle(ax, ay, az, bx, by, bz, cx, cy, cz, level) {
  if (level === 0) {
    emit(ax, ay, az, bx, by, bz, cx, cy, cz);
    return;
  }
  // (Math.sqrt of the sum, not Math.hypot: hypot guards against overflow and is several times slower)
  let x = ax + bx, y = ay + by, z = az + bz, k = 1 / Math.sqrt(x * x + y * y + z * z);
  const abx = x * k, aby = y * k, abz = z * k;
  x = ax + cx; y = ay + cy; z = az + cz; k = 1 / Math.sqrt(x * x + y * y + z * z);
  const acx = x * k, acy = y * k, acz = z * k;
  x = bx + cx; y = by + cy; z = bz + cz; k = 1 / Math.sqrt(x * x + y * y + z * z);
  const bcx = x * k, bcy = y * k, bcz = z * k;
  const n = level - 1;
  divideTriangle(ax, ay, az, abx, aby, abz, acx, acy, acz, n);
  divideTriangle(abx, aby, abz, bx, by, bz, bcx, bcy, bcz, n);
  divideTriangle(acx, acy, acz, bcx, bcy, bcz, cx, cy, cz, n);
  divideTriangle(abx, aby, abz, bcx, bcy, bcz, acx, acy, acz, n);
}

/**
 * Writes the sphere at `level` into `positions` (x,y,z per vertex, from index 0).
 * @param {number} level 0..MAX_LEVEL
 * @param {Float32Array} positions at least 3·vertexCount(level) floats
 * @returns {number} the vertex count
 */
export function tetrahedronSphere(level, positions) {
  if (!Number.isInteger(level) || level < 0 || level > MAX_LEVEL) {
    throw new RangeError(`sphere level must be an integer from 0 to ${MAX_LEVEL}, not ${level}`);
  }
  const count = vertexCount(level);
  if (positions.length < 3 * count) {
    throw new RangeError(`sphere level ${level} needs ${3 * count} floats, the array has ${positions.length}`);
  }
  out = positions;
  at = 0;
  for (const [a, b, c] of FACES) {
    divideTriangle(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], level);
  }
  out = null;
  return count;
}

// Each level is built once per page and kept: all nine together are 4/3 of the largest (12.6 MB).
const built = [];
const queued = new Set();

function build(level) {
  const mesh = new Float32Array(3 * vertexCount(level));
  tetrahedronSphere(level, mesh);
  return mesh;
}

// The levels next to the one shown are built while the browser is idle, so that Subdivide and
// Coarsen only upload (in Node, with no idle callbacks, they are built when asked for). Idle
// means after the click's upload and frame: an idle callback asked for at once can run while the
// upload itself is still awaited (WebGPU's onSubmittedWorkDone leaves the main thread idle) and
// delay the frame the click asked for. A timer, not an animation frame, so no frame is asked for.
const AHEAD_DELAY_MS = 50;
function buildAhead(level) {
  if (typeof requestIdleCallback !== 'function') return;
  for (const next of [level + 1, level - 1]) {
    if (next < 0 || next > MAX_LEVEL || built[next] || queued.has(next)) continue;
    queued.add(next);
    setTimeout(() => requestIdleCallback(() => {
      built[next] ??= build(next);
      queued.delete(next);
    }, { timeout: 1000 }), AHEAD_DELAY_MS);
  }
}

/**
 * The sphere at `level`: built on the first call for that level and kept, and its neighbouring
 * levels built ahead in idle time. The same array comes back every time: do not write into it.
 * @returns {Float32Array} 3·vertexCount(level) floats
 */
export function sphereMesh(level) {
  if (!Number.isInteger(level) || level < 0 || level > MAX_LEVEL) {
    throw new RangeError(`sphere level must be an integer from 0 to ${MAX_LEVEL}, not ${level}`);
  }
  const mesh = built[level] ??= build(level);
  buildAhead(level);
  return mesh;
}

/** For the bench and tests: which levels are built (true) and which are still to come (false). */
export function builtLevels() {
  return Array.from({ length: MAX_LEVEL + 1 }, (_, level) => built[level] !== undefined);
}

/** For the bench: forget every built level, as a page that has just opened. */
export function forgetMeshes() {
  built.length = 0;
}

// The measured numbers chooseLevel rests on are written by `npm run calibrate` (tools/calibrate.js).
export { MAX_DEVIATION, SHININESS, SHADING_TABLE };

/** The material the tables' default rows hold: the exercises' default shininess. */
const DEFAULT_SHININESS = 40;

/**
 * How far a lighting step's shading is off at `level` for shininess `s`, in 8-bit steps (1 =
 * 1/255), from SHADING_TABLE: 'diffuse' (WP04P3), 'gouraud' (WP04P4) or 'phong' (WP04P5). Between
 * two measured shininess values, the larger error of the two (the error does not always grow with
 * s); above the last one, the last row.
 */
export function shadingRmse(shading, level, s = DEFAULT_SHININESS) {
  const table = SHADING_TABLE[shading];
  if (!table) throw new RangeError(`shading must be one of ${Object.keys(SHADING_TABLE).join(', ')}, not ${shading}`);
  if (shading === 'diffuse') return table[level];
  const above = SHININESS.findIndex((x) => x >= s);
  if (above === -1) return table[SHININESS.length - 1][level];
  if (SHININESS[above] === s || above === 0) return table[above][level];
  return Math.max(table[above - 1][level], table[above][level]);
}

/** SHADING_TABLE at the default shininess (s = 40), level by level: { diffuse, gouraud, phong }. */
export const SHADING_RMSE = Object.fromEntries(Object.keys(SHADING_TABLE).map((shading) =>
  [shading, SHADING_TABLE.diffuse.map((_, level) => shadingRmse(shading, level))]));

/**
 * Model no more than the scene needs: the least level whose silhouette is within `tolerancePx`
 * pixels of the true sphere's, for a unit sphere `distance` from the eye seen with a vertical
 * field of view `fovy` (degrees) on a canvas `height` pixels high, and, given a `shading` method,
 * whose shading error (shadingRmse, for the material's `shininess`) is within `toleranceRmse` 8-bit steps.
 * The silhouette's radius on screen is R = f·tan(asin(r/d)) with f = (height/2)/tan(fovy/2);
 * a mesh that falls δ inside the sphere moves it by about δ·dR/dr = δ·f·d²/(d²−1)^(3/2) pixels.
 * @param {{tolerancePx?: number, shading?: 'diffuse' | 'gouraud' | 'phong' | null, shininess?: number, toleranceRmse?: number}} [options]
 * @returns {{level: number, errorPx: number, radiusPx: number, rmse: number | null, limit: 'silhouette' | 'shading' | 'max'}}
 *   errorPx and rmse at that level; limit: what set the level
 */
export function chooseLevel(height, fovy, distance, { tolerancePx = 0.5, shading = null, shininess = DEFAULT_SHININESS, toleranceRmse = 1 } = {}) {
  if (shading !== null && !(shading in SHADING_TABLE)) {
    throw new RangeError(`chooseLevel: shading must be one of ${Object.keys(SHADING_TABLE).join(', ')} or null, not ${shading}`);
  }
  const f = height / 2 / Math.tan((fovy * Math.PI) / 360);
  const d2 = distance * distance;
  const radiusPx = f * Math.tan(Math.asin(Math.min(1, 1 / distance)));
  const pxPerUnit = d2 > 1 ? (f * d2) / Math.pow(d2 - 1, 1.5) : Infinity;
  const rmseAt = (level) => (shading === null ? null : shadingRmse(shading, level, shininess));
  for (let level = 0; level <= MAX_LEVEL; level++) {
    const errorPx = MAX_DEVIATION[level] * pxPerUnit;
    const round = errorPx < tolerancePx;
    const smooth = shading === null || rmseAt(level) <= toleranceRmse;
    if (round && smooth) {
      const limit = level > 0 && MAX_DEVIATION[level - 1] * pxPerUnit < tolerancePx ? 'shading' : 'silhouette';
      return { level, errorPx, radiusPx, rmse: rmseAt(level), limit };
    }
  }
  return { level: MAX_LEVEL, errorPx: MAX_DEVIATION[MAX_LEVEL] * pxPerUnit, radiusPx, rmse: rmseAt(MAX_LEVEL), limit: 'max' };
}
