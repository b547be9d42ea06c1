// Lighting tinted by the normal colour: students keep WP04P1's colour 0.5·n + 0.5 as the material
// (albedo(n) × lighting) or mix it in (0.5·(0.5·n + 0.5) + 0.5·L_o). The hue then turns with the
// normal, and a brightness fit of a + b·max(n·w_i, 0) reads the albedo's slope as light: the light
// and the highlight's place go astray. Here: whether the hue follows the normal (the colour-
// independent part of the picture: each channel's share of the brightness), and the diffuse fit of
// the picture with a brightness-albedo that is linear in n divided out (fitted in turns with the
// lighting), or with a normal colouring added to the lighting taken out (tint-added.js).
import { luminance } from './samples.js';
import { diffuseFit } from './diffuse.js';
import { highlightSeen } from './highlight.js';
import { leastSquares, solveNormal, symmetricEigenvalues3 } from './linear.js';
import { addedTintFit, addedClearly } from './tint-added.js';
import { HALF_TURN, MAT4_ENTRIES } from '../units.js';

/** Guards against dividing by (nearly) zero. */
const SINGULAR = 1e-12, TINY = 1e-6;
/** The albedo's floor, which keeps a division by it finite (the mechanics of a fit). */
const ALBEDO_FLOOR = 0.05;

// a pixel clipped at white (a channel at clippedLevel) or nearly black (its channels' sum at darkSum) says little of its hue
const usable = (s, thresholds) =>
  Math.max(...s.c) < thresholds.clippedLevel && s.c[0] + s.c[1] + s.c[2] > thresholds.darkSum;

/**
 * Does the hue follow the normal? Each channel's share of the brightness (c_k / Σc) fitted as an
 * affine function of the normal: { spread (the shares' RMS variation), r2 (how much of it the
 * normal explains), turn }, or null (too few usable pixels). A plain material has one hue (a white
 * highlight aside): no spread. A hue that changes with the lighting alone (an ambient colour
 * other than the diffuse one) changes along the light's direction only; the P1 colour turns with
 * the normal in two directions (the shares sum to 1: at most two), so `turn` is the second
 * singular value of the shares' slopes.
 */
export function hueByNormal(pts, thresholds) {
  const use = pts.filter((s) => usable(s, thresholds));
  if (use.length < thresholds.minModelSamples) return null;
  const rows = use.map((s) => [1, s.n[0], s.n[1], s.n[2]]);
  let sse = 0, sst = 0;
  const slopes = [];
  for (let k = 0; k < 3; k++) {
    const ys = use.map((s) => s.c[k] / (s.c[0] + s.c[1] + s.c[2]));
    const mean = ys.reduce((a, v) => a + v, 0) / ys.length;
    const x = leastSquares(rows, ys);
    slopes.push(x ? x.slice(1) : [0, 0, 0]);
    for (let i = 0; i < ys.length; i++) {
      sst += (ys[i] - mean) ** 2;
      if (x) sse += (ys[i] - rows[i].reduce((a, v, j) => a + v * x[j], 0)) ** 2;
    }
  }
  const M = [0, 1, 2].map((i) => [0, 1, 2].map((j) => slopes.reduce((a, r) => a + r[i] * r[j], 0)));
  const ev = symmetricEigenvalues3(M);
  return {
    spread: Math.sqrt(sst / (3 * use.length)),
    r2: sst > SINGULAR ? 1 - sse / sst : 0,
    turn: Math.sqrt(Math.max(0, ev[1])),
  };
}

/** Is the picture tinted by the normal (hueByNormal: a hue that turns with the normal by tintTurn, explained by it to tintR2)? */
export const tintedByNormal = (hue, thresholds) =>
  !!hue && hue.turn >= thresholds.tintTurn && hue.r2 >= thresholds.tintR2;

/**
 * The albedo's slope q and the lighting (a, b) for a fixed light `l`: brightness ≈ (1 + q·n)·(a +
 * b·max(n·l, 0)) over the samples `use`, each factor solved by least squares with the other fixed,
 * `iterations` times (cheap: no search over directions here).
 */
function albedoAndLighting(use, l, q0, a0, b0, iterations) {
  let q = q0, a = a0, b = b0;
  const m = use.length;
  const xs = new Float64Array(m);
  for (let i = 0; i < m; i++) { const n = use[i].n; xs[i] = Math.max(0, n[0] * l[0] + n[1] * l[1] + n[2] * l[2]); }
  const N4 = new Float64Array(MAT4_ENTRIES), v4 = new Float64Array(4);
  const N2 = new Float64Array(4), v2 = new Float64Array(2);
  const r = new Float64Array(4);
  for (let it = 0; it < iterations; it++) {
    // the albedo with the lighting fixed: y ≈ L·(α + α q·n)
    N4.fill(0); v4.fill(0);
    for (let i = 0; i < m; i++) {
      const { n, y } = use[i], L = a + b * xs[i];
      r[0] = L; r[1] = L * n[0]; r[2] = L * n[1]; r[3] = L * n[2];
      for (let j = 0; j < 4; j++) { v4[j] += r[j] * y; for (let k = 0; k < 4; k++) N4[j * 4 + k] += r[j] * r[k]; }
    }
    const x1 = solveNormal(N4, v4, 4);
    if (!x1 || x1[0] <= TINY) break;
    q = [x1[1] / x1[0], x1[2] / x1[0], x1[3] / x1[0]];
    // the lighting with the albedo fixed: y ≈ A·(a + b x)
    N2.fill(0); v2.fill(0);
    for (let i = 0; i < m; i++) {
      const { n, y } = use[i], A = Math.max(0.05, 1 + q[0] * n[0] + q[1] * n[1] + q[2] * n[2]), x = xs[i];
      N2[0] += A * A; N2[1] += A * A * x; N2[3] += A * A * x * x; v2[0] += A * y; v2[1] += A * x * y;
    }
    N2[2] = N2[1];
    const x2 = solveNormal(N2, v2, 2);
    if (!x2) break;
    [a, b] = x2;
  }
  return q;
}

/**
 * The diffuse fit of a picture tinted by the normal: brightness = A(n)·(a + b·max(n·w_i, 0)) with
 * A(n) = 1 + q·n: in turns, the lighting by diffuseFit on the brightness with A divided out (its
 * light direction searched, the highlight left out), then A and the lighting for that light by
 * least squares (albedoAndLighting). diffuseFit's result on the de-tinted samples, with
 * `albedoSlope` |q|; null where it cannot be fitted. `plain`: diffuseFit(pts, thresholds), where the caller has it.
 */
export function detintedFit(pts, thresholds, plain = diffuseFit(pts, thresholds)) {
  let q = [0, 0, 0];
  const albedo = () => (n) => Math.max(ALBEDO_FLOOR, 1 + q[0] * n[0] + q[1] * n[1] + q[2] * n[2]);
  // (with q = 0, A is 1 and the samples divide out to themselves: the fit is `plain`, diffuseFit's
  // on the samples as they are, to the last bit)
  const fitWith = (A) =>
    q.every((v) => v === 0)
      ? plain
      : diffuseFit(
          pts.map((s) => ({ ...s, c: s.c.map((v) => v / A(s.n)) })),
          thresholds,
        );
  for (let round = 0; round < thresholds.tintRounds; round++) {
    const A = albedo();
    const fit = fitWith(A);
    if (!fit) return null;
    const L = (n) =>
      fit.ambient + fit.diffuse * Math.max(0, n[0] * fit.light[0] + n[1] * fit.light[1] + n[2] * fit.light[2]);
    // the pixels the lighting fits (no highlight, nothing clipped, not black)
    const use = pts
      .filter(
        (s) =>
          usable(s, thresholds) &&
          L(s.n) >= thresholds.tintLitLevel &&
          luminance(s.c) - L(s.n) * A(s.n) <= thresholds.highlightFitMargin,
      )
      .map((s) => ({ n: s.n, y: luminance(s.c) }));
    if (use.length < thresholds.minFitSamples) break;
    q = albedoAndLighting(use, fit.light, q, fit.ambient, fit.diffuse, thresholds.tintIterations);
  }
  const fit = fitWith(albedo());
  return fit && { ...fit, albedoSlope: Math.hypot(...q) };
}

const angleOf = (a, b) =>
  (HALF_TURN / Math.PI) * Math.acos(Math.max(-1, Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));

/**
 * The shading fit every reader of a lit picture uses: diffuseFit, and where the hue turns with the
 * normal (tintedByNormal) the de-tinted fit where it explains the picture better (and still sees
 * a highlight the plain fit sees). A tinted fit
 * carries `tint`: { turn, slope (the albedo's brightness slope), lightShift (degrees between the
 * plain and the de-tinted fits' lights), sure }: sure where the fit is clean (R² ≥ diffuseR2) and
 * either the plain fit is kept (dividing the tint out explains no more) or the albedo's brightness
 * is nearly even (slope < tintSlope) and both fits put the light within tintLightDegrees of each
 * other; where it is not, the fitted light cannot place a highlight. A normal colouring added to
 * the lighting (addedClearly) is taken out instead (addedTintFit): `tint.added` its share.
 */
export function shadeFit(pts, thresholds) {
  const plain = diffuseFit(pts, thresholds);
  if (!plain) return null;
  const hue = hueByNormal(pts, thresholds);
  if (!tintedByNormal(hue, thresholds)) return plain;
  // a normal colouring added to the lighting: its fit, read as any clean fit is
  const added = addedTintFit(pts, thresholds);
  if (addedClearly(added, thresholds)) {
    return {
      ...added,
      tint: { turn: hue.turn, added: added.added.share, sure: added.r2 >= thresholds.diffuseR2, plain },
    };
  }
  const de = detintedFit(pts, thresholds, plain);
  // the de-tinted fit where it explains the picture better, and does not lose a highlight the plain one sees
  const fit =
    de && de.r2 >= plain.r2 && (highlightSeen(de, thresholds) || !highlightSeen(plain, thresholds)) ? de : plain;
  const lightShift = de ? angleOf(de.light, plain.light) : null;
  const slope = de ? de.albedoSlope : null;
  // the plain fit kept (the tint divided out explains no more: a tint added, not multiplied) is read as any fit is
  const sure =
    fit.r2 >= thresholds.diffuseR2 &&
    (fit === plain || (slope < thresholds.tintSlope && lightShift <= thresholds.tintLightDegrees));
  return { ...fit, tint: { turn: hue.turn, slope, lightShift, sure, plain } };
}
