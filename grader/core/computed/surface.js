// The page's own surface per pixel (grader/browser/surface.js draws it again from what the page
// sent), made ready for the lighting's fits: each sample's position and unit normal in the model's
// space, whether it is a front face, and w_o; the camera fitted exactly from where the page's own
// matrices put each position (gl_Position = P V M p is linear in p: its 4×4 matrix is solved from
// the samples). No guess from the silhouette: where the page could not be drawn again, `why` says so.
import { solveNormal } from '../measure/linear.js';
import { dot, cross, unit } from '../measure/vectors.js';
import { CHANNEL_MAX, HALF_TURN } from '../units.js';
import { memo } from './memo.js';

/** A guard against dividing by (nearly) zero. */
const GUARD = 1e-9;

/** x of A x = b for a small square system (linear.js's elimination); null where singular. */
export const solve = (A, b) => solveNormal(A.flat(), b, b.length);

/**
 * The matrix that takes a position to gl_Position (P V M as the page multiplied it), row by row,
 * fitted by least squares to the samples ([p, clip] pairs); null where the samples do not fix it.
 */
export function clipMatrix(samples) {
  // one normal matrix [p, 1]ᵀ[p, 1] for the four rows; a right-hand side a row
  const AtA = [
      [0, 0, 0, 0],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
    ],
    Atb = [
      [0, 0, 0, 0],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
      [0, 0, 0, 0],
    ];
  for (const { p, clip } of samples) {
    const x = [p[0], p[1], p[2], 1];
    for (let i = 0; i < 4; i++) {
      for (let r = 0; r < 4; r++) Atb[r][i] += x[i] * clip[r];
      for (let j = 0; j < 4; j++) AtA[i][j] += x[i] * x[j];
    }
  }
  const rows = Atb.map((b) => solve(AtA, b));
  return rows.every(Boolean) ? rows : null;
}

/**
 * The camera in the model's space from the clip matrix A: its centre (`eye`, where x, y and w of
 * A [eye, 1] are 0) or, for an orthographic projection, the direction towards it (`towards`); and
 * its axes (`right`, `up`, `back`: the eye space's x, y and z in the model's space).
 */
export function cameraOfClip(A) {
  const [A0, A1, A2, A3] = A.map((r) => r.slice(0, 3));
  const eye = Math.hypot(...A3) > GUARD * Math.hypot(...A2)
    ? solve([A0, A1, A3], [-A[0][3], -A[1][3], -A[3][3]]) : null;
  // eye space: x along row 0, y along row 1 (a perspective's w row is −z; an orthographic's z row is −z times a scale)
  const back = unit(eye ? A3.map((x) => -x) : A2.map((x) => -x));
  const right = back && unit(cross(cross(back, A0), back));
  const up = back && right && cross(back, right);
  return { eye, towards: eye ? null : back, right, up, back };
}

/**
 * The surface as the artifact keeps it (facts.surface: { width, height, position, normal, box, clip
 * (the 4×4 P·V·M, rows), normals, points }, the last two the names of its pictures in `images`; or { why }) as { width,
 * height, position, normal, camera, clip, samples: [{ x, y, p, n, front, w_o }] } for every step-th
 * pixel it covers (about the rubric's surfacePixels), or { why }. n is the normal attribute, else the position, as the
 * page interpolated it, normalised; w_o points from the position to the camera. Read once a
 * surface, its pictures and the rubric (the side seen, the lighting and the highlight's place read it).
 */
export const surfaceOf = memo((surface, images, thresholds) => {
  if (!surface || surface.why) return { why: surface ? surface.why : 'the surface was not read' };
  const nImg = images[surface.normals], pImg = images[surface.points];
  if (!nImg || !pImg) return { why: 'the surface\'s pictures are missing from the artifact' };
  const { clip } = surface;
  if (!clip) return { why: 'where the page\'s matrices put its positions was not read' };
  const camera = cameraOfClip(clip);
  if (!camera.back) return { why: 'the camera could not be found from the page\'s matrices' };
  const { width, height } = surface, [lo, hi] = surface.box;
  const step = Math.max(1, Math.floor(Math.sqrt((surface.covered || width * height) / thresholds.surfacePixels)));
  const samples = [];
  for (let y = 0; y < height; y += step) {
    for (let x = 0; x < width; x += step) {
      const o = 4 * (y * width + x), a = nImg.data[o + 3];
      if (!a) continue;
      const n = unit([0, 1, 2].map((k) => (2 * nImg.data[o + k]) / CHANNEL_MAX - 1));
      if (!n) continue;
      const p = [0, 1, 2].map((k) => lo[k] + ((hi[k] - lo[k]) * pImg.data[o + k]) / CHANNEL_MAX);
      const w_o = camera.eye
        ? unit([camera.eye[0] - p[0], camera.eye[1] - p[1], camera.eye[2] - p[2]])
        : camera.towards;
      samples.push({ x, y, p, n, front: a === CHANNEL_MAX, w_o });
    }
  }
  return { width, height, position: surface.position, normal: surface.normal, clip, camera, samples };
});

/** The angle in degrees between unit vectors a and b. */
export const degreesBetween = (a, b) => (Math.acos(Math.max(-1, Math.min(1, dot(a, b)))) * HALF_TURN) / Math.PI;

/** The share of surface `s`'s samples that lie inside the outline `an` of picture `img` (the surface is that picture's view where nearly all do). */
export const insideShare = (s, img, an) =>
  s.samples.filter((q) => an.mask[q.y * img.width + q.x]).length / Math.max(1, s.samples.length);
