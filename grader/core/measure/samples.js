// Samples of the sphere inside its silhouette: each pixel's colour (0..1) and the normal a sphere
// has there, seen by an orthographic or a perspective camera; and a colour's brightness.
import { CHANNEL_MAX, FULL_TURN } from '../units.js';

/**
 * Interior samples: pixel colour (0..1) and the view-space normal a sphere has there, within
 * `maxRho` of the radius (the rubric's sampleRadius: the rim's pixels mix with the background), at
 * most `max` of them (maxSamples), on a regular grid.
 */
export function samples(img, an, thresholds, { maxRho = thresholds.sampleRadius, max = thresholds.maxSamples } = {}) {
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
      const c = [data[o] / CHANNEL_MAX, data[o + 1] / CHANNEL_MAX, data[o + 2] / CHANNEL_MAX];
      out.push({ x, y, n: [nx, ny, Math.sqrt(1 - rho2)], c });
    }
  }
  return out;
}

/**
 * samples() with the normals a perspective camera sees: the eye on the sphere's axis, the rubric's
 * pointLightFovy degrees high (the slides' perspective(45, …)), at the distance that makes the
 * sphere's radius on screen; each pixel's ray meets the unit sphere at x, and n = x.
 */
export function perspectiveSamples(img, an, thresholds, opts = {}) {
  const t = Math.tan((thresholds.pointLightFovy * Math.PI) / FULL_TURN) / (img.height / 2);
  const D = 1 / Math.sin(Math.atan(an.radius * t));
  return samples(img, an, thresholds, opts).map((s) => {
    const dx = (s.x + 0.5 - an.cx) * t, dy = -(s.y + 0.5 - an.cy) * t, len = Math.hypot(dx, dy, 1);
    const d = [dx / len, dy / len, -1 / len];
    const ed = D * d[2];
    const k = -ed - Math.sqrt(Math.max(0, ed * ed - D * D + 1));
    const x = [k * d[0], k * d[1], D + k * d[2]], xl = Math.hypot(...x);
    return { ...s, n: x.map((v) => v / xl) };
  });
}

/** A sample colour's brightness: the mean of its channels. */
export const luminance = (c) => (c[0] + c[1] + c[2]) / 3;

/** Do two masks (a truthy entry a sample picked) pick the same samples? */
export function sameMask(a, b) {
  for (let i = 0; i < a.length; i++) if (!a[i] !== !b[i]) return false;
  return true;
}

/** The share of the sphere's samples (the outline `an`) white (every channel at clippedLevel). */
export function clippedShare(img, an, thresholds) {
  const pts = samples(img, an, thresholds);
  return pts.length ? pts.filter((s) => Math.min(...s.c) >= thresholds.clippedLevel).length / pts.length : 0;
}
