// P3–P5: brightness fitted by a + b·max(n·w_i, 0) for a fitted light direction w_i (and, to tell
// them apart, by the two-sided a + b·|n·w_i|), the highlight above the fit measured on the way.
import { DIRS } from './directions.js';
import { luminance, sameMask } from './samples.js';
import { highlightOf } from './highlight.js';
import { lineFit } from './linear.js';

/** A guard against dividing by (nearly) zero. */
const GUARD = 1e-9;
/** The light's refinement: its first step and the step it stops before (the mechanics of a search). */
const REFINE_FIRST = 0.1, REFINE_LAST = 0.005;

/** The samples where `use` is set, as flat arrays (normals, brightness), which every fit below reads. */
function flat(pts, use) {
  let m = 0;
  for (let i = 0; i < pts.length; i++) if (!use || use[i]) m++;
  const nx = new Float64Array(m), ny = new Float64Array(m), nz = new Float64Array(m), y = new Float64Array(m);
  for (let i = 0, j = 0; i < pts.length; i++) {
    if (use && !use[i]) continue;
    const s = pts[i];
    nx[j] = s.n[0]; ny[j] = s.n[1]; nz[j] = s.n[2]; y[j] = s.y;
    j++;
  }
  let sy = 0, syy = 0;
  for (let j = 0; j < m; j++) { sy += y[j]; syy += y[j] * y[j]; }
  return { m, nx, ny, nz, y, sy, syy };
}

/** The line fit ({ a, b, sse }) of the samples F's brightness against max(n·l, 0). */
function fitDirection(F, l) {
  // brightness ≈ a + b max(n·l, 0): linear in (a, b) for a given l;
  // one pass: at the least-squares (a, b) the residual is Σy² − a Σy − b Σxy
  const { m, nx, ny, nz, y } = F;
  const l0 = l[0], l1 = l[1], l2 = l[2];
  let sx = 0, sxx = 0, sxy = 0;
  for (let i = 0; i < m; i++) {
    const x = nx[i] * l0 + ny[i] * l1 + nz[i] * l2;
    if (x > 0) { sx += x; sxx += x * x; sxy += x * y[i]; }
  }
  return lineFit(F.m, F.sy, F.syy, sx, sxx, sxy);
}

/**
 * fitDirection(F, l) for each l of `dirs`, four directions a pass over the samples (each sample's
 * normal read once for four; each sum added in fitDirection's order, so the same numbers).
 */
function fitEach(F, dirs) {
  const { m, nx, ny, nz, y } = F;
  const fits = new Array(dirs.length);
  let d = 0;
  for (; d + 4 <= dirs.length; d += 4) {
    const [p0, p1, p2] = dirs[d], [q0, q1, q2] = dirs[d + 1], [r0, r1, r2] = dirs[d + 2], [t0, t1, t2] = dirs[d + 3];
    let ps = 0, pss = 0, psy = 0, qs = 0, qss = 0, qsy = 0, rs = 0, rss = 0, rsy = 0, ts = 0, tss = 0, tsy = 0;
    for (let i = 0; i < m; i++) {
      const a = nx[i], b = ny[i], c = nz[i], v = y[i];
      const xp = a * p0 + b * p1 + c * p2, xq = a * q0 + b * q1 + c * q2;
      const xr = a * r0 + b * r1 + c * r2, xt = a * t0 + b * t1 + c * t2;
      if (xp > 0) { ps += xp; pss += xp * xp; psy += xp * v; }
      if (xq > 0) { qs += xq; qss += xq * xq; qsy += xq * v; }
      if (xr > 0) { rs += xr; rss += xr * xr; rsy += xr * v; }
      if (xt > 0) { ts += xt; tss += xt * xt; tsy += xt * v; }
    }
    fits[d] = lineFit(m, F.sy, F.syy, ps, pss, psy);
    fits[d + 1] = lineFit(m, F.sy, F.syy, qs, qss, qsy);
    fits[d + 2] = lineFit(m, F.sy, F.syy, rs, rss, rsy);
    fits[d + 3] = lineFit(m, F.sy, F.syy, ts, tss, tsy);
  }
  for (; d < dirs.length; d++) fits[d] = fitDirection(F, dirs[d]);
  return fits;
}

/**
 * The two-sided line fits of brightness against |n·l| (lit on both sides: a + b |n·l|) of F and
 * of Fall at once, F being the samples of Fall that `use` picks, in the same order: |n·l|
 * computed once a sample, each sum added up in the order a fit of either alone would add it.
 */
function fitTwoSided(Fall, F, use, l) {
  const { m, nx, ny, nz, y } = Fall;
  const l0 = l[0], l1 = l[1], l2 = l[2];
  let sx = 0, sxx = 0, sxy = 0, ux = 0, uxx = 0, uxy = 0;
  for (let i = 0; i < m; i++) {
    const x = Math.abs(nx[i] * l0 + ny[i] * l1 + nz[i] * l2);
    sx += x; sxx += x * x; sxy += x * y[i];
    if (use[i]) { ux += x; uxx += x * x; uxy += x * y[i]; }
  }
  return [lineFit(F.m, F.sy, F.syy, ux, uxx, uxy), lineFit(Fall.m, Fall.sy, Fall.syy, sx, sxx, sxy)];
}

/**
 * P3–P5: fit brightness = ambient + diffuse·max(n·w_i, 0) for some light direction w_i, leaving
 * out pixels much brighter than the fit (a highlight) on a second pass. Returns the fit's R²
 * (over the pixels fitted), the light direction, and the highlight those bright pixels make.
 */
export function diffuseFit(pts, thresholds) {
  if (pts.length < thresholds.minFitSamples) return null;
  for (const s of pts) s.y = luminance(s.c);
  const meanY = pts.reduce((a, s) => a + s.y, 0) / pts.length;
  const sst = pts.reduce((a, s) => a + (s.y - meanY) ** 2, 0);
  // a pixel clipped at white (a channel at 1) says only "at least this bright": left out of the fit
  // while enough are left (a washed-out material), kept for the highlight above it
  const unclipped = Uint8Array.from(pts, (s) => !s.clipped && Math.max(...s.c) < thresholds.clippedLevel);
  let use =
    unclipped.reduce((a, v) => a + v, 0) >=
    Math.max(thresholds.minFitSamples, thresholds.minUnclippedShare * pts.length)
      ? unclipped
      : new Uint8Array(pts.length).fill(1);
  const use0 = use;
  let best = null, sseAll = null, F = null;
  for (let pass = 0; pass < 2; pass++) {
    best = null;
    F = flat(pts, use);
    const fits = fitEach(F, DIRS);
    for (let j = 0; j < DIRS.length; j++) {
      const f = fits[j];
      if (f.b >= 0 && (!best || f.sse < best.sse)) best = { ...f, l: DIRS[j] };
    }
    // refine around the best direction
    for (let step = REFINE_FIRST; step > REFINE_LAST; step /= 2) {
      for (const d of [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]) {
        const l = best.l.map((v, k) => v + step * d[k]), len = Math.hypot(...l), u = l.map((v) => v / len);
        const f = fitDirection(F, u);
        if (f.b >= 0 && f.sse < best.sse) best = { ...f, l: u };
      }
    }
    if (pass === 0) {
      sseAll = best.sse;
      const left = Uint8Array.from(
        pts,
        (s, i) =>
          use0[i] &&
          s.y - (best.a + best.b * Math.max(0, s.n[0] * best.l[0] + s.n[1] * best.l[1] + s.n[2] * best.l[2])) <
            thresholds.highlightFitMargin,
      );
      // no pixel above the fit: the second pass would fit the same pixels to the same numbers
      if (sameMask(left, use)) break;
      use = left;
    }
  }
  const used = use.reduce((a, v) => a + v, 0);
  const meanU = pts.reduce((a, s, i) => a + (use[i] ? s.y : 0), 0) / Math.max(1, used);
  const sstU = pts.reduce((a, s, i) => a + (use[i] ? (s.y - meanU) ** 2 : 0), 0);
  // the highlight: how far above the diffuse fit a pixel is, as a share of the headroom left to
  // white there (a highlight on a bright diffuse patch saturates at 1 and cannot rise far)
  const hl = highlightOf(
    pts,
    (n) => best.a + best.b * Math.max(0, n[0] * best.l[0] + n[1] * best.l[1] + n[2] * best.l[2]),
    thresholds,
  );
  // the same pixels under a two-sided model: a page lit on both sides (|n·w_i|) fits it better
  let twoSided = null, twoSidedAll = null;
  const Fall = flat(pts, null); // (F: the second pass's pixels, the highlight left out)
  for (const l of DIRS) {
    const [f, g] = fitTwoSided(Fall, F, use, l);
    if (f.b >= 0 && (!twoSided || f.sse < twoSided.sse)) twoSided = { ...f, l };
    if (g.b >= 0 && (!twoSidedAll || g.sse < twoSidedAll.sse)) twoSidedAll = { ...g, l };
  }
  // ... and both models over all pixels, none left out as a highlight
  const r2All = sst > GUARD ? 1 - sseAll / sst : 0, r2TwoSidedAll = sst > GUARD ? 1 - twoSidedAll.sse / sst : 0;
  return {
    r2: sstU > GUARD ? 1 - best.sse / sstU : 0,
    r2TwoSided: sstU > GUARD ? 1 - twoSided.sse / sstU : 0,
    r2All,
    r2TwoSidedAll,
    rms: Math.sqrt(best.sse / Math.max(1, used)),
    ambient: best.a,
    diffuse: best.b,
    light: best.l,
    spread: Math.sqrt(sst / pts.length),
    highlightPeak: hl.peak,
    highlightRise: hl.rise,
    highlightShare: hl.bright / pts.length,
    highlightNormal: hl.normal,
    fitted: used / pts.length,
  };
}
