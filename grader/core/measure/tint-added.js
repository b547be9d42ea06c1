// A normal colouring added to the lighting, not multiplied: students mix WP04P1's colour into a lit
// step as 0.5·p + 0.5·L_o or 0.5·(0.5·n + 0.5) + 0.5·L_o. The k-th channel then carries the k-th
// component of the normal in the space the page coloured it (the model's, turned by the camera
// into the view's), c = α·R·n + β·L + γ. A brightness fit reads α·(R·n) averaged over the channels
// as light, and where L is near 1 the colours decode to unit normals as WP04P1's do; the channels
// tell the two apart. Here: R and α from how the channels differ (the lighting, the same in each
// channel of a grey material, cancels there), then the light by diffuseFit on the picture with
// α·R·n taken out, and α again with the lighting, in turns.
import { diffuseFit } from './diffuse.js';
import { leastSquares, symmetricEigenvalues3 } from './linear.js';
import { dot, cross } from './vectors.js';
import { HALF_TURN } from '../units.js';

/** Guards against dividing by (nearly) zero. */
const GUARD = 1e-9, SINGULAR = 1e-12, TINY = 1e-6;

const det = (A) => dot(A[0], cross(A[1], A[2]));
const clipped = (s, thresholds) =>
  Math.min(...s.c) <= thresholds.blackLevel || Math.max(...s.c) >= thresholds.clippedLevel;

/**
 * The normal colouring's turn R (3×3, rows) and share α from the channels' differences from
 * their mean, Δ_k = c_k − c̄ = α·((R·n)_k − mean) + const, fitted by least squares on [1, n]: the
 * slopes D are α·R with its column means taken out, so DᵀD = α²·I − 3·m·mᵀ, whose null direction
 * gives the means m back (the sign that keeps R a rotation). { R, alpha, even (the smaller of
 * D's two singular values over the larger: 1 for a turned normal) }, or null.
 */
function normalTurn(use) {
  const rows = use.map((s) => [1, s.n[0], s.n[1], s.n[2]]);
  const D = [];
  for (let k = 0; k < 3; k++) {
    const x = leastSquares(rows, use.map((s) => s.c[k] - (s.c[0] + s.c[1] + s.c[2]) / 3));
    if (!x) return null;
    D.push(x.slice(1));
  }
  const M = [0, 1, 2].map((i) => [0, 1, 2].map((j) => D.reduce((a, r) => a + r[i] * r[j], 0)));
  const [l1, l2] = symmetricEigenvalues3(M);
  if (!(l1 > GUARD)) return null;
  const alpha = Math.sqrt((l1 + l2) / 2);
  const u = [cross(D[0], D[1]), cross(D[0], D[2]), cross(D[1], D[2])].reduce((a, b) => (dot(b, b) > dot(a, a) ? b : a));
  const len = Math.sqrt(dot(u, u));
  if (len < SINGULAR) return null;
  for (const sign of [1, -1]) {
    const m = u.map((v) => (sign * alpha * v) / (len * Math.sqrt(3)));
    const A = D.map((r) => r.map((v, j) => v + m[j]));
    if (det(A) > 0) return { R: A.map((r) => r.map((v) => v / alpha)), alpha, even: Math.sqrt(Math.max(0, l2) / l1) };
  }
  return null;
}

/** The channels' R² over `use` for c_k = γ_k + β_k·lit + α·m_k (+ τ·m_k·lit where `times`), α = `alpha` fixed where given. */
function channelsR2(use, lit, turned, { alpha = null, times = false } = {}) {
  const rows = [], ys = [];
  for (const s of use) {
    const L = lit(s.n), m = turned(s.n);
    for (let k = 0; k < 3; k++) {
      const r = [0, 0, 0, 0, 0, 0];
      r[k] = 1;
      r[3 + k] = L;
      if (alpha === null) r.push(m[k]);
      if (times) r.push(m[k] * L);
      rows.push(r);
      ys.push(alpha === null ? s.c[k] : s.c[k] - alpha * m[k]);
    }
  }
  const x = leastSquares(rows, ys);
  if (!x) return { r2: 0, x: null };
  let sse = 0, sst = 0;
  for (let k = 0; k < 3; k++) {
    const mean = use.reduce((a, s) => a + s.c[k], 0) / use.length;
    for (let i = k; i < ys.length; i += 3) sst += (use[(i - k) / 3].c[k] - mean) ** 2;
  }
  for (let i = 0; i < ys.length; i++) sse += (ys[i] - rows[i].reduce((a, v, j) => a + v * x[j], 0)) ** 2;
  return { r2: sst > SINGULAR ? 1 - sse / sst : 0, x };
}

/**
 * The fit of a picture whose colour is the lighting with a normal colouring added: diffuseFit's
 * result on the picture with α·R·n taken out (pixels clipped at 0 or 1 in a channel only say the
 * sum passed there: out of that fit, kept for the highlight), with `added`: { share: α, turn (R's
 * angle, degrees), even, r2 (the channels' R² of the added model), r2Without (the same lighting,
 * nothing added), times (with a term m_k·lit beside α·m_k, its share of α: a P1 colour that
 * multiplies the lighting, as a material does, gives about diffuse/ambient, one added about 0) };
 * null where it cannot be fitted.
 */
export function addedTintFit(pts, thresholds) {
  const use0 = pts.filter((s) => !clipped(s, thresholds));
  if (use0.length < thresholds.minModelSamples) return null;
  const nt = normalTurn(use0);
  if (!nt) return null;
  const { R } = nt;
  const turned = (n) => R.map((r) => dot(r, n));
  let alpha = nt.alpha, fit = null, lit = null, use = null;
  for (let round = 0; round < thresholds.addedRounds; round++) {
    const rest = pts.map((s) => {
      const m = turned(s.n);
      return { ...s, clipped: clipped(s, thresholds), c: s.c.map((v, k) => v - alpha * m[k]) };
    });
    fit = diffuseFit(rest, thresholds);
    if (!fit) return null;
    const l = fit.light, f = fit;
    lit = (n) => Math.max(0, dot(n, l));
    use = pts.filter(
      (s, i) => !rest[i].clipped && rest[i].y - (f.ambient + f.diffuse * lit(s.n)) < thresholds.highlightFitMargin,
    );
    if (use.length < thresholds.minFitSamples) return null;
    const { x } = channelsR2(use, lit, turned);
    if (!x) return null;
    alpha = x[6];
  }
  const r2 = channelsR2(use, lit, turned).r2;
  const both = channelsR2(use, lit, turned, { times: true });
  const turn = (HALF_TURN / Math.PI) * Math.acos(Math.max(-1, Math.min(1, (R[0][0] + R[1][1] + R[2][2] - 1) / 2)));
  return {
    ...fit,
    added: {
      share: alpha,
      turn,
      even: nt.even,
      r2,
      r2Without: channelsR2(use, lit, turned, { alpha: 0 }).r2,
      times: both.x ? both.x[7] / Math.max(TINY, Math.abs(both.x[6])) : null,
    },
  };
}

/**
 * Does addedTintFit's `fit` read the picture as a normal colouring added to the lighting: a share
 * of at least addedShare, of a turned normal (its two singular values within addedEven), the
 * channels explained to addedR2, what is left unexplained shrunk addedShrink-fold from nothing added, a part that multiplies
 * the lighting (`times`) within addedTimesShare of it, and lighting left when it is taken out (the
 * rest shaded by evenSpread at least, as a lit picture must be, fitted to diffuseR2: WP04P1's colours alone leave a flat rest)?
 */
export const addedClearly = (fit, thresholds) =>
  !!fit &&
  fit.added.share >= thresholds.addedShare &&
  fit.added.even >= thresholds.addedEven &&
  fit.added.r2 >= thresholds.addedR2 &&
  1 - fit.added.r2Without >= thresholds.addedShrink * (1 - fit.added.r2) &&
  Math.abs(fit.added.times) <= thresholds.addedTimesShare &&
  fit.spread >= thresholds.evenSpread &&
  fit.r2 >= thresholds.diffuseR2;
