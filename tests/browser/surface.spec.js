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
import { surfaceOf, degreesBetween, clipMatrix } from '../../grader/core/computed/surface.js';
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
