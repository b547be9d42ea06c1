// The surface per pixel as the grader reads it from what a WebGPU page sent
// (grader/browser/surface-webgpu.js: drawn again on the page's own device), on our own lit steps in
// WebGPU, WP04P4 also multisampled as the slides make it (tests/browser/surface-helpers.js), and on a
// page shaped as ours are not.
import { test, expect } from '@playwright/test';
import { ownStepSurfaceTests, surfaceOfFixture, SIZE } from './surface-helpers.js';
import { degreesBetween, clipMatrix, cameraOfClip } from '../../grader/core/computed/surface.js';

ownStepSurfaceTests([['WP04P3', ''], ['WP04P4', '&angle=0.7'], ['WP04P5', '&angle=1.2'], ['WP04P4', '&angle=0.7&msaa=4']]
  .map(([step, query]) => ({ api: 'webgpu', step, query })));

// A WebGPU page shaped as our steps are not (tests/fixtures/surface-webgpu.html): its inputs in a
// struct, a normal attribute of its own, n = (p.y, p.z, p.x), in a second vertex buffer, an indexed
// draw and a second bind group. Each pixel's normal is the page's attribute, interpolated: within
// 1° of the permuted normal of the sphere point the pixel's ray meets (the eye at (0, 0, 3), 45°),
// and nowhere near the position itself.
test('a WebGPU page with its own normal attribute, an indexed draw and two bind groups: its surface carries that attribute', async ({ browser, baseURL }, testInfo) => {
  const surface = await surfaceOfFixture(browser, baseURL, 'webgpu', 'surface-webgpu.html');
  expect(surface.why).toBeUndefined();
  expect([surface.position, surface.normal]).toEqual(['aPos', 'aNormal']);
  const f = 1 / Math.tan(Math.PI / 8), eye = [0, 0, 3];
  let compared = 0, attribute = 0, position = 0;
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const o = 4 * (y * SIZE + x);
      if (surface.normals[o + 3] !== 255) continue;
      // the pixel's ray from the eye, and the sphere point it meets first
      const d = [((2 * (x + 0.5)) / SIZE - 1) / f, (1 - (2 * (y + 0.5)) / SIZE) / f, -1], dl = Math.hypot(...d);
      const u = d.map((v) => v / dl), b = eye[0] * u[0] + eye[1] * u[1] + eye[2] * u[2], disc = b * b - (9 - 1);
      if (disc < 0.05) continue; // (the rim: the triangles' outline and the sphere's differ there)
      const t = -b - Math.sqrt(disc), p = eye.map((e, k) => e + t * u[k]);
      const n = [0, 1, 2].map((k) => (2 * surface.normals[o + k]) / 255 - 1), l = Math.hypot(...n);
      const seen = n.map((v) => v / l);
      compared++;
      if (degreesBetween(seen, [p[1], p[2], p[0]]) <= 1) attribute++;
      if (degreesBetween(seen, p) <= 1) position++;
    }
  }
  testInfo.annotations.push({ type: 'surface', description: `${compared} pixels, ${attribute} within 1° of the attribute, ${position} of the position` });
  expect(compared).toBeGreaterThan(2000);
  expect(attribute / compared).toBeGreaterThanOrEqual(0.99);
  expect(position / compared).toBeLessThan(0.05);
  // the camera from where the page's matrix put its positions
  const clip = clipMatrix(surface.fit.map((q) => ({ p: q.slice(0, 3), clip: q.slice(3, 7) })));
  const camera = cameraOfClip(clip);
  for (let k = 0; k < 3; k++) expect(Math.abs(camera.eye[k] - eye[k])).toBeLessThan(1e-3);
});
