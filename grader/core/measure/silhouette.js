// The object in a picture: the background (the commonest border colour), the object's mask (thin
// lines opened away), and its silhouette (radial profile, roundness, fill, a circle fitted to the
// lit edge). An image is { width, height, data } (RGBA bytes); thresholds are the rubric's.
import { solve3 } from './linear.js';

/** A colour packed in one number, red and green shifted by these bits; SIX_BITS keeps a channel's 6 bits (the background's key). */
const RED_SHIFT = 16, GREEN_SHIFT = 8, SIX_BITS = 63;
/** The radial profile's rays from the centroid, and the lit edge's arc counted in bins of BIN_DEGREES (the mechanics of a fit). */
const RAYS = 72, ARC_BINS = 36, BIN_DEGREES = 10;

/** The background (the commonest border colour), the object's mask and its silhouette. */
export function analyse(img, thresholds) {
  const { width: w, height: h, data } = img;
  const tol = thresholds.backgroundTolerance;
  const counts = new Map();
  const border = [];
  for (let x = 0; x < w; x++) border.push([x, 0], [x, h - 1]);
  for (let y = 0; y < h; y++) border.push([0, y], [w - 1, y]);
  for (const [x, y] of border) {
    const o = 4 * (y * w + x);
    const key = (data[o] >> 2) << RED_SHIFT | (data[o + 1] >> 2) << GREEN_SHIFT | (data[o + 2] >> 2);
    counts.set(key, (counts.get(key) || 0) + 1);
  }
  const top = [...counts.entries()].sort((a, b) => b[1] - a[1])[0][0];
  const bg = [(top >> RED_SHIFT & SIX_BITS) * 4 + 2, (top >> GREEN_SHIFT & SIX_BITS) * 4 + 2, (top & SIX_BITS) * 4 + 2];
  const n = w * h;
  const raw = new Uint8Array(n);
  const first = data[0] << RED_SHIFT | data[1] << GREEN_SHIFT | data[2];
  let oneColour = true;
  const b0 = bg[0], b1 = bg[1], b2 = bg[2];
  for (let p = 0; p < n; p++) {
    const o = 4 * p, r = data[o], g = data[o + 1], b = data[o + 2];
    if (oneColour && (r << RED_SHIFT | g << GREEN_SHIFT | b) !== first) oneColour = false;
    if (Math.abs(r - b0) + Math.abs(g - b1) + Math.abs(b - b2) > tol) raw[p] = 1;
  }
  openMask(raw, w, h, thresholds.thinLine);
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
  if (area < Math.max(thresholds.minObjectPixels, thresholds.minCoverage * n)) return { ...result, blank: true };
  const cx = sx / area + 0.5, cy = sy / area + 0.5;
  // radial profile: the farthest object pixel along 72 rays from the centroid
  const rmax = Math.hypot(w, h);
  const radii = [];
  for (let k = 0; k < RAYS; k++) {
    const a = (2 * Math.PI * k) / RAYS, dx = Math.cos(a), dy = Math.sin(a);
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
    const a = (2 * Math.PI * k) / RAYS;
    const x = cx + r * Math.cos(a), y = cy + r * Math.sin(a);
    const m = thresholds.edgeMarginPixels;
    return x < m || y < m || x > w - m || y > h - m;
  });
  const circle = fitCircle(img, mask, bg, tol, thresholds);
  return { ...result, blank: false, cx, cy, R, radius: mean, roundness, fill, touches, circle };
}

/**
 * Thin lines drawn with the object (axes, a wireframe, a grid) are not the object: a morphological
 * opening by a square of side 2r + 1 (erode, then dilate) removes what is thinner than that and
 * leaves a solid disc as it was (its outline rounded at corners sharper than r pixels).
 */
export function openMask(mask, w, h, r) {
  if (!r) return mask;
  // an opening only takes ones away, so it is done in the box around the ones, as a picture of
  // its own whose outside counts as 0 (as the picture's does, and all round the box it holds no
  // one): the same mask, for a fraction of the work where the object is small in the picture
  let x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (let y = 0, o = 0; y < h; y++, o += w) {
    for (let x = 0; x < w; x++) {
      if (!mask[o + x]) continue;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      y1 = y;
    }
  }
  if (x1 < 0) return mask;
  const bw = x1 - x0 + 1, bh = y1 - y0 + 1;
  const box = new Uint8Array(bw * bh);
  for (let y = 0; y < bh; y++) box.set(mask.subarray((y0 + y) * w + x0, (y0 + y) * w + x0 + bw), y * bw);
  const opened = openBox(box, bw, bh, r);
  for (let y = 0; y < bh; y++) mask.set(opened.subarray(y * bw, (y + 1) * bw), (y0 + y) * w + x0);
  return mask;
}

/** The opening of a w × h mask by a square of side 2r + 1 (outside the mask counts as 0): a new mask. */
function openBox(mask, w, h, r) {
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
  return opened;
}

/**
 * A circle through the object's outline where it stands out clearly from the background (a
 * sphere's unlit side may be as dark as a dark background: then only the lit edge is outline).
 * Kåsa's least-squares fit; roundness = spread of the edge's distances from the centre over the
 * radius; arc = the degrees of the circle that edge covers.
 */
export function fitCircle(img, mask, bg, tol, thresholds) {
  const { width: w, height: h, data } = img;
  const pts = [];
  for (let y = 1; y < h - 1; y++) {
    for (let x = 1; x < w - 1; x++) {
      const p = y * w + x;
      if (!mask[p] || (mask[p - 1] && mask[p + 1] && mask[p - w] && mask[p + w])) continue;
      const o = 4 * p;
      if (
        Math.abs(data[o] - bg[0]) + Math.abs(data[o + 1] - bg[1]) + Math.abs(data[o + 2] - bg[2]) >
        thresholds.litEdgeContrast * tol
      ) {
        pts.push([x + 0.5, y + 0.5]);
      }
    }
  }
  if (pts.length < thresholds.minEdgePoints) return null;
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
  // the spread of the middle of the distances (edgeTrim of them left out at each end: a stray pixel or two)
  const lo = sorted[Math.floor(thresholds.edgeTrim * sorted.length)],
    hi = sorted[Math.ceil((1 - thresholds.edgeTrim) * sorted.length) - 1];
  const bins = new Set(
    pts.map(([x, y]) => Math.floor(((Math.atan2(y - cy, x - cx) + Math.PI) / (2 * Math.PI)) * ARC_BINS) % ARC_BINS),
  );
  return { cx, cy, r, roundness: (hi - lo) / r, arc: bins.size * BIN_DEGREES, points: pts.length };
}
