// The pages under stress: every URL parameter set to garbage (a sphere and a notice, never HTML
// from the URL), a lost and restored WebGL context (WebGPU: device), a long orbit, and thousands of
// level changes and slider moves (no new buffer, no heap growth, no GL error). All three APIs.
import { test, expect, open, scene, canvasPixels, errorAgainstReference, waitForFrame, anotherPage } from './fixtures.js';
import { SHADING_RMSE } from '../../common/sphere.js';

const PARAMS = {
  '/WP04P2/': ['level', 'size', 'depth', 'cull', 'cw'],
  '/WP04P5/': ['level', 'size', 'height', 'orbit', 'angle', 'light', 'lx', 'ly', 'lz', 'kd', 'Le', 'ks', 's', 'La', 'model', 'near', 'far'],
};
const BAD = ['', 'NaN', 'Infinity', '-1e309', '-5', 'abc', '<img src=x onerror=alert(1)>', '9'.repeat(400)];

for (const [path, names] of Object.entries(PARAMS)) {
  for (const value of BAD) {
    test(`${path} with every parameter = ${JSON.stringify(value.slice(0, 30))}: a sphere and a notice, no HTML`, { tag: '@any-api' }, async ({ page }) => {
      const query = names.map((n) => `${n}=${encodeURIComponent(value)}`).join('&');
      await page.goto(`${path}?api=${page.api}&${query}&${encodeURIComponent('<b>x</b>')}=1`);
      await page.waitForFunction(() => window.scene && window.scene.frame >= 1, null, { timeout: 30_000 });
      const s = await scene(page);
      expect(s.vertices).toBe(12 * 4 ** s.level);
      const notices = await page.locator('#messages .notice').allInnerTexts();
      // every value here is bad for every parameter, but '-5' is a fine light position and angle
      const fine = value === '-5' ? ['lx', 'ly', 'lz', 'angle'] : [];
      for (const n of names.filter((x) => !fine.includes(x))) {
        expect(notices.some((t) => t.startsWith(`${n}=`)), `a notice for ${n}`).toBe(true);
      }
      expect(notices.some((t) => t.includes('Unknown parameter "<b>x</b>"'))).toBe(true);
      expect(await page.locator('#messages img, #messages b').count(), 'nothing from the URL became HTML').toBe(0);
      expect(page.dialogs, 'no dialog opened').toEqual([]);
      expect(await page.locator('#messages .error').count()).toBe(0);
      // the values in force are valid ones
      expect(s.level).toBeGreaterThanOrEqual(0);
      expect(s.level).toBeLessThanOrEqual(8);
      if (s.material) {
        for (const v of [s.material.kd, s.material.ks, s.material.s, s.light.Le, s.light.La, ...s.light.position]) expect(Number.isFinite(v)).toBe(true);
      }
    });
  }
}

test('a lost context (WebGPU: a lost device) is reported, and on restore the page draws the same pixels', async ({ page }) => {
  const webgpu = page.api === 'webgpu';
  const said = webgpu ? 'lost its WebGPU device' : 'lost its WebGL context';
  await open(page, '/WP04P5/', { orbit: 0, angle: 0.4, model: 'blinn-phong', s: 80 });
  // the picture is the right one (the exact render), before and so after the restore
  expect((await errorAgainstReference(page)).rmse * 255, 'interior RMSE against the exact render, 8-bit steps').toBeLessThanOrEqual(1);
  const before = await canvasPixels(page);
  const counts = await page.evaluate(() => ({ ...window.__gl.counts }));
  const lostAt = (await scene(page)).frame;
  if (webgpu) {
    page.expectProblems(/WebGPU capture: readback/); // a copy in flight when the device goes
    await page.evaluate(() => window.__gl.devices.at(-1).destroy()); // the page asks for a new one by itself
  } else {
    await page.evaluate(() => { window.lose = window.__gl.contexts[0].getExtension('WEBGL_lose_context'); window.lose.loseContext(); });
    await expect(page.locator('#messages .notice')).toContainText(said);
  }
  // the controls still work while the context is gone; nothing throws
  await page.getByLabel('ks', { exact: true }).fill('0.7');
  await page.getByLabel('ks', { exact: true }).fill('0.5');
  if (!webgpu) await page.evaluate(() => window.lose.restoreContext());
  await page.waitForFunction((f) => window.scene.frame > f, lostAt);
  await expect(page.locator('#messages .notice', { hasText: said })).toHaveCount(0);
  // let the last change draw (two animation frames), then read the picture
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await waitForFrame(page, lostAt + 1);
  const after = await canvasPixels(page);
  expect(Buffer.compare(Buffer.from(before.data), Buffer.from(after.data)), 'the same pixels after the restore').toBe(0);
  const now = await page.evaluate(() => ({ ...window.__gl.counts }));
  expect(now.createProgram - counts.createProgram, 'one new program (pipeline) for the new context').toBe(1);
  expect(now.createBuffer - counts.createBuffer, 'one new vertex buffer for the new context').toBe(1);
});

/**
 * The JS heap in use after garbage collection: the least of three readings 300 ms apart, the page's
 * clock standing still between them, so that what a frame's work still holds (under WebGPU, the
 * capture's copy in flight) is let go. (One reading varied by up to 200 kB between runs under
 * WebGPU, the orbit's five hours once reading as 207 kB of growth.)
 */
async function heapAfterGC(page) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  let least = Infinity;
  for (let k = 0; k < 3; k++) {
    if (k) await new Promise((resolve) => setTimeout(resolve, 300));
    await cdp.send('HeapProfiler.collectGarbage');
    await cdp.send('HeapProfiler.collectGarbage'); // a second pass takes what the first only unlinked
    const { metrics } = await cdp.send('Performance.getMetrics');
    least = Math.min(least, metrics.find((m) => m.name === 'JSHeapUsedSize').value);
  }
  await cdp.detach();
  return least;
}

test('a long orbit: α stays in [0, 2π), the same angle gives the same picture, heap and buffers stay flat', async ({ page }) => {
  await page.clock.install({ time: 0 });
  await page.goto(`/WP04P4/?api=${page.api}&size=64&orbit=1&angle=0`);
  await expect.poll(async () => {
    await page.clock.runFor(20);
    return page.evaluate(() => window.scene && window.scene.frame);
  }).toBeGreaterThan(0);
  // warm up with what is measured (an hour's jump, then a second of frames), so that code the
  // JIT compiles late on a loaded machine is not counted as growth
  await page.clock.runFor(2000);
  await page.clock.fastForward('01:00:00');
  await page.clock.runFor(1000);
  const heap0 = await heapAfterGC(page);
  for (let hour = 0; hour < 5; hour++) {
    await page.clock.fastForward('01:00:00'); // an hour passes between two frames
    await page.clock.runFor(1000); // then a second of frames
    const s = await scene(page);
    expect(s.angle).toBeGreaterThanOrEqual(0);
    expect(s.angle).toBeLessThan(2 * Math.PI);
  }
  const heap1 = await heapAfterGC(page);
  expect(heap1 - heap0, 'JS heap growth over five hours of orbit (bytes)').toBeLessThan(200_000);
  const counts = await page.evaluate(() => ({ ...window.__gl.counts }));
  expect(counts.createBuffer).toBe(1);
  // stop at some angle; a fresh page at that angle draws the same picture
  await page.getByRole('checkbox', { name: 'Orbit' }).uncheck();
  await page.clock.runFor(100);
  const s = await scene(page);
  const stopped = await canvasPixels(page);
  const fresh = await anotherPage(page);
  await fresh.goto(`/WP04P4/?api=${page.api}&size=64&orbit=0&angle=${s.angle}`);
  await fresh.waitForFunction(() => window.scene && window.scene.frame >= 1);
  const again = await canvasPixels(fresh);
  expect(Buffer.compare(Buffer.from(stopped.data), Buffer.from(again.data))).toBe(0);
  // and it is the right picture: the exact render at that angle, within Gouraud's measured error
  const stats = await errorAgainstReference(page);
  expect(stats.rmse * 255, `interior RMSE at α = ${s.angle.toFixed(3)}, level ${s.level}`).toBeLessThanOrEqual(SHADING_RMSE.gouraud[s.level] + 0.5);
});

test('1,000 level changes and 1,000 slider moves: no new buffer, no heap growth, no GL error', async ({ page }) => {
  await open(page, '/WP04P5/', { orbit: 0, level: 0, size: 64 });
  const run = (n) => page.evaluate((count) => {
    const up = document.getElementById('subdivide'), down = document.getElementById('coarsen');
    const ks = document.getElementById('ks');
    // window.scene changes only when a frame is drawn, so the loop keeps count of the level itself
    let level = window.scene.level;
    let goingUp = level < 4;
    for (let k = 0; k < count; k++) {
      if (goingUp && level >= 4) goingUp = false;
      if (!goingUp && level <= 0) goingUp = true;
      (goingUp ? up : down).click();
      level += goingUp ? 1 : -1;
      ks.value = String((k % 100) / 100);
      ks.dispatchEvent(new Event('input'));
    }
    return level;
  }, n);
  const nextFrames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await run(100); // warm up
  await nextFrames();
  const heap0 = await heapAfterGC(page);
  const level = await run(1000);
  await nextFrames();
  expect((await scene(page)).level, 'the level the 1,000 clicks led to').toBe(level);
  const heap1 = await heapAfterGC(page);
  expect(heap1 - heap0, 'JS heap growth (bytes)').toBeLessThan(200_000);
  const counts = await page.evaluate(() => ({ ...window.__gl.counts }));
  expect(counts.createBuffer).toBe(1);
  expect(counts.createProgram).toBe(1);
  expect(await page.evaluate(() => window.__gl.errors())).toEqual([]);
});
