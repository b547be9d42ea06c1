// P3–P5: a point light at a fitted distance, with and without the 1/r² fall-off, and which of the
// two models a picture clearly shows.
import { DIRS } from './directions.js';
import { luminance, sameMask } from './samples.js';
import { highlightOf } from './highlight.js';
import { lineFit } from './linear.js';

/** A guard against dividing by (nearly) zero. */
const GUARD = 1e-12;
/** The refinement (the mechanics of a search): its first step, the step it stops before, and the distances it keeps within. */
const REFINE_FIRST = 0.1, REFINE_LAST = 0.005, NEAREST = 1.05, FARTHEST = 1e4;

/**
 * P3–P5: is the light a point light, and does it fall off as 1/r² (the slides: L_i = I/‖p_ℓ − x‖²)?
 * Brightness is fitted by a + b·max(n·w_i, 0)·g over the sphere seen as a unit sphere (x = n, the
 * normals of perspectiveSamples), the light at p_ℓ = d·l (d in sphere radii, from the centre), w_i = normalize(p_ℓ − x),
 * with g = 1/‖p_ℓ − x‖² (fall-off) or g = 1 (none). Both models hold a directional light (d → ∞),
 * so a far or directional light fits both alike: only a near light tells them apart. Pixels above
 * both fits (a highlight) and clipped ones are left out. Returns the best of each model. `thresholds`: the
 * rubric's thresholds; `around` a direction (only light directions within the cone whose cosine is
 * pointLightConeCosine, 60°, are tried) or null.
 */
export function pointLightFit(pts, thresholds, around = null) {
  const use0 = pts.map((s) => Math.max(...s.c) < thresholds.clippedLevel); // (a channel clipped at white says nothing of the fall-off)
  if (use0.filter(Boolean).length < thresholds.minModelSamples) return null;
  for (const s of pts) s.y = luminance(s.c);
  const F = flat(pts);
  let use = use0;
  let none = null, inv = null;
  const dirs = DIRS.filter(
    (l) => !around || l[0] * around[0] + l[1] * around[1] + l[2] * around[2] > thresholds.pointLightConeCosine,
  );
  for (let pass = 0; pass < 2; pass++) {
    const coarse = grid(F, use, dirs);
    none = search(F, use, false, coarse.none);
    inv = search(F, use, true, coarse.inv);
    if (!none || !inv) return null;
    if (pass === 0) {
      const margin = thresholds.highlightFitMargin;
      const left = pts.map(
        (s, i) => use0[i] && Math.min(s.y - none.a - none.b * none.xs[i], s.y - inv.a - inv.b * inv.xs[i]) < margin,
      );
      // no pixel above both fits: the second pass would fit the same pixels to the same numbers
      if (sameMask(left, use)) break;
      use = left;
    }
  }
  const used = use.reduce((a, v) => a + v, 0);
  const mean = pts.reduce((a, s, i) => a + (use[i] ? s.y : 0), 0) / used;
  const sst = pts.reduce((a, s, i) => a + (use[i] ? (s.y - mean) ** 2 : 0), 0);
  const brief = (f) => {
    const model = { a: f.a, b: f.b, l: f.l, d: f.d, falloff: f.falloff };
    const hl = highlightOf(pts, (n) => pointLightPredict(n, model), thresholds);
    return {
      distance: f.d,
      light: f.l,
      r2: sst > GUARD ? 1 - f.sse / sst : 0,
      rms: Math.sqrt(f.sse / used),
      model,
      highlightPeak: hl.peak,
      highlightRise: hl.rise,
      highlightShare: hl.bright / pts.length,
      highlightNormal: hl.normal,
    };
  };
  return { falloff: brief(inv), none: brief(none), fitted: used / pts.length };
}

/** The distances tried (in sphere radii from the centre; 1e4: as good as directional). */
const DIST = [1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 7, 10, 20, 1e4];

/** The samples as flat arrays (their normals and brightness), read by every fit below. */
function flat(pts) {
  const m = pts.length,
    nx = new Float64Array(m),
    ny = new Float64Array(m),
    nz = new Float64Array(m),
    ys = new Float64Array(m);
  for (let i = 0; i < m; i++) [nx[i], ny[i], nz[i], ys[i]] = [pts[i].n[0], pts[i].n[1], pts[i].n[2], pts[i].y];
  return { m, nx, ny, nz, ys };
}

/** One light (d·l, with or without fall-off) fitted over the samples `use` picks; `keep`: the model's term at each sample, kept for the best fit only. */
function fit({ m, nx, ny, nz, ys }, use, l, d, falloff, keep = false) {
  let n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  const xs = keep ? new Float64Array(m) : null;
  for (let i = 0; i < m; i++) {
    if (!use[i]) continue;
    const x = pointLightTerm(nx[i], ny[i], nz[i], l, d, falloff);
    const y = ys[i];
    if (keep) xs[i] = x;
    n++; sx += x; sy += y; sxx += x * x; sxy += x * y; syy += y * y;
  }
  return { ...solve(n, sy, syy, sx, sxx, sxy, l, d, falloff), xs };
}

/**
 * The coarse grid of lights for both models at once: a sample's w_i and ‖p_ℓ − x‖² serve both, and
 * each model's sums are added up in the order fit() adds them (the same numbers to the last bit).
 */
function grid({ m, nx, ny, nz, ys }, use, dirs) {
  let none = null, inv = null;
  // the samples used, in order, and their brightness sums (the same for every light tried)
  let n = 0, sy = 0, syy = 0;
  const at = new Int32Array(m);
  for (let i = 0; i < m; i++) {
    if (!use[i]) continue;
    at[n++] = i;
    sy += ys[i]; syy += ys[i] * ys[i];
  }
  for (const d of DIST) {
    const g = (d - 1) * (d - 1);
    for (const l of dirs) {
      const px = d * l[0], py = d * l[1], pz = d * l[2];
      let sx = 0, sxx = 0, sxy = 0, ux = 0, uxx = 0, uxy = 0;
      for (let k = 0; k < n; k++) {
        const i = at[k], n0 = nx[i], n1 = ny[i], n2 = nz[i];
        // (pointLightTerm's w_i and ‖p_ℓ − x‖², computed once for both models)
        const wx = px - n0, wy = py - n1, wz = pz - n2;
        const r2 = wx * wx + wy * wy + wz * wz;
        const cos = Math.max(0, (n0 * wx + n1 * wy + n2 * wz) / Math.sqrt(r2));
        const x = cos * g / r2;
        const y = ys[i];
        sx += cos; sxx += cos * cos; sxy += cos * y;
        ux += x; uxx += x * x; uxy += x * y;
      }
      const f = lineFit(n, sy, syy, sx, sxx, sxy), h = lineFit(n, sy, syy, ux, uxx, uxy);
      if (f.b > 0 && (!none || f.sse < none.sse)) none = { ...f, l, d, falloff: false };
      if (h.b > 0 && (!inv || h.sse < inv.sse)) inv = { ...h, l, d, falloff: true };
    }
  }
  return { none, inv };
}

/** From the grid's best (`coarse`), the direction refined, then the distance; the best fit with its terms kept. */
function search(F, use, falloff, coarse) {
  let best = coarse;
  if (!best) return null;
  for (let step = REFINE_FIRST; step > REFINE_LAST; step /= 2) { // refine the direction, then the distance
    for (const dd of [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]) {
      const l = best.l.map((v, k) => v + step * dd[k]), len = Math.hypot(...l);
      const f = fit(F, use, l.map((v) => v / len), best.d, falloff);
      if (f.b > 0 && f.sse < best.sse) best = f;
    }
    for (const d of [Math.max(NEAREST, best.d * (1 - 2 * step)), Math.min(FARTHEST, best.d * (1 + 2 * step))]) {
      const f = fit(F, use, best.l, d, falloff);
      if (f.b > 0 && f.sse < best.sse) best = f;
    }
  }
  return fit(F, use, best.l, best.d, falloff, true);
}

/**
 * max(n·w_i, 0) at the unit sphere's point x = n = (n0, n1, n2) for a point light at p_ℓ = d·l, w_i =
 * normalize(p_ℓ − x); with `falloff`, times 1/‖p_ℓ − x‖² scaled to 1 at the point nearest the light.
 */
function pointLightTerm(n0, n1, n2, l, d, falloff) {
  const wx = d * l[0] - n0, wy = d * l[1] - n1, wz = d * l[2] - n2;
  const r2 = wx * wx + wy * wy + wz * wz;
  const cos = Math.max(0, (n0 * wx + n1 * wy + n2 * wz) / Math.sqrt(r2));
  return falloff ? cos * ((d - 1) * (d - 1)) / r2 : cos;
}

/** The line fit over n samples from the sums, with the light tried (d·l, with or without fall-off). */
const solve = (n, sy, syy, sx, sxx, sxy, l, d, falloff) => ({ ...lineFit(n, sy, syy, sx, sxx, sxy), l, d, falloff });

/** The brightness a fitted point-light model (pointLightFit's `model`) gives at a sample's normal. */
export function pointLightPredict(n, m) {
  return m.a + m.b * pointLightTerm(n[0], n[1], n[2], m.l, m.d, m.falloff);
}

/**
 * The highlight above a point-light model, as diffuseFit measures it above its directional fit:
 * the largest rise of a pixel over the model, as a share of the headroom to white there. A near
 * light's 1/r² bright spot is part of the model, not a highlight. `pts` are perspectiveSamples.
 */
export function highlightAbove(pts, model, thresholds) {
  return highlightOf(pts, (n) => pointLightPredict(n, model), thresholds).peak;
}

/** 'falloff' or 'none': the model a near point light fits well (R² ≥ diffuseR2, d ≤ pointLightNear), or null. */
export function nearPointLight(pl, thresholds) {
  if (!pl) return null;
  const good = ['falloff', 'none'].filter((k) => pl[k].r2 >= thresholds.diffuseR2 && pl[k].distance <= thresholds.pointLightNear);
  return good.sort((a, b) => pl[b].r2 - pl[a].r2)[0] || null;
}
/** Model `a` ('falloff' or 'none') clearly beats model `b`: a near light, R² higher by pointLightGain, RMS lower by pointLightRmsRatio. */
export function clearlyBetter(pl, a, b, thresholds) {
  return (
    pl[a].r2 - pl[b].r2 >= thresholds.pointLightGain &&
    pl[a].distance <= thresholds.pointLightNear &&
    pl[b].rms >= thresholds.pointLightRmsRatio * pl[a].rms
  );
}
/** A light clearly near and falling off as 1/r²: it fits, and better than without the fall-off. */
export function clearlyNearFalloff(pl, thresholds) {
  return !!pl && clearlyBetter(pl, 'falloff', 'none', thresholds) && pl.falloff.r2 >= thresholds.diffuseR2;
}
