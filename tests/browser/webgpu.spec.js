// The WebGPU twins of the steps (project "webgpu" only): each step draws the same pixels as its
// WebGL 2 twin at several orbit angles and levels; the toggles of WP04P2 are pipelines made once;
// multisampling is a parameter. (The capture these pictures come through is held to a cleared
// canvas and a triangle, in both formats and with padded rows, in grader.spec.js.)
import { test, expect, open, scene, canvasPixels, andDraw, anotherPage } from './fixtures.js';
import { P1_VIEWS, P2_VIEWS } from './screenshot-views.js';

test.beforeEach(({ api }) => {
  test.skip(api !== 'webgpu', 'WebGPU only');
});

/** RMSE in 8-bit steps over RGB, and the pixels where one image shows the background and the other not. */
function difference(a, b) {
  const background = (d, o) => d[o] === 100 && d[o + 1] === 149 && d[o + 2] === 237;
  let sum = 0, silhouette = 0, sphere = 0;
  for (let o = 0; o < a.data.length; o += 4) {
    for (let k = 0; k < 3; k++) sum += (a.data[o + k] - b.data[o + k]) ** 2;
    if (background(a.data, o) !== background(b.data, o)) silhouette++;
    if (!background(b.data, o)) sphere++;
  }
  return { rmse: Math.sqrt(sum / (3 * a.data.length / 4)), silhouette, sphere };
}

async function webglTwin(page, path, params) {
  const twin = await anotherPage(page, 'webgl2');
  await open(twin, path, params);
  const pixels = await canvasPixels(twin);
  const s = await scene(twin);
  await twin.close();
  return { pixels, scene: s };
}

const STILL = { orbit: 0 };
const CASES = [
  // the unlit steps: the views of foundation.spec.js's screenshots (held there under WebGL 2 only)
  ['WP04P1', [...P1_VIEWS.map((v) => v.params), {}]],
  ['WP04P2', [{ level: 2 }, ...P2_VIEWS.map((v) => v.params), {}]],
  // the lit steps: each orbit angle once, each level (2, 4 and the chosen one) at more than one
  // angle, the point light once
  ...['WP04P3', 'WP04P4', 'WP04P5'].map((step) => [step, [{ angle: 0 }, { angle: 0, level: 2 }, { angle: 1.1, level: 4, light: 'point' },
    { angle: 2.5 }, { angle: 4, level: 2 }, { angle: 4, level: 4 }].map((p) => ({ ...STILL, ...p }))]),
];
for (const [step, views] of CASES) {
  test(`${step}: the same pixels as WebGL 2 (within 1/255 RMSE, the same silhouette) in ${views.length} views`, async ({ page }) => {
    test.setTimeout(120_000);
    const worst = { rmse: 0, silhouette: 0 };
    for (const params of views) {
      const s = await open(page, `/${step}/`, params);
      expect(s.api).toBe('webgpu');
      const gpu = await canvasPixels(page);
      const gl = await webglTwin(page, `/${step}/`, params);
      expect({ ...s, api: 'webgl2', frame: 0 }, 'the same window.scene').toEqual({ ...gl.scene, frame: 0 });
      const d = difference(gpu, gl.pixels);
      const view = JSON.stringify(params);
      expect(d.rmse, `RMSE in ${view}`).toBeLessThanOrEqual(1);
      expect(d.silhouette, `silhouette pixels that differ in ${view}`).toBeLessThanOrEqual(Math.ceil(0.002 * d.sphere));
      worst.rmse = Math.max(worst.rmse, d.rmse);
      worst.silhouette = Math.max(worst.silhouette, d.silhouette);
    }
    console.log(`[webgpu] ${step} vs WebGL 2 over ${views.length} views: worst RMSE ${worst.rmse.toFixed(3)}/255, worst silhouette ${worst.silhouette} px`);
  });
}

test('WP04P2: every toggle is a pipeline, made on first use and kept; 1,000 changes make no new buffer', async ({ page }) => {
  await open(page, '/WP04P2/', { level: 1 });
  const boxes = ['Depth test', 'Cull faces', 'Clockwise front faces'].map((name) => page.getByRole('checkbox', { name }));
  for (let k = 0; k < 8; k++) {
    for (let b = 0; b < 3; b++) {
      const on = ((k >> b) & 1) === 0;
      if ((await boxes[b].isChecked()) !== on) await andDraw(page, () => boxes[b].setChecked(on));
    }
  }
  const counts = await page.evaluate(() => ({ ...window.__gl.counts }));
  expect(counts.createProgram, 'one pipeline per combination of the three toggles').toBeLessThanOrEqual(8);
  // 1,000 more: toggles and level changes, no new pipeline, no new buffer
  await page.evaluate(() => {
    const ids = ['depthTest', 'cullFace', 'frontFaceCW', 'subdivide', 'coarsen'];
    for (let k = 0; k < 1000; k++) document.getElementById(ids[k % 5]).click();
  });
  const after = await page.evaluate(() => ({ ...window.__gl.counts }));
  expect(after.createProgram).toBe(counts.createProgram);
  expect([after.createBuffer, after.createUniformBuffer], 'one vertex and one uniform buffer in all').toEqual([1, 1]);
  expect(after.bufferData - counts.bufferData, 'a level change is one writeBuffer').toBe(400);
});

test('?msaa=4: the slides\' multisampled target, resolved to the canvas; the default draws as WebGL', async ({ page }) => {
  await open(page, '/WP04P4/', { ...STILL, level: 3 });
  const single = await canvasPixels(page);
  const s = await open(page, '/WP04P4/', { ...STILL, level: 3, msaa: 4 });
  expect(s.level).toBe(3);
  const multi = await canvasPixels(page);
  const d = difference(single, multi);
  expect(d.rmse, 'only the edges differ').toBeLessThan(6);
  expect(d.rmse, 'but they do: the edges are smoothed').toBeGreaterThan(0);
});
