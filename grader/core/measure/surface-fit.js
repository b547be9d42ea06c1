// The slide's reflection model fitted on the page's own surface (core/computed/surface.js: each
// pixel's normal, position and w_o as the page drew them), channel by channel:
//   L_o = k_a L_a + k_d L_e max(n · w_i, 0) + k_s L_e max(w_r · w_o, 0)^s   (Phong; Blinn-Phong: n · w_h)
// with w_i a direction fixed in the model's space (a directional light; one view cannot tell the
// world from the eye's space: the camera's turn does), the material per channel (a, d, k: linear
// once w_i, s and the form are chosen, so solved by least squares), channels that clip left out.
// Beside it, the known misreadings, each fitted the same way and named: the normal colour of
// WP04P1 added as a term of its own (0.5·n + 0.5, c = t·(0.5·n + 0.5) + …), and w_o taken as a fixed
// direction (the eye space's (0, 0, 1)), from the world origin (−p), with the view matrix applied
// twice, or with its sign turned. Which explains the picture
// best, and by how much, is evidence for the audits; a reason rests on it only past the rubric's margin.
import { solveNormal } from './linear.js';
import { DIRS } from './directions.js';
import { dot, unit } from './vectors.js';
import { CHANNEL_MAX } from '../units.js';

/** The least pixels a fit is solved on: in all, and a channel. */
const LEAST_PIXELS = 30, LEAST_A_CHANNEL = 8;
/** The light's refinement steps around the best of the coarse search (the mechanics of a search). */
const REFINE_STEPS = [0.15, 0.05, 0.015, 0.005];
/** What is kept of a fit: its coefficients to 1/COEF_ROUND, its residuals to 1/RMS_ROUND. */
const COEF_ROUND = 1e4, RMS_ROUND = 1e5;

/**
 * The samples with the picture's colour at each ([0, 1] a channel). Front and back faces alike: a
 * page that winds its triangles the other way and culls nothing shows its outside as back faces.
 */
export function coloured(samples, img) {
  const out = [];
  for (const s of samples) {
    const o = 4 * (s.y * img.width + s.x);
    out.push({ ...s, c: [img.data[o] / CHANNEL_MAX, img.data[o + 1] / CHANNEL_MAX, img.data[o + 2] / CHANNEL_MAX] });
  }
  return out;
}

/**
 * The samples as columns, for fits that allocate nothing a sample: n, c, and for each channel
 * whether it is neither clipped nor black (those are left out of that channel's fit; `black`:
 * black ones kept, where a term set to 0 is what is read).
 */
export function columns(use, thresholds, { black = false } = {}) {
  const m = use.length;
  const n = new Float64Array(3 * m), c = new Float64Array(3 * m), ok = new Uint8Array(3 * m);
  use.forEach((s, i) => {
    for (let k = 0; k < 3; k++) {
      n[3 * i + k] = s.n[k];
      c[3 * i + k] = s.c[k];
      ok[3 * i + k] = s.c[k] < thresholds.clippedLevel && (black || s.c[k] > thresholds.blackLevel) ? 1 : 0;
    }
  });
  return { m, n, c, ok };
}

/**
 * Least squares of each channel on the basis [1, D?, S?, tint?] (D, S each sample's diffuse and
 * specular terms, or null; the normal colour 0.5·n_ch + 0.5 added or, `times`, multiplying them
 * all) over the samples whose channel is neither clipped nor black: { coef: [per channel], sse,
 * used }, or null where a channel cannot be solved. The residual comes from the normal equations.
 */
export function fitChannels(cols, D, S, { tint = false, times = false } = {}) {
  const k = 1 + (D ? 1 : 0) + (S ? 1 : 0) + (tint ? 1 : 0);
  const N = new Float64Array(k * k), v = new Float64Array(k);
  // where S and the normal colour sit in the basis (after 1 and D)
  const sAt = S ? 1 + (D ? 1 : 0) : 0, tAt = tint ? k - 1 : 0;
  const coef = [];
  let sse = 0, used = 0;
  for (let ch = 0; ch < 3; ch++) {
    // the normal equations' sums, a basis of four at most, each added up sample by sample (the
    // terms the basis lacks stay 0 and are not read)
    let v0 = 0, v1 = 0, v2 = 0, v3 = 0;
    let n00 = 0, n01 = 0, n02 = 0, n03 = 0, n11 = 0, n12 = 0, n13 = 0, n22 = 0, n23 = 0, n33 = 0;
    let yy = 0, count = 0;
    for (let i = 0; i < cols.m; i++) {
      if (!cols.ok[3 * i + ch]) continue;
      const t = 0.5 * cols.n[3 * i + ch] + 0.5, w = times ? t : 1;
      const r0 = w, d = D ? w * D[i] : 0, s = S ? w * S[i] : 0;
      const r1 = D ? d : sAt === 1 ? s : tAt === 1 ? t : 0;
      const r2 = sAt === 2 ? s : tAt === 2 ? t : 0, r3 = tAt === 3 ? t : 0;
      const y = cols.c[3 * i + ch];
      v0 += r0 * y; v1 += r1 * y; v2 += r2 * y; v3 += r3 * y;
      n00 += r0 * r0; n01 += r0 * r1; n02 += r0 * r2; n03 += r0 * r3;
      n11 += r1 * r1; n12 += r1 * r2; n13 += r1 * r3;
      n22 += r2 * r2; n23 += r2 * r3; n33 += r3 * r3;
      yy += y * y;
      count++;
    }
    if (count < LEAST_A_CHANNEL) return null;
    const sums = [[n00, n01, n02, n03], [n01, n11, n12, n13], [n02, n12, n22, n23], [n03, n13, n23, n33]];
    for (let a = 0; a < k; a++) {
      v[a] = [v0, v1, v2, v3][a];
      for (let b = 0; b < k; b++) N[a * k + b] = sums[a][b];
    }
    const x = solveNormal(N, v, k);
    if (!x) return null;
    // Σ(y − r·x)² = Σy² − xᵀv at the least-squares solution
    sse += Math.max(0, yy - x.reduce((acc, xi, a) => acc + xi * v[a], 0));
    used += count;
    coef.push(x);
  }
  return { coef, sse, used };
}

/** The forms of the specular term: each gives max(cos, 0)^s for a sample, a light and w_o. */
export const SPECULAR = {
  phong: (n, wi, wo) => {
    const c = dot(n, wi);
    return c > 0 ? dot([2 * c * n[0] - wi[0], 2 * c * n[1] - wi[1], 2 * c * n[2] - wi[2]], wo) : 0;
  },
  'blinn-phong': (n, wi, wo) => {
    const h = dot(n, wi) > 0 && unit([wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]]); // (no w_h where w_i = −w_o)
    return h ? dot(n, h) : 0;
  },
};

/** max(cos, 0) of the specular term `spec` (SPECULAR's) at each of the samples `use`, for the light `wi` and w_o as `wo` (VIEW's) takes it from `camera`. */
export const specularCosines = (use, camera, wi, spec, wo) => use.map((q) => Math.max(spec(q.n, wi, wo(q, camera)), 0));

/** p in the eye's space (its coordinates along the camera's right, up and back, from its centre), or null. */
function inEye(p, camera) {
  if (!camera.eye) return null;
  const d = [p[0] - camera.eye[0], p[1] - camera.eye[1], p[2] - camera.eye[2]];
  return [dot(camera.right, d), dot(camera.up, d), dot(camera.back, d)];
}

/**
 * w_o as the slide says, and as it is got wrong, in the model's space (null: the camera cannot say).
 * The view matrix applied twice: w_o = −normalize((V·(V·p)).xyz) in the eye's space is, turned back
 * into the model's, normalize(e − V·p) with V·p's coordinates read as a point of the model's space.
 */
export const VIEW = {
  'the slide': (s) => s.w_o,
  'fixed at the eye space\'s (0, 0, 1)': (s, camera) => camera.back,
  'from the world origin (−p)': (s) => unit(s.p.map((v) => -v)) || [0, 0, 0],
  'with the view matrix applied twice': (s, camera) => {
    const q = inEye(s.p, camera);
    return q && (unit([camera.eye[0] - q[0], camera.eye[1] - q[1], camera.eye[2] - q[2]]) || [0, 0, 0]);
  },
  'pointing away from the eye (its sign)': (s) => s.w_o.map((v) => -v),
};

export const SHININESS = [5, 10, 20, 40, 80, 160, 320];

/** How the normal colour enters: not at all, added as a term of its own, or as the material (multiplying the lighting). */
const TINTS = [[null, {}, ''], ['added', { tint: true }, ', the normal colour added'], ['times', { times: true }, ', the normal colour as the material']];

/** max(n · w_i, 0) for every sample. */
export function diffuseTerm(cols, wi, out = new Float64Array(cols.m)) {
  for (let i = 0; i < cols.m; i++) {
    out[i] = Math.max(0, cols.n[3 * i] * wi[0] + cols.n[3 * i + 1] * wi[1] + cols.n[3 * i + 2] * wi[2]);
  }
  return out;
}

/**
 * The best directional light for the diffuse term (with the normal colour as `how` says:
 * { tint } added, { times } multiplying): { wi, fit } over the fibonacci directions, then refined
 * around the best.
 */
function bestLight(cols, how) {
  let best = null;
  const D = new Float64Array(cols.m);
  const tryLight = (wi) => {
    const f = fitChannels(cols, diffuseTerm(cols, wi, D), null, how);
    if (f && (!best || f.sse < best.fit.sse)) best = { wi, fit: f };
  };
  // a coarse search over every fourth direction, then refined: the diffuse fit's error is smooth in w_i
  for (let k = 0; k < DIRS.length; k += 4) tryLight(DIRS[k]);
  if (!best) return null;
  for (const step of REFINE_STEPS) {
    const c = best.wi;
    for (const a of [-1, 0, 1]) {
      for (const b of [-1, 0, 1]) {
        for (const e of [-1, 0, 1]) {
          if (a || b || e) {
            tryLight(unit([c[0] + a * step, c[1] + b * step, c[2] + e * step]));
          }
        }
      }
    }
  }
  return best;
}

/**
 * The model fitted on the page's surface and the picture: { samples, diffuse: { wi, rms, r2 }, slide:
 * the slide's formula's best { name, rms, s }, best: { name, wi, form, view, s, rms, tint } (the slide's
 * formula unless a variant beats it by the rubric's surfaceVariantMargin), variants: [{ name, rms, s, view, tint }]
 * (lowest residual first) }, or { why }.
 * `surface` is core/computed/surface.js's (samples in the model's space, its camera).
 */
export function surfaceFit(surface, img, thresholds) {
  if (!surface || surface.why) return { why: surface ? surface.why : 'no surface' };
  const use = coloured(surface.samples, img);
  if (use.length < LEAST_PIXELS) return { why: `only ${use.length} pixels of the page's surface to fit` };
  const mean = [0, 1, 2].map((ch) => use.reduce((a, s) => a + s.c[ch], 0) / use.length);
  const sst = use.reduce((a, s) => a + s.c.reduce((b, v, ch) => b + (v - mean[ch]) ** 2, 0), 0);
  const cols = columns(use, thresholds);
  const rms = (f) => Math.sqrt(f.sse / Math.max(1, f.used));
  const variants = [];
  const lights = {};
  for (const [key, how, words] of TINTS) {
    const b = bestLight(cols, how);
    if (!b) continue;
    lights[key] = b;
    variants.push({ name: `diffuse${words}`, wi: b.wi, tint: key, form: null, view: null, s: null, fit: b.fit });
    const D = diffuseTerm(cols, b.wi), S = new Float64Array(cols.m);
    for (const [form, spec] of Object.entries(SPECULAR)) {
      for (const [view, wo] of Object.entries(VIEW)) {
        if (!wo(use[0], surface.camera)) continue;
        const cosines = specularCosines(use, surface.camera, b.wi, spec, wo);
        for (const sh of SHININESS) {
          for (let i = 0; i < cols.m; i++) S[i] = cosines[i] ** sh;
          const f = fitChannels(cols, D, S, how);
          if (f) variants.push({ name: `${form}, w_o ${view}${words}`, wi: b.wi, tint: key, form, view, s: sh, fit: f });
        }
      }
    }
  }
  // WP04P1's colouring alone, no light at all: c = a + t·(0.5·n + 0.5)
  const alone = fitChannels(cols, null, null, { tint: true });
  if (!variants.length) return { why: 'the model could not be fitted on the page\'s surface' };
  // one entry a name: its best shininess
  const byName = new Map();
  for (const v of variants) if (!byName.has(v.name) || v.fit.sse < byName.get(v.name).fit.sse) byName.set(v.name, v);
  const ranked = [...byName.values()].sort((a, b) => rms(a.fit) - rms(b.fit));
  // the slide's formula (w_o as the slide has it, nothing added) stands unless it leaves a visible
  // residual (surfaceResidual) and a misreading explains the picture better by the rubric's margin
  // (a term more always fits a little better, and lighting per vertex fits a per-fragment model only
  // nearly); one misreading at a time: the normal colour first, then w_o given that colour, or the
  // two together where neither alone explains the picture
  const slideView = (v) => !v.view || v.view === 'the slide';
  const slide = ranked.find((v) => slideView(v) && !v.tint);
  const better = (v, than) =>
    rms(than.fit) >= thresholds.surfaceResidual && rms(v.fit) < (1 - thresholds.surfaceVariantMargin) * rms(than.fit);
  let top = slide || ranked[0];
  const tinted = slide && ranked.find((v) => slideView(v) && v.tint);
  if (tinted && better(tinted, top)) top = tinted;
  // w_o misread with the same colour, else with the normal colour beside it (two misreadings at once,
  // each of which alone leaves the picture unexplained), past the margin over the slide's w_o
  const viewed = slide && ranked.find((v) => !slideView(v) && v.tint === top.tint);
  const viewedTinted = slide && !top.tint && ranked.find((v) => !slideView(v) && v.tint);
  if (viewed && better(viewed, top)) top = viewed;
  else if (viewedTinted && better(viewedTinted, top)) top = viewedTinted;
  const d = lights.null;
  return {
    samples: use.length,
    diffuse: d ? { wi: d.wi, rms: rms(d.fit), r2: sst > 0 ? 1 - d.fit.sse / sst : 0 } : null,
    best: { name: top.name, wi: top.wi, form: top.form, view: top.view, s: top.s, tint: top.tint, rms: rms(top.fit),
      r2: sst > 0 ? 1 - top.fit.sse / sst : 0,
      coef: top.fit.coef.map((c) => c.map((v) => Math.round(v * COEF_ROUND) / COEF_ROUND)) },
    slide: slide ? { name: slide.name, form: slide.form, rms: rms(slide.fit), s: slide.s } : null,
    // the lighting is there, beside the normal colour: the colour alone leaves a visible residual that the lighting halves
    normalColourAlone: alone ? { rms: rms(alone) } : null,
    lit: !!alone && !!tinted && better(tinted, { fit: alone }),
    variants: ranked.map((v) => ({
      name: v.name, rms: Math.round(rms(v.fit) * RMS_ROUND) / RMS_ROUND, s: v.s, view: v.view, tint: v.tint,
    })),
  };
}
