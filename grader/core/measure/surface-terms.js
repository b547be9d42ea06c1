// P4: the terms of the slide's reflection model one picture shows, read on the page's own surface
// (core/computed/surface.js) with the light, the specular term's form, w_o and the normal colour
// fixed at what the judged picture's fit found (measure/surface-fit.js):
//   L_o = k_a L_a + k_d L_e max(n · w_i, 0) + k_s L_e max(w_r · w_o, 0)^s
// per channel a = k_a L_a, d = k_d L_e, k = k_s L_e (linear once w_i and s are fixed: least squares;
// the normal colour added, t, a colour no light moves, is read with a),
// and s the shininess that fits best. A slider trial compares two such readings of the same pixels:
// which of a, d, k and s it moved. Clipped channels stay out; black ones stay in (a term set to 0
// leaves its pixels black, which is what the model says there).
import { coloured, columns, fitChannels, diffuseTerm, specularCosines, SPECULAR, VIEW, SHININESS } from './surface-fit.js';

/** The least pixels a reading is made on. */
const LEAST_PIXELS = 30;
/** The normal colour as the judged fit took it (surface-fit.js's TINTS): the fit's options. */
const HOW = { added: { tint: true }, times: { times: true } };

/**
 * The terms `img` shows on `surface` (surfaceOf's samples, its camera) under `model` (the judged
 * fit's best: { wi, form, view, tint }): { a, d, k, t: [per channel], s, rms }, or null where too few
 * pixels or a channel cannot be solved. A model with no highlight is read with the slide's Phong
 * form and w_o, so that a trial that brings one is seen.
 */
export function termsOnSurface(surface, img, model, thresholds) {
  const use = coloured(surface.samples, img);
  if (use.length < LEAST_PIXELS) return null;
  const cols = columns(use, thresholds, { black: true });
  const how = HOW[model.tint] || {};
  const spec = SPECULAR[model.form || 'phong'], wo = VIEW[model.view || 'the slide'];
  if (!wo(use[0], surface.camera)) return null;
  const D = diffuseTerm(cols, model.wi);
  const cosines = specularCosines(use, surface.camera, model.wi, spec, wo);
  const S = new Float64Array(cols.m);
  let best = null;
  for (const s of SHININESS) {
    for (let i = 0; i < cols.m; i++) S[i] = cosines[i] ** s;
    const f = fitChannels(cols, D, S, how);
    if (f && (!best || f.sse < best.fit.sse)) best = { s, fit: f };
  }
  if (!best) return null;
  const { coef, sse, used } = best.fit;
  return {
    a: coef.map((c) => c[0]),
    // the normal colour added (c = a + … + t·(0.5·n + 0.5)), lit by no light: read with the ambient term
    t: model.tint === 'added' ? coef.map((c) => c[3]) : null,
    d: coef.map((c) => c[1]),
    k: coef.map((c) => c[2]),
    s: best.s,
    rms: Math.sqrt(sse / Math.max(1, used)),
  };
}

/**
 * Did a term (one number a channel, as a colour) move from `xb` to `xa`: termMoved on the colour's
 * length, by how far the colour moved. (A channel clipped near the highlight is fitted on fewer
 * pixels and reads its term lower: the colour as a whole, not one channel, is the term.)
 */
function colourMoved(xb, xa, thresholds) {
  const length = (x) => Math.hypot(...x);
  const nb = length(xb), na = length(xa), d = length(xb.map((v, ch) => v - xa[ch]));
  if (Math.max(nb, na) < thresholds.termChange) return null;
  return d >= thresholds.termChange && d >= thresholds.termChangeShare * Math.max(nb, na);
}

/** Either of two readings moved (true), else either did not (false), else null. */
const either = (x, y) => (x === true || y === true ? true : x === false || y === false ? false : null);

/** Does a reading show the specular term: in every channel (a highlight the surface's pixels miss, clipped to white, reads as noise in some)? */
export const showsSpecular = (t, thresholds) => !!t && Math.min(...t.k) >= thresholds.termChange;

/**
 * What a slider trial moved, from the readings before (`b`) and after (`a`) on the same pixels:
 * { ambient, diffuse, specular, shininess }, each true, false or null (not seen). null for the
 * whole trial where the model, which explained the picture before, leaves the one after unexplained
 * (surfaceTrialResidual times the residual before, and past surfaceResidual): the trial turned the
 * light or the view, and the same pixels no longer hold the same terms. The shininess is read only
 * where both readings show the specular term; it moved where the fitted s did.
 */
export function surfaceTrial(b, a, thresholds) {
  if (!b || !a) return null;
  if (a.rms > Math.max(thresholds.surfaceResidual, thresholds.surfaceTrialResidual * b.rms)) return null;
  return {
    ambient: either(colourMoved(b.a, a.a, thresholds), b.t && colourMoved(b.t, a.t, thresholds)),
    diffuse: colourMoved(b.d, a.d, thresholds),
    specular: colourMoved(b.k, a.k, thresholds),
    shininess: showsSpecular(b, thresholds) && showsSpecular(a, thresholds) ? b.s !== a.s : null,
  };
}

/**
 * The residual (RMS over the channels neither clipped nor black) that `model`, the judged fit's
 * best whole (its light, form, w_o, s, normal colour and material `coef` per channel, as
 * surface-fit.js's fitChannels lays them out), leaves on `img` over `surface`: nothing refitted,
 * each pixel's colour predicted from its own normal and position (clipped at white, as a picture
 * is). Null where too few pixels.
 */
export function modelResidual(surface, img, model, thresholds) {
  const use = coloured(surface.samples, img);
  if (use.length < LEAST_PIXELS || !model.coef) return null;
  const cols = columns(use, thresholds);
  const D = diffuseTerm(cols, model.wi);
  const spec = model.form && SPECULAR[model.form], wo = VIEW[model.view || 'the slide'];
  if (spec && !wo(use[0], surface.camera)) return null;
  const S = spec ? specularCosines(use, surface.camera, model.wi, spec, wo).map((c) => c ** model.s) : null;
  let sse = 0, used = 0;
  for (let i = 0; i < cols.m; i++) {
    for (let ch = 0; ch < 3; ch++) {
      if (!cols.ok[3 * i + ch]) continue;
      const x = model.coef[ch], t = 0.5 * cols.n[3 * i + ch] + 0.5, w = model.tint === 'times' ? t : 1;
      let j = 1, y = x[0] * w + x[j++] * w * D[i];
      if (S) y += x[j++] * w * S[i];
      if (model.tint === 'added') y += x[j] * t;
      sse += (cols.c[3 * i + ch] - Math.min(1, Math.max(0, y))) ** 2;
      used++;
    }
  }
  return used ? Math.sqrt(sse / used) : null;
}
