// The front page and the two unlit steps, against screenshots and the exact sphere: WP04P1 (the
// subdivided sphere coloured 0.5 p + 0.5, Subdivide / Coarsen, one recycled buffer) and WP04P2
// (depth test, culling, clockwise front faces). Then what a page does with bad input and failures:
// out-of-range URL values, broken or missing shaders, no WebGL (2), file://, and the address
// following the controls. Run under WebGL 2 and WebGPU; the screenshots under WebGL 2 only
// (@any-api): webgpu.spec.js holds WebGPU's equal to WebGL 2's in the same views. WebGL 1 draws
// with the same GLSL and JavaScript (only getContext differs): Chromium's is held to the exact
// sphere by the fallback test here, Firefox's on every step by firefox.spec.js.
import { test, expect, open, scene, andDraw, canvasPixels, expectCanvasScreenshot, messages } from './fixtures.js';
import { checkNormalColours } from './bounds.js';
import { P1_VIEWS, P2_VIEWS } from './screenshot-views.js';

test('the front page lists the steps in order and every link works', { tag: '@any-api' }, async ({ page }) => {
  await page.goto('/');
  const links = page.locator('ol.steps a');
  const hrefs = await links.evaluateAll((as) => as.map((a) => a.getAttribute('href')));
  expect(hrefs.length).toBeGreaterThanOrEqual(2);
  expect(hrefs).toEqual([...hrefs].sort());
  for (const href of hrefs) {
    const response = await page.request.get(new URL(href, page.url()).href);
    expect(response.status(), href).toBe(200);
  }
  await links.first().click();
  await expect(page).toHaveURL(/WP04P1/);
});

test.describe('WP04P1', () => {
  for (const { name, params: { level } } of P1_VIEWS) {
    test(`screenshot at level ${level}`, { tag: '@any-api' }, async ({ page }) => {
      const s = await open(page, '/WP04P1/', { level });
      expect(s.level).toBe(level);
      expect(s.vertices).toBe(12 * 4 ** level);
      await expectCanvasScreenshot(page, `${name}.png`);
    });
  }

  test('each pixel shows c = 0.5 p + 0.5 of a sphere point under it', async ({ page }) => {
    const s = await open(page, '/WP04P1/', { level: 5 });
    expect(s.shading).toBe('normals');
    // no depth test yet: the last triangle drawn wins, which may be the far side
    checkNormalColours(await canvasPixels(page), s.camera, { allowFar: true });
  });

  test('Subdivide and Coarsen step the level, stop at the ends, and show the count', { tag: '@any-api' }, async ({ page }) => {
    await open(page, '/WP04P1/', { level: 1 });
    const subdivide = page.getByRole('button', { name: 'Subdivide' });
    const coarsen = page.getByRole('button', { name: 'Coarsen' });
    let s = await andDraw(page, () => subdivide.click());
    expect(s.level).toBe(2);
    await expect(page.locator('#info')).toHaveText('level 2 · 192 vertices');
    await andDraw(page, () => coarsen.click());
    s = await andDraw(page, () => coarsen.click());
    expect(s.level).toBe(0);
    await expect(coarsen).toBeDisabled();
    await expect(subdivide).toBeEnabled();
    await expect(page).toHaveURL(/level=0/);
  });

  test('1,000 level changes recycle the one buffer and the one program', async ({ page }) => {
    await open(page, '/WP04P1/', { level: 0 });
    const before = await page.evaluate(() => ({ ...window.__gl.counts }));
    expect(before.createBuffer).toBe(1);
    expect(before.createProgram).toBe(1);
    // Up to level 6 and back, again and again: 1,000 clicks in all
    const result = await page.evaluate(() => {
      const up = document.getElementById('subdivide');
      const down = document.getElementById('coarsen');
      let goingUp = true;
      for (let k = 0; k < 1000; k++) {
        if (goingUp && window.scene.level >= 6) goingUp = false;
        if (!goingUp && window.scene.level <= 0) goingUp = true;
        (goingUp ? up : down).click();
      }
      return { level: window.scene.level, frame: window.scene.frame };
    });
    expect(result.frame).toBe(1001);
    const after = await page.evaluate(() => ({ ...window.__gl.counts }));
    expect(after.createBuffer, 'buffers created').toBe(1);
    expect(after.createProgram, 'programs created').toBe(1);
    expect(after.createShader, 'shaders created').toBe(page.api === 'webgpu' ? 1 : 2); // one WGSL module, or GLSL's two
    expect(after.bufferData - before.bufferData, 'bufferData per level change').toBe(1000);
    expect(after.getUniformLocation, 'uniform look-ups happen once').toBe(before.getUniformLocation);
    expect(await page.evaluate(() => window.__gl.errors())).toEqual([]);
  });
});

test.describe('WP04P2', () => {
  for (const { name, label, params } of P2_VIEWS) {
    test(`screenshot: ${label}`, { tag: '@any-api' }, async ({ page }) => {
      await open(page, '/WP04P2/', params);
      await expectCanvasScreenshot(page, `${name}.png`);
    });
  }

  test('defaults are as the slides end up: depth test and culling on, counter-clockwise', async ({ page }) => {
    const s = await open(page, '/WP04P2/');
    expect([s.depthTest, s.cullFace, s.frontFace]).toEqual([true, true, 'ccw']);
    await expect(page.getByRole('checkbox', { name: 'Depth test' })).toBeChecked();
    await expect(page.getByRole('checkbox', { name: 'Cull faces' })).toBeChecked();
    await expect(page.getByRole('checkbox', { name: 'Clockwise front faces' })).not.toBeChecked();
  });

  test('with the depth test each pixel shows the near sphere point; culling changes nothing', async ({ page }) => {
    let s = await open(page, '/WP04P2/', { level: 5 });
    const culled = await canvasPixels(page);
    checkNormalColours(culled, s.camera);
    s = await andDraw(page, () => page.getByRole('checkbox', { name: 'Cull faces' }).uncheck());
    expect(s.cullFace).toBe(false);
    const unculled = await canvasPixels(page);
    expect(Buffer.compare(Buffer.from(culled.data), Buffer.from(unculled.data)), 'culling has no visible effect').toBe(0);
  });

  test('clockwise front faces show the inside of the far side', async ({ page }) => {
    await open(page, '/WP04P2/', { level: 5 });
    const s = await andDraw(page, () => page.getByRole('checkbox', { name: 'Clockwise front faces' }).check());
    expect(s.frontFace).toBe('cw');
    checkNormalColours(await canvasPixels(page), s.camera, { useFar: true });
    await expect(page).toHaveURL(/cw=1/);
  });
});

test.describe('bad input and failures', () => {
  const cases = [
    ['level=999', { level: '999' }, 8, /level=999 is above the largest value 8/],
    ['level=-2', { level: '-2' }, 0, /level=-2 is below the least value 0/],
    ['level=abc', { level: 'abc' }, 5, /level=abc is not a number/],
    ['api=foo', { api: 'foo' }, 5, /api=foo is not one of webgl2, webgl/],
  ];
  for (const [name, params, level, notice] of cases) {
    test(`${name} draws a valid sphere and says what was fixed`, { tag: '@any-api' }, async ({ page }) => {
      const s = await open(page, '/WP04P1/', params);
      expect(s.level).toBe(level);
      expect(s.vertices).toBe(12 * 4 ** level);
      await expect(page.locator('#messages .notice')).toContainText(notice);
      const img = await canvasPixels(page);
      const centre = 4 * (64 * 128 + 64);
      expect([...img.data.slice(centre, centre + 3)]).not.toEqual([100, 149, 237]);
    });
  }

  test('a broken shader is reported with its file and line, on the page', async ({ page }) => {
    const [file, body] = page.api === 'webgpu'
      ? ['shader.wgsl', '@vertex\nfn main_vs() -> @builtin(position) vec4f {\n  return vec4f(0.0);\n  let x: f32 = vColour;\n}\n']
      : ['shader.frag', 'precision mediump float;\nvarying vec4 vColor;\nvoid main() {\n  gl_FragColor = vColour;\n}\n'];
    await page.route(`**/WP04P1/${file}`, (route) => route.fulfill({ contentType: 'text/plain', body }));
    if (page.api === 'webgpu') page.expectProblems(/vColour/); // Chromium also logs WGSL errors itself
    await page.goto(`/WP04P1/?api=${page.api}&size=64`);
    const error = page.locator('#messages .error');
    await expect(error).toContainText(`${file}, line 4`);
    await expect(error.locator('pre')).toContainText('>> 4');
  });

  test('a missing shader file is reported on the page', async ({ page }) => {
    const file = page.api === 'webgpu' ? 'shader.wgsl' : 'shader.vert';
    await page.route(`**/WP04P2/${file}`, (route) => route.fulfill({ status: 404, body: 'not found' }));
    page.expectProblems(/404/); // the browser itself logs the failed request
    await page.goto(`/WP04P2/?api=${page.api}&size=64`);
    await expect(page.locator('#messages .error')).toContainText(`Could not load the shader ${file}: the server answered 404`);
  });

  test('no WebGL at all: a clear message instead of a blank canvas', async ({ page }) => {
    test.skip(page.api === 'webgpu', 'a WebGPU page asks for no WebGL context');
    await page.addInitScript(() => { HTMLCanvasElement.prototype.getContext = () => null; });
    await page.goto(`/WP04P1/?api=${page.api}&size=64`);
    await expect(page.locator('#messages .error')).toContainText('cannot create a WebGL context');
  });

  for (const [what, init] of [['no navigator.gpu', () => { Object.defineProperty(Navigator.prototype, 'gpu', { get: () => undefined }); }],
    ['no adapter', () => { GPU.prototype.requestAdapter = async () => null; }]]) {
    test(`no WebGPU (${what}): a clear message with a link to the same view in WebGL`, async ({ page }) => {
      test.skip(page.api !== 'webgpu', 'the WebGPU pages only');
      await page.addInitScript(init);
      await page.goto('/WP04P3/?api=webgpu&size=64&kd=0.5');
      await expect(page.locator('#messages .error')).toContainText(/WebGPU/);
      const link = page.locator('#messages .error a');
      await link.click();
      await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
      const s = await scene(page);
      expect([s.api, s.material.kd]).toEqual(['webgl2', 0.5]);
    });
  }

  test('no WebGL 2: falls back to WebGL 1, says so, and draws the same sphere', async ({ page }) => {
    test.skip(page.api === 'webgpu', 'a WebGL test (it asks for api=webgl2 itself)');
    await page.addInitScript(() => {
      const original = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
        return type === 'webgl2' ? null : original.call(this, type, ...rest);
      };
    });
    await page.goto('/WP04P2/?api=webgl2&size=128&level=5');
    await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
    const s = await scene(page);
    expect(s.api).toBe('webgl');
    expect(await page.evaluate(() => window.__gl.contexts.map((gl) => gl.constructor.name)), 'a WebGL 1 context').toEqual(['WebGLRenderingContext']);
    await expect(page.locator('#messages .notice')).toContainText('WebGL 2 is not available');
    // Chromium's WebGL 1 draws the depth-tested sphere exactly (Firefox's: firefox.spec.js, every step)
    checkNormalColours(await canvasPixels(page), s.camera);
  });

  test('opened from file:// the page says how to serve it', { tag: '@any-api' }, async ({ page }) => {
    page.expectProblems(/CORS|file:|Failed to load|ERR_/i);
    await page.goto(new URL('../../WP04P1/index.html', import.meta.url).href);
    await expect(page.locator('#messages .error')).toContainText('npm start');
    expect(await messages(page)).toContain('file://');
  });

  test('the address follows the controls and reloads to the same view', { tag: '@any-api' }, async ({ page }) => {
    await open(page, '/WP04P2/', { level: 2 });
    await andDraw(page, () => page.getByRole('button', { name: 'Subdivide' }).click());
    await andDraw(page, () => page.getByRole('checkbox', { name: 'Depth test' }).uncheck());
    const before = await canvasPixels(page);
    // the address is written at most every 100 ms: wait for it
    await expect.poll(() => new URL(page.url()).searchParams.get('depth')).toBe('0');
    expect(new URL(page.url()).searchParams.get('level')).toBe('3');
    const url = page.url();
    await page.goto(url);
    await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
    const s = await scene(page);
    expect([s.level, s.depthTest]).toEqual([3, false]);
    const after = await canvasPixels(page);
    expect(Buffer.compare(Buffer.from(before.data), Buffer.from(after.data))).toBe(0);
  });
});
