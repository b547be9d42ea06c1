// P4: which of the Phong model's terms a slider trial moved, read in the picture just before it and
// the one after: the dark side (where max(n·w_i, 0) is 0, the ambient term alone lights it) and
// the lit side above it (the diffuse term, kd·Le per unit of n·w_i). The highlight's pixels and
// clipped ones stay out of both; a side with too few pixels in view is not read (null). Beside them,
// the specular term's height: how far the highlight rises above the diffuse term.
import { samples, luminance } from './samples.js';
import { diffuseFit } from './diffuse.js';
import { dot } from './vectors.js';
import { highlightSeen } from './highlight.js';

/** The median of `xs` (null for none). */
function median(xs) {
  if (!xs.length) return null;
  const s = Float64Array.from(xs).sort(), m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

/**
 * One picture's terms: `ambient`, the median brightness of the dark side (n·w_i below
 * −termDarkCos for the light `l`), and `diffuse`, the median of (brightness − ambient) / n·w_i on
 * the lit side (n·w_i above termLitCos); each null where its side has fewer than termSideShare of
 * the samples in view. `fit` (the picture's own diffuse fit) says which pixels are its highlight;
 * `skip[i]` leaves sample i out (clipped here or in the other picture).
 */
export function termLevels(pts, fit, l, skip, thresholds) {
  const dark = [], lit = [];
  for (let i = 0; i < pts.length; i++) {
    if (skip[i]) continue;
    const p = pts[i], y = luminance(p.c), c = dot(p.n, l);
    const model = fit ? fit.ambient + fit.diffuse * Math.max(0, dot(p.n, fit.light)) : y;
    if (y - model > thresholds.highlightMargin) continue; // the highlight
    if (c < -thresholds.termDarkCos) dark.push(y);
    else if (c > thresholds.termLitCos) lit.push([y, c]);
  }
  const enough = (xs) => xs.length >= Math.max(thresholds.minFitSamples, thresholds.termSideShare * pts.length);
  const ambient = enough(dark) ? median(dark) : null;
  const diffuse = ambient !== null && enough(lit) ? median(lit.map(([y, c]) => (y - ambient) / c)) : null;
  return { ambient, diffuse, dark: dark.length / Math.max(1, pts.length) };
}

/** The `q` quantile of `xs` (sorted in place). */
function quantile(xs, q) {
  xs.sort();
  return xs[Math.min(xs.length - 1, Math.floor(q * xs.length))];
}

/**
 * Did the dark side (n·w_i below −termDarkCos for `l`) change by one factor in every pixel: the
 * spread (between the quartiles) of after / before over its pixels, those darker than termChange
 * left out, is within termEvenSpread. `pb` and `pa` are the same pixels in the two pictures.
 */
export function darkEven(pb, pa, l, skip, thresholds) {
  const ratios = [];
  for (let i = 0; i < pb.length; i++) {
    if (skip[i] || dot(pb[i].n, l) >= -thresholds.termDarkCos) continue;
    const yb = luminance(pb[i].c);
    if (yb >= thresholds.termChange) ratios.push(luminance(pa[i].c) / yb);
  }
  if (ratios.length < thresholds.minFitSamples) return true;
  const r = Float64Array.from(ratios);
  return quantile(r, 3 / 4) - quantile(r, 1 / 4) <= thresholds.termEvenSpread;
}

/**
 * Did a term move from `a` to `b`: by termChange or more, and by termChangeShare of the larger or
 * more. null where it was not read, or is fainter than termChange in both pictures (not seen at all).
 */
export function termMoved(a, b, thresholds) {
  if (a === null || b === null) return null;
  if (Math.max(Math.abs(a), Math.abs(b)) < thresholds.termChange) return null;
  const d = Math.abs(a - b);
  return d >= thresholds.termChange && d >= thresholds.termChangeShare * Math.max(Math.abs(a), Math.abs(b));
}

/**
 * What a slider trial moved: { ambient, diffuse } (true, false, or null where it cannot be read),
 * with each picture's levels. `an` is the sphere found in the picture before (and after, in a
 * picture that moves by itself: `anAfter`); in a still picture the same pixels are compared. The
 * light is the one the clearer of the two pictures' fits finds (a term set to 0 can leave the
 * other picture with no diffuse shading to fit); in a moving picture each has its own.
 */
export function trialTerms(before, after, an, anAfter, thresholds, { moving = false } = {}) {
  const opts = { max: thresholds.fitSamples };
  const pb = samples(before, an, thresholds, opts);
  const pa = samples(after, moving && anAfter && !anAfter.blank ? anAfter : an, thresholds, opts);
  if (!moving && pa.length !== pb.length) return null;
  const fb = diffuseFit(pb, thresholds), fa = diffuseFit(pa, thresholds);
  if (!fb || !fa) return null;
  const clear = (f) => (f.diffuse >= thresholds.diffuseMin ? f.r2 : -1);
  const lb = !moving && clear(fa) > clear(fb) ? fa.light : fb.light;
  const la = moving && clear(fa) >= 0 ? fa.light : lb;
  const clipped = (p) => Math.max(p.c[0], p.c[1], p.c[2]) >= thresholds.clippedLevel;
  const skipB = pb.map((p, i) => clipped(p) || (!moving && clipped(pa[i])));
  const skipA = moving ? pa.map(clipped) : skipB;
  const b = termLevels(pb, fb, lb, skipB, thresholds), a = termLevels(pa, fa, la, skipA, thresholds);
  // (in a still picture, the ambient term moves the whole dark side by one factor: a dark side
  // moved unevenly is another term reaching it, a broad highlight of a low s, and is not read)
  const even = moving || darkEven(pb, pa, lb, skipB, thresholds);
  return {
    ambient: even ? termMoved(b.ambient, a.ambient, thresholds) : null,
    diffuse: termMoved(b.diffuse, a.diffuse, thresholds),
    before: b,
    after: a,
  };
}

/**
 * Did a slider trial move the specular term's height (k_s L_e: how far the highlight rises above the
 * diffuse term), read in the two pictures' fits (`fb` before, `fa` after: diffuseFit's
 * highlightRise, highlightPeak)? null where neither picture shows a highlight (highlightSeen), or
 * where both do and one reaches white (a clipped highlight rises as far as white lets it, not as
 * far as k_s L_e: its height cannot be compared); else termMoved on the two rises.
 */
export function highlightMoved(fb, fa, thresholds) {
  if (!fb || !fa) return null;
  const seenB = highlightSeen(fb, thresholds), seenA = highlightSeen(fa, thresholds);
  if (!seenB && !seenA) return null;
  const white = (f) => f.highlightPeak >= thresholds.clippedLevel;
  if (seenB && seenA && (white(fb) || white(fa))) return null;
  return termMoved(fb.highlightRise, fa.highlightRise, thresholds);
}
