// The surface per pixel as the grader reads it from what a page sent (grader/browser/surface.js,
// surface-webgpu.js, grader/core/computed/surface.js), on our own lit steps in WebGL 2, WebGL 1 and
// WebGPU: each pixel's normal within 1° of the exact sphere's (tools/reference/render.js, with the
// page's own window.scene), the camera found from the page's matrices where the scene says it is, and
// nothing of the grader's own drawing counted or recorded as the page's.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { nativesInit } from '../../grader/browser/natives.js';
import { instrumentScript } from '../../grader/browser/instrument.js';
import { recordersInit } from '../../grader/browser/geometry.js';
import { webgpuCaptureScript } from '../../grader/browser/webgpu-capture.js';
import { surfaceOf, degreesBetween, clipMatrix, cameraOfClip } from '../../grader/core/computed/surface.js';
import { renderReference } from '../../tools/reference/render.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const SIZE = 128;

/** The page's surface as the grader reads it, its pictures as { width, height, data }, and window.scene. */
async function surfaceOfPage(page, url) {
  await page.goto(url);
  await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
  return page.evaluate(async () => {
    const seen = () => ({ draws: window.__grade.draws, glsl: window.__grade.glsl.length, wgsl: window.__grade.wgsl.length, errors: window.__grade.shaderErrors.length,
      gpuErrors: window.__grade.gpuErrors.length, faces: JSON.stringify(window.__grade.faces), frames: window.__webgpuCapture ? window.__webgpuCapture.frames : 0,
      recorded: window.__geometry.history.length });
    const before = seen();
    const s = await window.__geometry.surface({ fitSamples: 256 });
    const after = seen();
    const picture = (bytes) => ({ width: s.width, height: s.height, data: Array.from(bytes) });
    return { scene: window.scene, before, after, surface: s.why ? s : { ...s, normals: picture(s.normals), points: picture(s.points) } };
  });
}

// WebGL 1's steps are WebGL 2's JavaScript and GLSL 1.0 (only getContext differs): one step there.
// WebGPU's steps draw the same sphere with their own WGSL: drawn again on the page's own device.
const CASES = [
  ...['webgl2', 'webgl'].flatMap((api) => [['WP04P3', ''], ['WP04P4', '&angle=0.7'], ['WP04P5', '&angle=1.2']]
    .filter(([st]) => api === 'webgl2' || st === 'WP04P4').map(([step, query]) => ({ api, project: 'webgl2', step, query }))),
  // (WP04P4 a second time multisampled, as the slides make it: the draws go into a 4× target resolved to the canvas)
  ...[['WP04P3', ''], ['WP04P4', '&angle=0.7'], ['WP04P5', '&angle=1.2'], ['WP04P4', '&angle=0.7&msaa=4']].map(([step, query]) => ({ api: 'webgpu', project: 'webgpu', step, query })),
];

for (const { api, project, step, query } of CASES) {
  test(`${step} in ${api}${query.includes('msaa') ? ', multisampled' : ''}: the page's own surface per pixel, within 1° of the exact sphere's normals`, async ({ browser, baseURL }, testInfo) => {
    test.skip(testInfo.project.name !== project, `its own pages in ${api}: once is enough`);
    const context = await browser.newContext();
    try {
      const scripts = [nativesInit, ...(api === 'webgpu' ? [webgpuCaptureScript] : []), instrumentScript, recordersInit];
      for (const script of scripts) await context.addInitScript(script);
      const page = await context.newPage();
      const { scene, before, after, surface } = await surfaceOfPage(page, `${baseURL}/${step}/?api=${api}&orbit=0&size=${SIZE}${query}`);
      expect(surface.why).toBeUndefined();
      // the grader's drawing is its own: no draw, frame, shader, error or culling state of the page's changed
      expect(after).toEqual(before);
      const ref = renderReference({ ...scene, shading: 'normals' }, SIZE, SIZE);
      let compared = 0, within = 0, worst = 0;
      for (let y = 2; y < SIZE - 2; y++) {
        for (let x = 2; x < SIZE - 2; x++) {
          // inside the sphere: the pixel and its neighbours two pixels away covered in both
          const inside = [[0, 0], [2, 0], [-2, 0], [0, 2], [0, -2]].every(([dx, dy]) => ref.coverage[(y + dy) * SIZE + x + dx] && surface.normals.data[4 * ((y + dy) * SIZE + x + dx) + 3]);
          if (!inside) continue;
          const o = 4 * (y * SIZE + x), r = 3 * (y * SIZE + x);
          const n = [0, 1, 2].map((k) => (2 * surface.normals.data[o + k]) / 255 - 1), l = Math.hypot(...n);
          const e = [0, 1, 2].map((k) => 2 * ref.rgb[r + k] - 1), le = Math.hypot(...e);
          const d = degreesBetween(n.map((v) => v / l), e.map((v) => v / le));
          compared++;
          if (d <= 1) within++;
          worst = Math.max(worst, d);
        }
      }
      testInfo.annotations.push({ type: 'surface', description: `${step} ${api}: ${compared} pixels, ${within} within 1°, worst ${worst.toFixed(2)}°` });
      expect(compared).toBeGreaterThan(2000);
      expect(within / compared).toBeGreaterThanOrEqual(0.99);
      // the camera found from where the page's matrices put its positions is the scene's
      const clip = clipMatrix(surface.fit.map((f) => ({ p: f.slice(0, 3), clip: f.slice(3, 7) })));
      const s = surfaceOf({ ...surface, clip, normals: 'n', points: 'p' }, { n: surface.normals, p: surface.points }, T);
      for (let k = 0; k < 3; k++) expect(Math.abs(s.camera.eye[k] - scene.camera.eye[k])).toBeLessThan(1e-3);
    } finally {
      await context.close();
    }
  });
}

// A WebGPU page shaped as our steps are not (tests/fixtures/surface-webgpu.html): its inputs in a
// struct, a normal attribute of its own, n = (p.y, p.z, p.x), in a second vertex buffer, an indexed
// draw and a second bind group. Each pixel's normal is the page's attribute, interpolated: within
// 1° of the permuted normal of the sphere point the pixel's ray meets (the eye at (0, 0, 3), 45°),
// and nowhere near the position itself.
test('a WebGPU page with its own normal attribute, an indexed draw and two bind groups: its surface carries that attribute', async ({ browser, baseURL }, testInfo) => {
  test.skip(testInfo.project.name !== 'webgpu', 'a WebGPU page');
  const context = await browser.newContext();
  try {
    for (const script of [nativesInit, webgpuCaptureScript, instrumentScript, recordersInit]) await context.addInitScript(script);
    const page = await context.newPage();
    await page.goto(`${baseURL}/tests/fixtures/surface-webgpu.html`);
    await page.waitForFunction(() => window.drawn === true);
    const surface = await page.evaluate(async () => {
      const s = await window.__geometry.surface({ fitSamples: 256 });
      return s.why ? s : { ...s, normals: Array.from(s.normals), points: null };
    });
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
  } finally {
    await context.close();
  }
});
