// The camera as the page sent it: the view matrix among the matrices it sends that change while the
// orbit runs with no control touched (sentAnimated, read by grader/browser/sent.js), and how far it
// turned between two views. Pure: the orbit's gathering reads it to sample until the camera has
// turned enough to tell a light in the world from one that moves with the camera, and the orbit's
// audit to weigh the lit side's turn against the camera's.
import { HALF_TURN, MAT4_ENTRIES, MILLIONTHS } from '../units.js';

/** The animated 4×4 matrices in `sent` ({ key: [16 numbers] }), or null where none is. */
export function cameraOf(sent, animated) {
  if (!sent || !animated || !animated.length) return null;
  const out = {};
  for (const k of animated) {
    const v = String(sent[k] || '').split(',').map(Number);
    if (v.length === MAT4_ENTRIES && v.every(Number.isFinite)) {
      out[k] = v.map((x) => Math.round(x * MILLIONTHS) / MILLIONTHS);
    }
  }
  return Object.keys(out).length ? out : null;
}

/** The 3×3 part of a column-major 4×4 matrix, as rows, scaled to unit rows; null where it is no rotation (a projection in it). */
function rotationOf(m, tolerance) {
  const r = [[m[0], m[4], m[8]], [m[1], m[5], m[9]], [m[2], m[6], m[10]]];
  const scale = Math.cbrt(
    Math.abs(
      r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
        r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
        r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]),
    ),
  );
  if (!(scale > 0)) return null;
  const u = r.map((row) => row.map((x) => x / scale));
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) {
      const dot = u[i][0] * u[j][0] + u[i][1] * u[j][1] + u[i][2] * u[j][2];
      if (Math.abs(dot - (i === j ? 1 : 0)) > tolerance) return null;
    }
  }
  return u;
}

/** The angle, in degrees, of the rotation from `a` to `b` (3×3, rows). */
function turnBetween(a, b) {
  let trace = 0;
  for (let i = 0; i < 3; i++) for (let k = 0; k < 3; k++) trace += a[i][k] * b[i][k]; // trace(a bᵀ)
  return (HALF_TURN / Math.PI) * Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2)));
}

/**
 * The camera's rotation (world to eye, 3×3 rows) in each of `cameras` (cameraOf of each view, in
 * order), from the one matrix key that is a rotation in every view (a view or model-view matrix; a
 * combined P·V is not read); null where a view has no camera or no such matrix is.
 */
export function cameraRotations(cameras, tolerance) {
  if (cameras.length < 2 || cameras.some((c) => !c)) return null;
  for (const key of Object.keys(cameras[0])) {
    const rs = cameras.map((c) => c[key] && rotationOf(c[key], tolerance));
    if (!rs.some((r) => !r)) return rs;
  }
  return null;
}

/**
 * How far the camera travelled over `cameras`, in order: the turns from each to the next added up,
 * in degrees; null where unknown. A turn is the least rotation between two views, so the path is
 * never longer than the camera's own: a path of a full turn is at least one time round.
 */
export function cameraPath(cameras, tolerance) {
  const rs = cameraRotations(cameras, tolerance);
  return rs && rs.slice(1).reduce((sum, r, k) => sum + turnBetween(rs[k], r), 0);
}

/** How far the camera turned over `cameras`: the largest turn from the first, in degrees; null where unknown. */
export function cameraTurn(cameras, tolerance) {
  return rotationsTurn(cameraRotations(cameras.filter(Boolean), tolerance));
}

/** The largest turn from the first of `rotations` (cameraRotations), in degrees; null where there are none. */
export function rotationsTurn(rotations) {
  return rotations && Math.max(...rotations.slice(1).map((r) => turnBetween(rotations[0], r)));
}

/** A direction `v` seen in the eye space of rotation `from`, as it would be seen from `to` if it stayed in the world: to·fromᵀ·v. */
export function staysInWorld(from, to, v) {
  const world = [0, 1, 2].map((k) => from[0][k] * v[0] + from[1][k] * v[1] + from[2][k] * v[2]);
  return to.map((row) => row[0] * world[0] + row[1] * world[1] + row[2] * world[2]);
}
