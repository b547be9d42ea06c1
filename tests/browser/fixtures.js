// Shared browser-test fixtures. Every test:
// - runs with the project's API (webgl2 / webgpu; WebGL 1 in Firefox's suite): open() adds ?api= to the page's URL;
// - counts WebGL calls (createBuffer, bufferData, createProgram, ...) through wrappers installed
//   on the context prototypes before any page script runs; under WebGPU the same names count the
//   calls that do the same job (a vertex buffer made or written, a render pipeline, a WGSL module);
// - under WebGPU sees the canvas through grader/browser/webgpu-capture.js (headless Chromium cannot present
//   a WebGPU canvas: the capture stands in for its context and copies each frame to a 2D canvas);
// - fails on any page error, console error or gl.getError() other than NO_ERROR, unless the test
//   says which errors it expects (page.expectProblems(/regex/)).
import { test as base, expect } from '@playwright/test';
import { PNG } from 'pngjs';
import { PIN_CANVAS_PATH, canvasScreenshot } from '../../tools/browser.js';
import { renderReference } from '../../common/exact-render.js';
import { compareToReference } from '../../tools/reference/measure.js';
import { readWebGPUFrame, webgpuCaptureScript } from '../../grader/browser/webgpu-capture.js';

/** The init script that counts WebGL (WebGPU) calls and keeps the contexts: window.__gl. */
export function instrument() {
  const counts = {};
  const contexts = [];
  const wrap = (proto, names) => {
    if (!proto) return;
    for (const name of names) {
      const original = proto[name];
      proto[name] = function (...args) {
        counts[name] = (counts[name] || 0) + 1;
        return original.apply(this, args);
      };
    }
  };
  const names = ['createBuffer', 'deleteBuffer', 'bufferData', 'bufferSubData', 'createProgram', 'createShader',
    'createTexture', 'drawArrays', 'drawElements', 'getUniformLocation', 'getAttribLocation', 'useProgram'];
  wrap(window.WebGLRenderingContext && WebGLRenderingContext.prototype, names);
  wrap(window.WebGL2RenderingContext && WebGL2RenderingContext.prototype, names);
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
    const ctx = getContext.call(this, type, ...rest);
    if (ctx && /webgl/.test(type) && !contexts.includes(ctx)) contexts.push(ctx);
    return ctx;
  };
  window.__gl = {
    counts,
    contexts,
    errors: () => contexts.map((gl) => gl.getError()).filter((e) => e !== 0),
  };
  // WebGPU: the calls that do the WebGL calls' jobs, under their names (the capture's own are not
  // counted); the devices, so that a test can destroy one
  if (!window.GPUDevice) return;
  const capture = (descriptor) => descriptor && /webgpu-capture/.test(descriptor.label || '');
  const vertexBuffers = new WeakSet();
  const count = (name) => { counts[name] = (counts[name] || 0) + 1; };
  const devices = [];
  const { createBuffer, createRenderPipeline, createShaderModule } = GPUDevice.prototype;
  GPUDevice.prototype.createBuffer = function (descriptor) {
    const buffer = createBuffer.call(this, descriptor);
    if (!capture(descriptor)) count(descriptor.usage & GPUBufferUsage.VERTEX ? 'createBuffer' : 'createUniformBuffer');
    if (descriptor.usage & GPUBufferUsage.VERTEX) vertexBuffers.add(buffer);
    return buffer;
  };
  GPUDevice.prototype.createRenderPipeline = function (...args) { count('createProgram'); return createRenderPipeline.apply(this, args); };
  GPUDevice.prototype.createShaderModule = function (...args) { count('createShader'); return createShaderModule.apply(this, args); };
  const { writeBuffer } = GPUQueue.prototype;
  GPUQueue.prototype.writeBuffer = function (buffer, ...rest) {
    if (vertexBuffers.has(buffer)) count('bufferData');
    return writeBuffer.call(this, buffer, ...rest);
  };
  const { requestDevice } = GPUAdapter.prototype;
  GPUAdapter.prototype.requestDevice = async function (...args) {
    const device = await requestDevice.apply(this, args);
    devices.push(device);
    return device;
  };
  window.__gl.devices = devices;
}

// Opening a page in a new browser context starts a renderer process: about a core-second here, as
// much as the test itself. So a worker keeps one page and each test navigates it anew (open() and
// page.goto load a new document: new WebGL context, new window.__gl). A test that changes the page
// beyond where it stands (an init script, a route, the clock, a listener of its own)
// or that fails gets a fresh context after it, as does the first test of a worker.
const CHANGES_THE_PAGE = ['addInitScript', 'route', 'unroute', 'on', 'once', 'addListener', 'exposeFunction', 'exposeBinding',
  'setViewportSize', 'emulateMedia', 'setExtraHTTPHeaders'];

export const test = base.extend({
  api: ['webgl2', { option: true, scope: 'worker' }],
  kept: [async ({ browser, api }, use, workerInfo) => {
    const { baseURL, viewport, deviceScaleFactor } = workerInfo.project.use;
    const kept = {
      context: null, page: null, problems: [],
      async fresh() {
        if (kept.context) await kept.context.close().catch(() => {});
        kept.context = await browser.newContext({ baseURL, viewport, deviceScaleFactor });
        const page = kept.page = await kept.context.newPage();
        page.on('pageerror', (e) => kept.problems.push(`page error: ${e.message}`));
        page.on('console', (m) => {
          if (m.type() === 'error') kept.problems.push(`console error: ${m.text()}`);
        });
        // our pages never open a dialog: one is dismissed, kept in page.dialogs, and a problem
        page.on('dialog', (d) => {
          page.dialogs.push(d.message());
          kept.problems.push(`dialog: ${d.message()}`);
          d.dismiss().catch(() => {});
        });
        await page.addInitScript(instrument);
        if (api === 'webgpu') await page.addInitScript(webgpuCaptureScript);
        page.api = api;
        kept.changed = false;
        for (const name of CHANGES_THE_PAGE) {
          const own = page[name];
          page[name] = (...args) => { kept.changed = true; return own.apply(page, args); };
        }
        const clock = page.clock;
        Object.defineProperty(page, 'clock', { get: () => { kept.changed = true; return clock; } });
      },
    };
    await use(kept);
    if (kept.context) await kept.context.close().catch(() => {});
  }, { scope: 'worker' }],
  page: async ({ kept }, use, testInfo) => {
    if (!kept.page || kept.changed || kept.page.isClosed()) await kept.fresh();
    const { page } = kept;
    const problems = kept.problems = [];
    let expected = null;
    page.expectProblems = (pattern) => { expected = pattern; };
    page.problems = problems;
    page.dialogs = [];
    const others = [];
    const opened = (p) => others.push(p);
    kept.context.on('page', opened);
    await use(page);
    kept.context.off('page', opened);
    for (const p of others) await p.close().catch(() => {});
    if (!page.isClosed()) {
      const glErrors = await page.evaluate(() => (window.__gl ? window.__gl.errors() : []));
      for (const e of glErrors) problems.push(`gl.getError() = 0x${e.toString(16)}`);
      if (page.api === 'webgpu') {
        // what the capture met so far (not waiting for a copy in flight: an orbiting page never stops)
        const errors = await page.evaluate(() => (window.__webgpuCapture ? [...window.__webgpuCapture.errors] : []));
        for (const e of errors) problems.push(`WebGPU capture: ${e}`);
      }
    }
    if (testInfo.status !== testInfo.expectedStatus) kept.changed = true;
    // nothing left running (an orbit draws on) until the next test opens its page; a changed page
    // is closed then (its init scripts would run on about:blank too)
    if (!kept.changed && !page.isClosed()) await page.goto('about:blank').catch(() => { kept.changed = true; });
    const unexpected = expected ? problems.filter((p) => !expected.test(p)) : problems;
    expect(unexpected, 'page, console and GL errors').toEqual([]);
  },
});
export { expect };

/** A second page beside `page`, with the same API, instrumentation and (WebGPU) capture. */
export async function anotherPage(page, api = page.api) {
  const other = await page.context().newPage();
  other.api = api;
  await other.addInitScript(instrument);
  if (api === 'webgpu') await other.addInitScript(webgpuCaptureScript);
  return other;
}

/**
 * Opens an exercise with ?api= from the project and small-canvas defaults, waits for a frame, and
 * checks that the page really got the API it asked for: window.scene.api and the context's class.
 */
export async function open(page, path, params = {}) {
  const query = new URLSearchParams({ api: page.api, size: '128', ...params });
  await page.goto(`${path}?${query}`);
  await waitForFrame(page, 1);
  const s = await scene(page);
  const asked = ['webgl2', 'webgl', 'webgpu'].includes(query.get('api')) ? query.get('api') : 'webgl2';
  expect(s.api, 'window.scene.api').toBe(asked);
  const got = await page.evaluate(() => window.__gl && {
    classes: window.__gl.contexts.map((gl) => gl.constructor.name),
    devices: (window.__gl.devices || []).length,
  });
  if (!got) return s; // a page opened outside the fixture (not instrumented)
  if (asked === 'webgpu') expect([got.classes, got.devices > 0], 'a WebGPU device, no WebGL context').toEqual([[], true]);
  else expect(got.classes, 'the WebGL context class').toEqual([asked === 'webgl2' ? 'WebGL2RenderingContext' : 'WebGLRenderingContext']);
  return s;
}

/**
 * Waits until the page has drawn at least `n` frames (window.scene.frame); under WebGPU, also
 * until the capture has put the last one on the canvas.
 */
export async function waitForFrame(page, n) {
  await page.waitForFunction((k) => window.scene && window.scene.frame >= k, n);
  if (page.api === 'webgpu') await readWebGPUFrame(page);
}

/** The page's window.scene now. */
export function scene(page) {
  return page.evaluate(() => window.scene);
}

/** Does something and waits for the frame it causes. */
export async function andDraw(page, action) {
  const before = (await scene(page)).frame;
  await action();
  await waitForFrame(page, before + 1);
  return scene(page);
}

/** Asserts the canvas matches a baseline PNG (tests/screenshots/<project>/<name>). */
export async function expectCanvasScreenshot(page, name) {
  if (page.api === 'webgpu') await readWebGPUFrame(page);
  const size = await page.locator('canvas').evaluate((c) => ({ width: c.width, height: c.height }));
  await expect(page).toHaveScreenshot(name, { stylePath: PIN_CANVAS_PATH, clip: { x: 0, y: 0, ...size } });
}

/** A screenshot of the canvas, decoded: { width, height, data (RGBA, row 0 at the top) }. */
export async function canvasPixels(page) {
  if (page.api === 'webgpu') await readWebGPUFrame(page); // the last frame on the canvas
  const png = PNG.sync.read(await canvasScreenshot(page));
  return { width: png.width, height: png.height, data: png.data };
}

/** Renders the page's own window.scene exactly and compares the canvas with it (options: compareToReference's). */
export async function errorAgainstReference(page, options) {
  const s = await scene(page);
  const img = await canvasPixels(page);
  return compareToReference(img, renderReference(s, img.width, img.height), options);
}

/** The text of the page's message area. */
export function messages(page) {
  return page.locator('#messages').innerText();
}
