// The surface per pixel of a WebGL page whose model matrix is an instanced `attribute mat4`
// (tests/fixtures/surface-instanced.html, shaped as a real hand-in is): the grader's redraw
// (grader/browser/surface.js) must set all four of its locations, each with its divisor, as the
// page did (grader/browser/geometry.js records the divisor), and draw an instanced draw again as
// one (grader/browser/instanced-draws.js counts the page's). Each pixel's normal (n = p: the
// position in the model's space) is within 1° of the moved sphere's normal where its ray meets it.
// And the grader's experiment with culling off reaches an instanced draw as it reaches a plain one.
// Each way again with the position's index written as `gl.aPos`, a property never set: WebGL takes
// undefined as 0, and so must the recorder (grader/browser/webgl-args.js), in WebGL 1 and 2 alike.
import { test, expect } from '@playwright/test';
import { surfaceOfFixture, onFixture, SIZE } from './surface-helpers.js';
import { degreesBetween } from '../../grader/core/computed/surface.js';

// (the three ways the page draws: one instance with plain drawArrays; two, the first out of view,
// with ANGLE_instanced_arrays' drawArraysInstancedANGLE in WebGL 1 and WebGL 2's drawElementsInstanced)
const WAYS = [
  ['plain drawArrays', '', 1],
  ['two instances, drawArraysInstancedANGLE', '?draw=angle', 2],
  ['two instances, WebGL 2\'s drawElementsInstanced', '?draw=webgl2', 2],
];
const LOOSE = WAYS.map(([way, query, n]) => [`${way}, the position's index gl.aPos (undefined)`, `${query}${query ? '&' : '?'}loose`, n]);
for (const [way, query, instances] of [...WAYS, ...LOOSE]) {
  test(`a model matrix as an instanced mat4 attribute (divisor 1, ${way}): the surface is the page's own sphere, its vertices counted`, async ({ browser, baseURL }, testInfo) => {
    const surface = await surfaceOfFixture(browser, baseURL, 'webgl', `surface-instanced.html${query}`);
    expect(surface.why).toBeUndefined();
    expect([surface.width, surface.position, surface.normal]).toEqual([SIZE, 'aPos', null]);
    // the page's one draw of 32·64·6 vertices an instance, as the grader counts the page's work
    expect(surface.counted).toEqual({ draws: 1, vertices: instances * 32 * 64 * 6 });
    const f = 1 / Math.tan(Math.PI / 8), eye = [0, 0, 3], centre = [0.25, 0, 0];
    let compared = 0, within = 0, drawn = 0;
    for (let y = 0; y < SIZE; y++) {
      for (let x = 0; x < SIZE; x++) {
        const o = 4 * (y * SIZE + x);
        if (surface.normals[o + 3]) drawn++;
        // the pixel's ray from the eye, and the moved sphere's point it meets first
        const d = [((2 * (x + 0.5)) / SIZE - 1) / f, (1 - (2 * (y + 0.5)) / SIZE) / f, -1], dl = Math.hypot(...d);
        const u = d.map((v) => v / dl), e = eye.map((v, k) => v - centre[k]);
        const b = e[0] * u[0] + e[1] * u[1] + e[2] * u[2], disc = b * b - (e[0] ** 2 + e[1] ** 2 + e[2] ** 2 - 1);
        if (disc < 0.05) continue; // (the rim: the triangles' outline and the sphere's differ there)
        compared++;
        if (surface.normals[o + 3] !== 255) continue;
        const t = -b - Math.sqrt(disc), p = e.map((v, k) => v + t * u[k]);
        const n = [0, 1, 2].map((k) => (2 * surface.normals[o + k]) / 255 - 1), l = Math.hypot(...n);
        if (degreesBetween(n.map((v) => v / l), p) <= 1) within++;
      }
    }
    testInfo.annotations.push({ type: 'surface', description: `${compared} pixels inside the sphere, ${within} within 1°, ${drawn} drawn again` });
    expect(compared).toBeGreaterThan(2000);
    expect(within / compared).toBeGreaterThanOrEqual(0.99);
    expect(drawn).toBeLessThan(1.1 * compared + 16 * Math.sqrt(compared)); // (nothing drawn outside the sphere but its rim)
  });
}

// the grader's experiment (gather/faces.js): the page's own frame drawn again with culling off,
// where the page culls its front faces: the near side, culled, shows again, in every way of drawing
for (const [way, query] of WAYS) {
  test(`with culling off (${way}, the front faces culled): the near side shows, as the grader's experiment asks`, async ({ browser, baseURL }) => {
    await onFixture(browser, baseURL, 'webgl', `surface-instanced.html${query}${query ? '&' : '?'}cull=front`, async (page) => {
      // the blue of the pixel at the moved sphere's centre: 0.5·p_z + 0.5, near side 1, far side 0
      const blue = () => page.evaluate(() => {
        const gl = document.getElementById('c').getContext(window.location.search.includes('webgl2') ? 'webgl2' : 'webgl');
        const px = new Uint8Array(4);
        // (x at the moved centre: 0.25 in the model, 0.25·f/3 in NDC)
        gl.readPixels(Math.round(64 + 64 * (0.25 / Math.tan(Math.PI / 8)) / 3), 64, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
        return px[2];
      });
      expect(await blue()).toBeLessThan(64); // culled: the inside of the far side
      await page.evaluate(() => { window.__grade.noCull = true; window.draw(); });
      expect(await blue()).toBeGreaterThan(192); // culling off: the near side
      await page.evaluate(() => { window.__grade.noCull = false; window.draw(); });
      expect(await blue()).toBeLessThan(64); // as the page set it again
    });
  });
}
