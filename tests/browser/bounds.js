// What a step's picture is held to against the exact sphere, in every engine and API: the colours
// 0.5 p + 0.5 of the unlit steps (WP04P1, WP04P2), and each lit step's bound against the exact
// render (common/exact-render.js). Chromium's specs and the Firefox suite share them, so that
// both engines are held to the same numbers.
import { expect } from '@playwright/test';
import { SHADING_RMSE } from '../../common/sphere.js';

// Where the ray through pixel (i, j)'s centre meets the unit sphere: [near point, far point] or null.
function sphereHits(camera, width, height, i, j) {
  const sub = (a, b) => a.map((v, k) => v - b[k]);
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const norm = (a) => a.map((v) => v / Math.hypot(...a));
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const f = norm(sub(camera.at, camera.eye));
  const r = norm(cross(f, camera.up));
  const u = cross(r, f);
  const t = Math.tan((camera.fovy * Math.PI) / 360);
  const x = ((2 * (i + 0.5)) / width - 1) * t * camera.aspect;
  const y = (1 - (2 * (j + 0.5)) / height) * t;
  const d = norm([0, 1, 2].map((k) => f[k] + x * r[k] + y * u[k]));
  const b = dot(camera.eye, d);
  const c = dot(camera.eye, camera.eye) - 1;
  const disc = b * b - c;
  if (disc <= 0) return null;
  const at = (s) => camera.eye.map((e, k) => e + s * d[k]);
  const near = at(-b - Math.sqrt(disc));
  return { near, far: at(-b + Math.sqrt(disc)), cosine: Math.sqrt(disc) };
}

const normalColour = (p) => p.map((v) => Math.round(255 * (0.5 * v + 0.5)));
const BACKGROUND = [100, 149, 237];

/** Compares sampled pixels with c = 0.5 p + 0.5 of the near (and, if allowed, the far) sphere point. */
export function checkNormalColours(img, camera, { allowFar = false, useFar = false, tolerance = 3 } = {}) {
  let checked = 0;
  const bad = [];
  for (let j = 2; j < img.height; j += 5) {
    for (let i = 2; i < img.width; i += 5) {
      const o = 4 * (j * img.width + i);
      const got = [img.data[o], img.data[o + 1], img.data[o + 2]];
      const hit = sphereHits(camera, img.width, img.height, i, j);
      if (!hit) {
        expect(got, `background at ${i},${j}`).toEqual(BACKGROUND);
        continue;
      }
      if (hit.cosine < 0.25) continue; // near the silhouette the mesh's chords differ from the sphere
      const candidates = useFar ? [hit.far] : allowFar ? [hit.near, hit.far] : [hit.near];
      const ok = candidates.some((p) => normalColour(p).every((v, k) => Math.abs(v - got[k]) <= tolerance));
      checked++;
      if (!ok) bad.push(`${i},${j}: got ${got}, want ${candidates.map(normalColour).join(' or ')}`);
    }
  }
  expect(checked).toBeGreaterThan(200);
  expect(bad.slice(0, 5)).toEqual([]);
}

/**
 * A lit step's interior RMSE bound against the exact render, in 8-bit steps, at its level: Gouraud
 * (WP04P3 diffuse, WP04P4 with highlights) its measured error at that level (SHADING_RMSE, default
 * view) plus a margin, as the highlight falls elsewhere on the mesh away from the default view;
 * Phong shading (WP04P5) 1/255.
 */
export function litBound(step, level) {
  return { WP04P3: SHADING_RMSE.diffuse[level] + 0.5, WP04P4: SHADING_RMSE.gouraud[level] + 0.5, WP04P5: 1 }[step];
}

/**
 * Holds a lit step's compareToReference stats to its bound: interior RMSE (litBound), silhouette
 * within 0.5% of the sphere's pixels, no NaN-black pixel, no saturated pixel where the reference is
 * not (Gouraud: 8, where the true highlight saturates its interpolated one ends a pixel or two off).
 */
export function expectWithinLitBound(stats, step, level, view) {
  expect(stats.rmse * 255, `${view}: interior RMSE in 8-bit steps`).toBeLessThanOrEqual(litBound(step, level));
  expect(stats.silhouetteMismatchRatio, `${view}: silhouette mismatch`).toBeLessThanOrEqual(0.005);
  expect(stats.nanLike, `${view}: NaN-black pixels`).toBe(0);
  expect(stats.saturated, `${view}: saturated pixels where the reference is not`).toBeLessThanOrEqual(step === 'WP04P4' ? 8 : 0);
}

/** Prints a comparison's numbers and keeps them as an annotation of the test. */
export function report(testInfo, label, stats) {
  const line = `${label}: interior RMSE ${(stats.rmse * 255).toFixed(3)}/255, max ${(stats.maxError * 255).toFixed(1)}/255, ` +
    `silhouette mismatch ${stats.silhouetteMismatch} px (${(100 * stats.silhouetteMismatchRatio).toFixed(2)}% of ${stats.spherePixels})`;
  testInfo.annotations.push({ type: 'error', description: line });
  console.log(`[${testInfo.project.name}] ${line}`);
}
