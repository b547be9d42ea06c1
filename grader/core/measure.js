// Judging a picture by the properties of the slide's step, not by its pixels against ours:
// students pick their own camera, canvas, background, light and material. An image is
// { width, height, data } (RGBA bytes). Everything here is plain arithmetic, no browser.

/** The background (the commonest border colour), the object's mask and its silhouette. */
export function analyse(img, rubric = {}) {
  const { width: w, height: h, data } = img;
  const tol = rubric.backgroundTolerance ?? 30;
  const counts = new Map();
  const border = [];
  for (let x = 0; x < w; x++) border.push([x, 0], [x, h - 1]);
  for (let y = 0; y < h; y++) border.push([0, y], [w - 1, y]);
  for (const [x, y] of border) {
    const o = 4 * (y * w + x);
    const key = (data[o] >> 2) << 16 | (data[o + 1] >> 2) << 8 | (data[o + 2] >> 2);
    counts.set(key, (counts.get(key) || 0) + 1);
  }
  const top = [...counts.entries()].sort((a, b) => b[1] - a[1])[0][0];
  const bg = [(top >> 16 & 63) * 4 + 2, (top >> 8 & 63) * 4 + 2, (top & 63) * 4 + 2];
  const n = w * h;
  const raw = new Uint8Array(n);
  const first = data[0] << 16 | data[1] << 8 | data[2];
  let oneColour = true;
  const b0 = bg[0], b1 = bg[1], b2 = bg[2];
  for (let p = 0; p < n; p++) {
    const o = 4 * p, r = data[o], g = data[o + 1], b = data[o + 2];
    if (oneColour && (r << 16 | g << 8 | b) !== first) oneColour = false;
    if (Math.abs(r - b0) + Math.abs(g - b1) + Math.abs(b - b2) > tol) raw[p] = 1;
  }
  openMask(raw, w, h, rubric.thinLine ?? 2);
  // the largest 4-connected component is the object (text or a second canvas element aside)
  const label = new Int32Array(n);
  let best = 0, bestLabel = 0, next = 0;
  const stack = new Int32Array(n);
  for (let p = 0; p < n; p++) {
    if (!raw[p] || label[p]) continue;
    next++;
    let size = 0, top = 0;
    stack[top++] = p;
    label[p] = next;
    while (top) {
      const q = stack[--top];
      size++;
      const x = q % w;
      if (x > 0 && raw[q - 1] && !label[q - 1]) { label[q - 1] = next; stack[top++] = q - 1; }
      if (x < w - 1 && raw[q + 1] && !label[q + 1]) { label[q + 1] = next; stack[top++] = q + 1; }
      if (q >= w && raw[q - w] && !label[q - w]) { label[q - w] = next; stack[top++] = q - w; }
      if (q + w < n && raw[q + w] && !label[q + w]) { label[q + w] = next; stack[top++] = q + w; }
    }
    if (size > best) { best = size; bestLabel = next; }
  }
  const mask = new Uint8Array(n);
  let sx = 0, sy = 0;
  for (let p = 0; p < n; p++) {
    if (label[p] === bestLabel && best) { mask[p] = 1; sx += p % w; sy += Math.floor(p / w); }
  }
  const area = best;
  const result = { width: w, height: h, bg, area, coverage: area / n, oneColour, mask };
  if (area < Math.max(30, (rubric.minCoverage ?? 0.002) * n)) return { ...result, blank: true };
  const cx = sx / area + 0.5, cy = sy / area + 0.5;
  // radial profile: the farthest object pixel along 72 rays from the centroid
  const rmax = Math.hypot(w, h);
  const radii = [];
  for (let k = 0; k < 72; k++) {
    const a = (2 * Math.PI * k) / 72, dx = Math.cos(a), dy = Math.sin(a);
    let last = 0;
    for (let t = 0; t < rmax; t += 0.5) {
      const x = Math.floor(cx + t * dx), y = Math.floor(cy + t * dy);
      if (x < 0 || y < 0 || x >= w || y >= h) break;
      if (mask[y * w + x]) last = t + 0.5;
    }
    radii.push(last);
  }
  const mean = radii.reduce((s, r) => s + r, 0) / radii.length;
  const roundness = (Math.max(...radii) - Math.min(...radii)) / mean;
  const R = Math.sqrt(area / Math.PI);
  const fill = area / (Math.PI * mean * mean);
  const touches = radii.some((r, k) => {
    const a = (2 * Math.PI * k) / 72;
    const x = cx + r * Math.cos(a), y = cy + r * Math.sin(a);
    return x < 1.5 || y < 1.5 || x > w - 1.5 || y > h - 1.5;
  });
  const circle = fitCircle(img, mask, bg, tol);
  return { ...result, blank: false, cx, cy, R, radius: mean, roundness, fill, touches, circle };
}

/**
 * Thin lines drawn with the object (axes, a wireframe, a grid) are not the object: a morphological
 * opening by a square of side 2r + 1 (erode, then dilate) removes what is thinner than that and
 * leaves a solid disc as it was (its outline rounded at corners sharper than r pixels).
 */
export function openMask(mask, w, h, r) {
  if (!r) return mask;
  const tmp = new Uint8Array(mask.length);
  // erode then dilate, each as a horizontal and a vertical pass of a 1-D min (max) over 2r + 1,
  // read off a count of ones in the window (outside the picture counts as 0); the vertical pass
  // keeps a count per column and goes down the rows
  const full = 2 * r + 1;
  const count = new Int32Array(w + 1), col = new Int32Array(w);
  const pass = (src, dst, horizontal, keep) => {
    if (horizontal) {
      for (let y = 0, o = 0; y < h; y++, o += w) {
        for (let x = 0; x < w; x++) count[x + 1] = count[x] + src[o + x];
        for (let x = 0; x < w; x++) {
          const lo = x - r, hi = x + r;
          const ones = count[hi < w ? hi + 1 : w] - count[lo > 0 ? lo : 0];
          dst[o + x] = keep ? (ones === full ? 1 : 0) : (ones > 0 ? 1 : 0); // (a window cut by the edge never holds full)
        }
      }
      return;
    }
    col.fill(0);
    for (let y = 0; y < r && y < h; y++) for (let x = 0; x < w; x++) col[x] += src[y * w + x];
    for (let y = 0; y < h; y++) {
      const add = y + r, drop = y - r - 1;
      if (add < h) for (let x = 0, o = add * w; x < w; x++) col[x] += src[o + x];
      if (drop >= 0) for (let x = 0, o = drop * w; x < w; x++) col[x] -= src[o + x];
      for (let x = 0, o = y * w; x < w; x++) dst[o + x] = keep ? (col[x] === full ? 1 : 0) : (col[x] > 0 ? 1 : 0);
    }
  };
  pass(mask, tmp, true, true);
  const eroded = new Uint8Array(mask.length);
  pass(tmp, eroded, false, true);
  pass(eroded, tmp, true, false);
  const opened = new Uint8Array(mask.length);
  pass(tmp, opened, false, false);
  mask.set(opened);
  return mask;
}

/**
 * A circle through the object's outline where it stands out clearly from the background (a
 * sphere's unlit side may be as dark as a dark background: then only the lit edge is outline).
 * Kåsa's least-squares fit; roundness = spread of the edge's distances from the centre over the
 * radius; arc = the degrees of the circle that edge covers.
 */
export function fitCircle(img, mask, bg, tol) {
  const { width: w, height: h, data } = img;
  const pts = [];
  for (let y = 1; y < h - 1; y++) {
    for (let x = 1; x < w - 1; x++) {
      const p = y * w + x;
      if (!mask[p] || (mask[p - 1] && mask[p + 1] && mask[p - w] && mask[p + w])) continue;
      const o = 4 * p;
      if (Math.abs(data[o] - bg[0]) + Math.abs(data[o + 1] - bg[1]) + Math.abs(data[o + 2] - bg[2]) > 2.5 * tol) pts.push([x + 0.5, y + 0.5]);
    }
  }
  if (pts.length < 12) return null;
  // x² + y² + D x + E y + F = 0
  const A = [[0, 0, 0], [0, 0, 0], [0, 0, 0]], b = [0, 0, 0];
  for (const [x, y] of pts) {
    const row = [x, y, 1], z = -(x * x + y * y);
    for (let i = 0; i < 3; i++) { b[i] += row[i] * z; for (let j = 0; j < 3; j++) A[i][j] += row[i] * row[j]; }
  }
  const [D, E, F] = solve3(A, b);
  const cx = -D / 2, cy = -E / 2, r = Math.sqrt(Math.max(0, cx * cx + cy * cy - F));
  if (!(r > 0)) return null;
  const d = pts.map(([x, y]) => Math.hypot(x - cx, y - cy));
  const sorted = [...d].sort((a, c) => a - c);
  // the spread of the middle 96% (a stray pixel or two aside)
  const lo = sorted[Math.floor(0.02 * sorted.length)], hi = sorted[Math.ceil(0.98 * sorted.length) - 1];
  const bins = new Set(pts.map(([x, y]) => Math.floor(((Math.atan2(y - cy, x - cx) + Math.PI) / (2 * Math.PI)) * 36) % 36));
  return { cx, cy, r, roundness: (hi - lo) / r, arc: bins.size * 10, points: pts.length };
}

/** Interior samples: pixel colour (0..1) and the view-space normal a sphere has there. */
export function samples(img, an, { maxRho = 0.85, max = 4000 } = {}) {
  const { width: w, data } = img;
  const out = [];
  const r = an.radius;
  const x0 = Math.max(0, Math.floor(an.cx - r)), x1 = Math.min(w - 1, Math.ceil(an.cx + r));
  const y0 = Math.max(0, Math.floor(an.cy - r)), y1 = Math.min(img.height - 1, Math.ceil(an.cy + r));
  const step = Math.max(1, Math.floor(Math.sqrt(((x1 - x0 + 1) * (y1 - y0 + 1)) / max)));
  for (let y = y0; y <= y1; y += step) {
    for (let x = x0; x <= x1; x += step) {
      const p = y * w + x;
      if (!an.mask[p]) continue;
      const nx = (x + 0.5 - an.cx) / r, ny = -(y + 0.5 - an.cy) / r, rho2 = nx * nx + ny * ny;
      if (rho2 > maxRho * maxRho) continue;
      const o = 4 * p;
      out.push({ x, y, n: [nx, ny, Math.sqrt(1 - rho2)], c: [data[o] / 255, data[o + 1] / 255, data[o + 2] / 255] });
    }
  }
  return out;
}

function solve3(A, b) {
  const det = (m) => m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const d = det(A);
  if (Math.abs(d) < 1e-12) return [0, 0, 0];
  return [0, 1, 2].map((k) => det(A.map((row, i) => row.map((v, j) => (j === k ? b[i] : v)))) / d);
}
const det3 = (m) => m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);

/**
 * P1/P2: do the colours decode to unit normals d = 2c − 1, and is d a rotation of the normal a
 * sphere has at that pixel (front faces) or a reflection of it (the inside of the far side)?
 */
export function normalColours(pts) {
  if (pts.length < 20) return null;
  let lenErr = 0;
  const mean = [0, 0, 0];
  for (const s of pts) {
    const d = s.c.map((v) => 2 * v - 1);
    s.d = d;
    lenErr += Math.abs(Math.hypot(...d) - 1);
    for (let k = 0; k < 3; k++) mean[k] += s.c[k] / pts.length;
  }
  let spread = 0;
  for (const s of pts) spread += s.c.reduce((a, v, k) => a + (v - mean[k]) ** 2, 0);
  spread = Math.sqrt(spread / pts.length);
  // least squares d ≈ M n, row by row
  const NtN = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  const Ntd = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  for (const s of pts) {
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) { NtN[i][j] += s.n[i] * s.n[j]; Ntd[i][j] += s.n[i] * s.d[j]; }
    }
  }
  const M = [0, 1, 2].map((row) => solve3(NtN, [0, 1, 2].map((i) => Ntd[i][row])));
  let res = 0;
  for (const s of pts) {
    for (let row = 0; row < 3; row++) res += (s.d[row] - (M[row][0] * s.n[0] + M[row][1] * s.n[1] + M[row][2] * s.n[2])) ** 2;
  }
  return { unitError: lenErr / pts.length, spread, residual: Math.sqrt(res / pts.length), det: det3(M) };
}

const luminance = (c) => (c[0] + c[1] + c[2]) / 3;

function fibonacciDirections(n) {
  const out = [];
  for (let k = 0; k < n; k++) {
    const z = 1 - (2 * (k + 0.5)) / n, r = Math.sqrt(1 - z * z), a = k * Math.PI * (3 - Math.sqrt(5));
    out.push([r * Math.cos(a), r * Math.sin(a), z]);
  }
  return out;
}
const DIRS = fibonacciDirections(500);

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

function fitDirection(F, l, twoSided = false) {
  // brightness ≈ a + b max(n·l, 0) (or a + b |n·l|, lit on both sides): linear in (a, b) for a given l;
  // one pass: at the least-squares (a, b) the residual is Σy² − a Σy − b Σxy
  const { m, nx, ny, nz, y, sy, syy } = F;
  const l0 = l[0], l1 = l[1], l2 = l[2];
  let sx = 0, sxx = 0, sxy = 0;
  if (twoSided) {
    for (let i = 0; i < m; i++) {
      const x = Math.abs(nx[i] * l0 + ny[i] * l1 + nz[i] * l2);
      sx += x; sxx += x * x; sxy += x * y[i];
    }
  } else {
    for (let i = 0; i < m; i++) {
      const x = nx[i] * l0 + ny[i] * l1 + nz[i] * l2;
      if (x > 0) { sx += x; sxx += x * x; sxy += x * y[i]; }
    }
  }
  const den = m * sxx - sx * sx;
  const b = den > 1e-9 ? (m * sxy - sx * sy) / den : 0;
  const a = (sy - b * sx) / m;
  return { a, b, sse: Math.max(0, syy - a * sy - b * sxy), l };
}

/**
 * P3–P5: fit brightness = ambient + diffuse·max(n·w_i, 0) for some light direction w_i, leaving
 * out pixels much brighter than the fit (a highlight) on a second pass. Returns the fit's R²
 * (over the pixels fitted), the light direction, and the highlight those bright pixels make.
 */
export function diffuseFit(pts, rubric = {}) {
  if (pts.length < 20) return null;
  for (const s of pts) s.y = luminance(s.c);
  const meanY = pts.reduce((a, s) => a + s.y, 0) / pts.length;
  const sst = pts.reduce((a, s) => a + (s.y - meanY) ** 2, 0);
  // a pixel clipped at white (a channel at 1) says only "at least this bright": left out of the fit
  // while enough are left (a washed-out material), kept for the highlight above it
  const unclipped = Uint8Array.from(pts, (s) => Math.max(...s.c) < 0.99);
  let use = unclipped.reduce((a, v) => a + v, 0) >= Math.max(20, 0.3 * pts.length) ? unclipped : new Uint8Array(pts.length).fill(1);
  const use0 = use;
  let best = null, sseAll = null, F = null;
  const highlightMargin = rubric.highlightMargin ?? 0.12;
  for (let pass = 0; pass < 2; pass++) {
    best = null;
    F = flat(pts, use);
    for (const l of DIRS) {
      const f = fitDirection(F, l);
      if (f.b >= 0 && (!best || f.sse < best.sse)) best = f;
    }
    // refine around the best direction
    for (let step = 0.1; step > 0.005; step /= 2) {
      for (const d of [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]) {
        const l = best.l.map((v, k) => v + step * d[k]), len = Math.hypot(...l);
        const f = fitDirection(F, l.map((v) => v / len));
        if (f.b >= 0 && f.sse < best.sse) best = f;
      }
    }
    if (pass === 0) {
      sseAll = best.sse;
      use = Uint8Array.from(pts, (s, i) => use0[i] && s.y - (best.a + best.b * Math.max(0, s.n[0] * best.l[0] + s.n[1] * best.l[1] + s.n[2] * best.l[2])) < highlightMargin * 0.7);
    }
  }
  const used = use.reduce((a, v) => a + v, 0);
  const meanU = pts.reduce((a, s, i) => a + (use[i] ? s.y : 0), 0) / Math.max(1, used);
  const sstU = pts.reduce((a, s, i) => a + (use[i] ? (s.y - meanU) ** 2 : 0), 0);
  // the highlight: how far above the diffuse fit a pixel is, as a share of the headroom left to
  // white there (a highlight on a bright diffuse patch saturates at 1 and cannot rise far)
  const hl = highlightOf(pts, (n) => best.a + best.b * Math.max(0, n[0] * best.l[0] + n[1] * best.l[1] + n[2] * best.l[2]), rubric);
  // the same pixels under a two-sided model: a page lit on both sides (|n·w_i|) fits it better
  let twoSided = null, twoSidedAll = null;
  const Fall = flat(pts, null); // (F: the second pass's pixels, the highlight left out)
  for (const l of DIRS) {
    const f = fitDirection(F, l, true);
    if (f.b >= 0 && (!twoSided || f.sse < twoSided.sse)) twoSided = f;
    const g = fitDirection(Fall, l, true);
    if (g.b >= 0 && (!twoSidedAll || g.sse < twoSidedAll.sse)) twoSidedAll = g;
  }
  // ... and both models over all pixels, none left out as a highlight
  const r2All = sst > 1e-9 ? 1 - sseAll / sst : 0, r2TwoSidedAll = sst > 1e-9 ? 1 - twoSidedAll.sse / sst : 0;
  return { r2: sstU > 1e-9 ? 1 - best.sse / sstU : 0, r2TwoSided: sstU > 1e-9 ? 1 - twoSided.sse / sstU : 0, r2All, r2TwoSidedAll, rms: Math.sqrt(best.sse / Math.max(1, used)), ambient: best.a, diffuse: best.b,
    light: best.l, spread: Math.sqrt(sst / pts.length), highlightPeak: hl.peak, highlightRise: hl.rise, highlightShare: hl.bright / pts.length, highlightNormal: hl.normal,
    fitted: used / pts.length };
}

/**
 * The highlight above a model of the diffuse brightness (`predict(n)`): the largest rise of a
 * pixel over it as a share of the headroom to white there (`peak`: a highlight on a bright diffuse
 * patch saturates at 1 and cannot rise far), the largest rise itself (`rise`), and how many pixels
 * rise clearly (`bright`).
 */
export function highlightOf(pts, predict, rubric = {}) {
  const margin = rubric.highlightMargin ?? 0.12;
  let peak = 0, rise = 0, bright = 0;
  const rises = new Float64Array(pts.length);
  for (let i = 0; i < pts.length; i++) {
    const s = pts[i];
    const pred = predict(s.n);
    const r = luminance(s.c) - pred;
    rises[i] = r;
    if (r < (rubric.highlightMinRise ?? 0.06)) continue;
    const share = Math.min(1, r / Math.max(0.1, 1 - pred));
    peak = Math.max(peak, share);
    rise = Math.max(rise, r);
    if (r > margin || share > 0.8) bright++;
  }
  // where it is: the mean normal of the pixels that rise most (within 70% of the largest rise)
  let normal = null;
  if (rise > 0) {
    const m = [0, 0, 0];
    for (let i = 0; i < pts.length; i++) if (rises[i] >= 0.7 * rise) for (let k = 0; k < 3; k++) m[k] += pts[i].n[k] * rises[i];
    const len = Math.hypot(...m);
    if (len > 0) normal = m.map((v) => v / len);
  }
  return { peak, rise, bright, normal };
}

/**
 * How far (degrees) a highlight sits from where the Phong and Blinn-Phong models put it: at the
 * normal halfway between the direction to the light and the direction to the viewer (w_h =
 * normalize(w_i + w_o), w_o = +z toward the viewer; a perspective camera moves it a few degrees).
 * `toViewer` 0: how far from the light itself (w_i).
 */
export function highlightOffset(highlightNormal, light, toViewer = 1) {
  if (!highlightNormal || !light) return null;
  const h = [light[0], light[1], light[2] + toViewer];
  const len = Math.hypot(...h);
  if (len < 1e-6) return null; // the light straight behind: no half vector
  const c = (highlightNormal[0] * h[0] + highlightNormal[1] * h[1] + highlightNormal[2] * h[2]) / len;
  return (180 / Math.PI) * Math.acos(Math.max(-1, Math.min(1, c)));
}

/**
 * Is there a specular highlight above a fit (diffuseFit's, or a point-light model's)? Either it
 * rises far toward white (highlightPeak), or it stands clearly out of the fit's own noise: a
 * rise of highlightClearRise or more, highlightNoise times the fit's RMS, over a few pixels (a
 * small or tinted highlight on a clean fit; a page with no specular term has neither).
 */
export function highlightSeen(fit, rubric = {}) {
  if (fit.highlightPeak >= (rubric.highlightPeak ?? 0.5)) return true;
  return fit.highlightRise >= (rubric.highlightClearRise ?? 0.1) && fit.highlightRise >= (rubric.highlightNoise ?? 10) * fit.rms && fit.highlightShare > 0;
}

/**
 * How much the silhouette changed between two pictures: the relative change of its area, or of
 * its roundness, whichever is more (pixel flips along the edge alone do not count).
 */
export function silhouetteChange(a, b) {
  if (!a || !b || a.width !== b.width || a.height !== b.height || a.blank || b.blank) return a && b && a.blank && b.blank ? 0 : 1;
  return Math.max(Math.abs(a.area - b.area) / Math.max(a.area, b.area), Math.abs(a.roundness - b.roundness) / 3);
}

/**
 * The pixels where two pictures' objects differ (one mask has it, the other not), and how many of
 * them lie at the outline (farther than 0.9 of the radius from the centre): a finer or coarser
 * mesh at a high level moves only a few outline pixels, too few to change the area or roundness.
 */
export function outlineFlips(a, b) {
  if (!a || !b || a.blank || b.blank || a.width !== b.width || a.height !== b.height) return null;
  let flips = 0, atOutline = 0;
  const w = a.width, r = 0.9 * Math.min(a.radius, b.radius);
  for (let p = 0; p < a.mask.length; p++) {
    if (a.mask[p] === b.mask[p]) continue;
    flips++;
    const x = p % w, y = (p - x) / w;
    if (Math.hypot(x + 0.5 - a.cx, y + 0.5 - a.cy) >= r) atOutline++;
  }
  return { flips, atOutline, area: b.area - a.area };
}

/** RMS difference of brightness between two pictures over the pixels inside both objects. */
export function shadingChange(imgA, anA, imgB, anB, maxRho = 0.8) {
  let sum = 0, n = 0;
  const w = imgA.width;
  for (let p = 0; p < anA.mask.length; p++) {
    if (!anA.mask[p] || !anB.mask[p]) continue;
    const x = p % w, y = (p - x) / w;
    if (Math.hypot(x + 0.5 - anB.cx, y + 0.5 - anB.cy) > maxRho * anB.radius) continue;
    const o = 4 * p;
    const ya = (imgA.data[o] + imgA.data[o + 1] + imgA.data[o + 2]) / 765, yb = (imgB.data[o] + imgB.data[o + 1] + imgB.data[o + 2]) / 765;
    sum += (ya - yb) ** 2;
    n++;
  }
  return n ? Math.sqrt(sum / n) : null;
}

/** Whether two pictures differ anywhere (more than rounding). */
export function pictureChange(a, b) {
  if (!a || !b || a.width !== b.width || a.height !== b.height) return 1;
  let diff = 0;
  for (let o = 0; o < a.data.length; o += 4) {
    if (Math.abs(a.data[o] - b.data[o]) + Math.abs(a.data[o + 1] - b.data[o + 1]) + Math.abs(a.data[o + 2] - b.data[o + 2]) > 6) diff++;
  }
  return diff / (a.width * a.height);
}

/**
 * P3–P5: is the light a point light, and does it fall off as 1/r² (the slides: L_i = I/‖p_ℓ − x‖²)?
 * Brightness is fitted by a + b·max(n·w_i, 0)·g over the sphere seen as a unit sphere (x = n, the
 * normals of perspectiveSamples), the light at p_ℓ = d·l (d in sphere radii, from the centre), w_i = normalize(p_ℓ − x),
 * with g = 1/‖p_ℓ − x‖² (fall-off) or g = 1 (none). Both models hold a directional light (d → ∞),
 * so a far or directional light fits both alike: only a near light tells them apart. Pixels above
 * both fits (a highlight) and clipped ones are left out. Returns the best of each model.
 */
export function pointLightFit(pts, rubric = {}) {
  const use0 = pts.map((s) => Math.max(...s.c) < 0.985);
  if (use0.filter(Boolean).length < 50) return null;
  for (const s of pts) s.y = luminance(s.c);
  const DIST = [1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 7, 10, 20, 1e4];
  const fit = (use, l, d, falloff) => {
    let n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    const xs = new Float64Array(pts.length);
    for (let i = 0; i < pts.length; i++) {
      if (!use[i]) continue;
      const s = pts[i];
      const x = pointLightTerm(s.n, l, d, falloff);
      xs[i] = x;
      n++; sx += x; sy += s.y; sxx += x * x; sxy += x * s.y; syy += s.y * s.y;
    }
    const den = n * sxx - sx * sx;
    const b = den > 1e-9 ? (n * sxy - sx * sy) / den : 0;
    const a = (sy - b * sx) / n;
    return { a, b, l, d, falloff, sse: Math.max(0, syy - a * sy - b * sxy), xs };
  };
  const search = (use, falloff, around) => {
    let best = null;
    const dirs = DIRS.filter((l) => !around || l[0] * around[0] + l[1] * around[1] + l[2] * around[2] > 0.5);
    for (const d of DIST) {
      for (const l of dirs) {
        const f = fit(use, l, d, falloff);
        if (f.b > 0 && (!best || f.sse < best.sse)) best = f;
      }
    }
    if (!best) return null;
    for (let step = 0.1; step > 0.005; step /= 2) { // refine the direction, then the distance
      for (const dd of [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]) {
        const l = best.l.map((v, k) => v + step * dd[k]), len = Math.hypot(...l);
        const f = fit(use, l.map((v) => v / len), best.d, falloff);
        if (f.b > 0 && f.sse < best.sse) best = f;
      }
      for (const d of [Math.max(1.05, best.d * (1 - 2 * step)), Math.min(1e4, best.d * (1 + 2 * step))]) {
        const f = fit(use, best.l, d, falloff);
        if (f.b > 0 && f.sse < best.sse) best = f;
      }
    }
    return best;
  };
  let use = use0;
  let none = null, inv = null;
  const around = rubric.around || null;
  for (let pass = 0; pass < 2; pass++) {
    none = search(use, false, around);
    inv = search(use, true, around);
    if (!none || !inv) return null;
    if (pass === 0) {
      const margin = (rubric.highlightMargin ?? 0.12) * 0.7;
      use = pts.map((s, i) => use0[i] && Math.min(s.y - none.a - none.b * none.xs[i], s.y - inv.a - inv.b * inv.xs[i]) < margin);
    }
  }
  const used = use.reduce((a, v) => a + v, 0);
  const mean = pts.reduce((a, s, i) => a + (use[i] ? s.y : 0), 0) / used;
  const sst = pts.reduce((a, s, i) => a + (use[i] ? (s.y - mean) ** 2 : 0), 0);
  const brief = (f) => {
    const model = { a: f.a, b: f.b, l: f.l, d: f.d, falloff: f.falloff };
    const hl = highlightOf(pts, (n) => pointLightPredict(n, model), rubric);
    return { distance: f.d, light: f.l, r2: sst > 1e-12 ? 1 - f.sse / sst : 0, rms: Math.sqrt(f.sse / used), model, highlightPeak: hl.peak, highlightRise: hl.rise,
      highlightShare: hl.bright / pts.length, highlightNormal: hl.normal };
  };
  return { falloff: brief(inv), none: brief(none), fitted: used / pts.length };
}

/**
 * max(n·w_i, 0) at the unit sphere's point x = n for a point light at p_ℓ = d·l, w_i =
 * normalize(p_ℓ − x); with `falloff`, times 1/‖p_ℓ − x‖² scaled to 1 at the point nearest the light.
 */
function pointLightTerm(n, l, d, falloff) {
  const wx = d * l[0] - n[0], wy = d * l[1] - n[1], wz = d * l[2] - n[2];
  const r2 = wx * wx + wy * wy + wz * wz;
  const cos = Math.max(0, (n[0] * wx + n[1] * wy + n[2] * wz) / Math.sqrt(r2));
  return falloff ? cos * ((d - 1) * (d - 1)) / r2 : cos;
}

/** The brightness a fitted point-light model (pointLightFit's `model`) gives at a sample's normal. */
export function pointLightPredict(n, m) {
  return m.a + m.b * pointLightTerm(n, m.l, m.d, m.falloff);
}

/**
 * The highlight above a point-light model, as diffuseFit measures it above its directional fit:
 * the largest rise of a pixel over the model, as a share of the headroom to white there. A near
 * light's 1/r² bright spot is part of the model, not a highlight. `pts` are perspectiveSamples.
 */
export function highlightAbove(pts, model, rubric = {}) {
  return highlightOf(pts, (n) => pointLightPredict(n, model), rubric).peak;
}

/** 'falloff' or 'none': the model a near point light fits well (R² ≥ diffuseR2, d ≤ pointLightNear), or null. */
export function nearPointLight(pl, T) {
  if (!pl) return null;
  const good = ['falloff', 'none'].filter((k) => pl[k].r2 >= T.diffuseR2 && pl[k].distance <= T.pointLightNear);
  return good.sort((a, b) => pl[b].r2 - pl[a].r2)[0] || null;
}
/** Model `a` ('falloff' or 'none') clearly beats model `b`: a near light, R² higher by pointLightGain, RMS lower by pointLightRmsRatio. */
export function clearlyBetter(pl, a, b, T) {
  return pl[a].r2 - pl[b].r2 >= T.pointLightGain && pl[a].distance <= T.pointLightNear && pl[b].rms >= T.pointLightRmsRatio * pl[a].rms;
}
/** A light clearly near and falling off as 1/r²: it fits, and better than without the fall-off. */
export function clearlyNearFalloff(pl, T) {
  return !!pl && clearlyBetter(pl, 'falloff', 'none', T) && pl.falloff.r2 >= T.diffuseR2;
}

/**
 * Dark spots: pixels inside the sphere that a change of s made much darker than they were, and
 * darker than the diffuse + ambient fit of the judged picture predicts there. Lowering s never
 * darkens a pixel of the Phong or Blinn-Phong model (cos^s grows as s falls for cos in [0, 1]),
 * and no specular term takes light away: such pixels are holes (pow(0, 0) or pow of a negative
 * base, undefined: NaN, black on many GPUs). `img` is the judged picture, `after` the same view
 * with s lowered, `fit` img's diffuseFit.
 */
export function darkSpots(img, an, after, fit, rubric = {}) {
  const margin = rubric.darkSpotMargin ?? 0.15;
  const { width: w } = img;
  let dark = 0, n = 0;
  for (const s of samples(img, an)) {
    const o = 4 * (s.y * w + s.x);
    const before = (img.data[o] + img.data[o + 1] + img.data[o + 2]) / 765;
    const now = (after.data[o] + after.data[o + 1] + after.data[o + 2]) / 765;
    const pred = fit.ambient + fit.diffuse * Math.max(0, s.n[0] * fit.light[0] + s.n[1] * fit.light[1] + s.n[2] * fit.light[2]);
    n++;
    if (now < before - margin && now < pred - margin) dark++;
  }
  return n ? { share: dark / n, count: dark } : null;
}

/**
 * samples() with the normals a perspective camera sees: the eye on the sphere's axis, `fovy`
 * degrees high (the slides' perspective(45, …) unless told), at the distance that makes the
 * sphere's radius on screen; each pixel's ray meets the unit sphere at x, and n = x.
 */
export function perspectiveSamples(img, an, fovy = 45, opts = {}) {
  const t = Math.tan((fovy * Math.PI) / 360) / (img.height / 2);
  const D = 1 / Math.sin(Math.atan(an.radius * t));
  return samples(img, an, opts).map((s) => {
    const dx = (s.x + 0.5 - an.cx) * t, dy = -(s.y + 0.5 - an.cy) * t, len = Math.hypot(dx, dy, 1);
    const d = [dx / len, dy / len, -1 / len];
    const ed = D * d[2];
    const k = -ed - Math.sqrt(Math.max(0, ed * ed - D * D + 1));
    const x = [k * d[0], k * d[1], D + k * d[2]], xl = Math.hypot(...x);
    return { ...s, n: x.map((v) => v / xl) };
  });
}
