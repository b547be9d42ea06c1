// Every step in Firefox (Debian's firefox-esr, WebGL on Mesa's llvmpipe), in WebGL 2 and WebGL 1,
// where many students open them: the page contract (the URL's state in window.scene and kept by
// the controls, no console or page error, no GL error), the picture against the exact sphere with
// the bounds Chromium is held to (bounds.js: the default view, and for the lit steps an orbit angle
// with a point light), Subdivide and Coarsen, fuzzed URLs; and ?api=webgpu, which Firefox here
// cannot run: the message and its link to the same view in WebGL. Project "firefox" only.
// A difference between the engines that students meet: GLSL's pow(x, y) is undefined for x < 0;
// SwiftShader returns |x|^y, Mesa NaN (and pow(0, 0) is 1 in one, 0 in the other). A shader that
// forgets max(w_r · w_o, 0) passes Chromium's default view (0.39/255 from the exact render) and
// draws mostly black here (110/255), which this suite's default view catches.
import { test, expect } from './firefox-fixtures.js';
import { open, scene, andDraw, canvasPixels, errorAgainstReference } from './fixtures.js';
import { checkNormalColours, expectWithinLitBound, report } from './bounds.js';

const POINT = { light: 'point', lx: 1, ly: 1.5, lz: 2, Le: 4 };
const LIT_VIEWS = {
  'the default view': { orbit: 0, angle: 0 },
  'orbit angle 1.1 rad, a point light': { orbit: 0, angle: 1.1, ...POINT },
};

for (const api of ['webgl2', 'webgl']) {
  test.describe(`Firefox ${api}`, () => {
    test.use({ api });

    test('WP04P1 and WP04P2: each pixel shows c = 0.5 p + 0.5 of a sphere point under it', async ({ page }) => {
      let s = await open(page, '/WP04P1/', { level: 5 });
      expect([s.exercise, s.level, s.vertices]).toEqual(['WP04P1', 5, 12 * 4 ** 5]);
      // no depth test yet: the last triangle drawn wins, which may be the far side
      checkNormalColours(await canvasPixels(page), s.camera, { allowFar: true });
      s = await open(page, '/WP04P2/', { level: 5 });
      expect([s.exercise, s.depthTest, s.cullFace, s.frontFace]).toEqual(['WP04P2', true, true, 'ccw']);
      checkNormalColours(await canvasPixels(page), s.camera);
      s = await open(page, '/WP04P2/', { level: 5, cw: 1 });
      expect(s.frontFace).toBe('cw');
      checkNormalColours(await canvasPixels(page), s.camera, { useFar: true });
    });

    for (const step of ['WP04P3', 'WP04P4', 'WP04P5']) {
      test(`${step}: the URL's view, within its bound of the exact render`, async ({ page }, testInfo) => {
        for (const [view, params] of Object.entries(LIT_VIEWS)) {
          const s = await open(page, `/${step}/`, params);
          expect([s.exercise, s.orbit, s.angle], 'window.scene holds the URL\'s state').toEqual([step, false, params.angle]);
          if (params.light) expect(s.light.position).toEqual([params.lx, params.ly, params.lz, 1]);
          const stats = await errorAgainstReference(page);
          report(testInfo, `${step} ${view}, level ${s.level}`, stats);
          expectWithinLitBound(stats, step, s.level, view);
        }
      });
    }

    test('Subdivide and Coarsen step the level; the URL follows and reloads to the same pixels', async ({ page }, testInfo) => {
      const p = page.puppeteer;
      await open(page, '/WP04P5/', { orbit: 0, angle: 0.4, level: 4 });
      let s = await andDraw(page, () => p.click('#subdivide'));
      expect([s.level, s.vertices]).toEqual([5, 12 * 4 ** 5]);
      await andDraw(page, () => p.click('#subdivide'));
      s = await andDraw(page, () => p.click('#coarsen'));
      expect(s.level).toBe(5);
      expect(await p.$eval('#info', (e) => e.textContent)).toContain('level 5 · 12,288 vertices');
      const stats = await errorAgainstReference(page);
      report(testInfo, 'WP04P5 after Subdivide, Subdivide, Coarsen (level 5)', stats);
      expectWithinLitBound(stats, 'WP04P5', s.level, 'level 5');
      const before = await canvasPixels(page);
      // the address is written at most every 100 ms
      await expect.poll(() => new URL(page.url()).searchParams.get('level')).toBe('5');
      expect(new URL(page.url()).searchParams.get('api')).toBe(api);
      await p.reload();
      await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
      expect(await scene(page)).toMatchObject({ level: 5, angle: 0.4, api });
      const after = await canvasPixels(page);
      expect(Buffer.compare(Buffer.from(before.data), Buffer.from(after.data)), 'the same pixels after the reload').toBe(0);
    });

    test('fuzzed URLs: clamped or ignored, said on the page, never HTML from the URL', async ({ page }) => {
      const cases = [
        [{ level: '999', kd: 'abc', s: '-3' }, { level: 8, kd: 0.8, s: 0 }, ['level=999', 'kd=abc', 's=-3']],
        [{ level: '-2', ks: '7', '<img src=x onerror=alert(1)>': '1' }, { level: 0, ks: 1 }, ['level=-2', 'ks=7', 'Unknown parameter']],
      ];
      for (const [params, want, notices] of cases) {
        const s = await open(page, '/WP04P4/', { orbit: 0, ...params });
        expect({ level: s.level, ...s.material }).toMatchObject(want);
        expect(s.vertices).toBe(12 * 4 ** s.level);
        const said = await page.locator('#messages .notice').allInnerTexts();
        for (const n of notices) expect(said.some((t) => t.includes(n)), `a notice for ${n}`).toBe(true);
        expect(await page.locator('#messages img').count(), 'nothing from the URL became HTML').toBe(0);
        const img = await canvasPixels(page);
        const centre = 4 * (64 * 128 + 64);
        expect([...img.data.slice(centre, centre + 3)], 'a sphere is drawn').not.toEqual([100, 149, 237]);
      }
    });
  });
}

test('?api=webgpu: Firefox here has no WebGPU; the page says so and links to the same view in WebGL', async ({ page }) => {
  await page.goto('/WP04P3/?api=webgpu&size=64&kd=0.5&orbit=0');
  const p = page.puppeteer;
  await p.waitForSelector('#messages .error a');
  expect(await page.locator('#messages .error').innerText()).toMatch(/WebGPU/);
  await Promise.all([p.waitForNavigation(), page.locator('#messages .error a').click()]);
  await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
  const s = await scene(page);
  expect([s.api, s.material.kd, s.orbit]).toEqual(['webgl2', 0.5, false]);
});
