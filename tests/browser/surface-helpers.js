// What the surface specs share (surface.spec.js: our steps in WebGL 2 and WebGL 1;
// surface-webgpu.spec.js: in WebGPU, and a page shaped as ours are not): reading a page's surface as
// the grader reads it, and the test that holds one of our own steps to the exact sphere's normals
// (common/exact-render.js, with the page's own window.scene) and the camera to the scene's.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { nativesInit } from '../../grader/browser/natives.js';
import { instrumentScript } from '../../grader/browser/instrument.js';
import { recordersInit } from '../../grader/browser/geometry.js';
import { webgpuCaptureScript } from '../../grader/browser/webgpu-capture.js';
import { surfaceOf, degreesBetween, clipMatrix } from '../../grader/core/computed/surface.js';
import { renderReference } from '../../common/exact-render.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
export const SIZE = 128;

/** The init scripts a graded page gets, in the grader's order, for `api`. */
export const initScripts = (api) => [nativesInit, ...(api === 'webgpu' ? [webgpuCaptureScript] : []), instrumentScript, recordersInit];

/** The page's surface as the grader reads it, its pictures as { width, height, data }, and window.scene. */
export async function surfaceOfPage(page, url) {
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

/**
 * `look(page)` on a fixture page (`file` under tests/fixtures/, which sets window.drawn once it has
 * drawn), opened in a context of its own with the grader's init scripts for `api`.
 */
export async function onFixture(browser, baseURL, api, file, look) {
  const context = await browser.newContext();
  try {
    for (const script of initScripts(api)) await context.addInitScript(script);
    const page = await context.newPage();
    await page.goto(`${baseURL}/tests/fixtures/${file}`);
    await page.waitForFunction(() => window.drawn === true);
    return await look(page);
  } finally {
    await context.close();
  }
}

/**
 * A fixture page's surface (onFixture): its pictures' bytes as arrays (the points left out), or
 * { why }; and the draws and vertices the grader counted (counted).
 */
export const surfaceOfFixture = (browser, baseURL, api, file) => onFixture(browser, baseURL, api, file, (page) =>
  page.evaluate(async () => {
    const s = await window.__geometry.surface({ fitSamples: 256 });
    const counted = { draws: window.__grade.draws, vertices: window.__grade.vertices };
    return s.why ? { ...s, counted } : { ...s, normals: Array.from(s.normals), points: null, counted };
  }));

/**
 * One test a case ({ api, step, query }): the step's own surface per pixel within 1° of the exact
 * sphere's normals on 99% of its pixels, the camera within 1e-3, nothing of the page's changed.
 */
export function ownStepSurfaceTests(cases) {
  for (const { api, step, query } of cases) {
    test(`${step} in ${api}${query.includes('msaa') ? ', multisampled' : ''}: the page's own surface per pixel, within 1° of the exact sphere's normals`, async ({ browser, baseURL }, testInfo) => {
      const context = await browser.newContext();
      try {
        for (const script of initScripts(api)) await context.addInitScript(script);
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
}
