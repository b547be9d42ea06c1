// What draw-batch.spec.js (Chromium) and draw-batch-firefox.spec.js (Firefox) hold of
// grader/browser/draw-batch.js: each scene of tests/fixtures/draw-batch.html drawn in a plain page
// (the reference) and in a page with the grader's scripts shows and reads the same (the canvas
// exactly, also when read right after the last draw; the errors the page's getError gives; the draws
// the grader counts), and a run of separate triangles reaches WebGL as one draw. A spy under both
// pages counts the draw calls that reach WebGL.
import { expect } from '@playwright/test';
import { drawBatchScript } from '../../grader/browser/draw-batch.js';
import { instrumentScript } from '../../grader/browser/instrument.js';

const N = 300; // the page's triangles a mesh
// scene → [the page's draw calls, the calls that reach WebGL batched] (null: as many as the page's;
// undefined: not counted, where WebGL may refuse the run as one and it is drawn again one by one)
const SCENES = {
  depth: [N, 1],
  blend: [N, 1],
  pairs: [(2 * N) / 3, 1], // (one triangle, then two, ...)
  pastTheEnd: [N + 20, undefined],
  pairsPastTheEnd: [214, undefined], // (one triangle, then two, ... past the end: drawn again draw by draw, each its own size)
  uniformBetween: [N, null],
  meshBetween: [2 * N, 2],
  resizeBetween: [2 * N, 2],
  strips: [N / 2, null],
  errorBefore: [N, 1],
  backwards: [N, null],
};

/** The init scripts, in order, of a plain page (the spy alone) and of a batched one. */
export const initScripts = (batched) => (batched ? [spyScript, drawBatchScript, instrumentScript] : [spyScript]);

function spyScript() {
  window.__real = 0;
  for (const c of [window.WebGLRenderingContext, window.WebGL2RenderingContext]) {
    const { drawArrays } = c.prototype;
    c.prototype.drawArrays = function (...a) { window.__real++; return drawArrays.apply(this, a); };
  }
}

/** `plain` and `batched`: pages ({ evaluate(fn, arg) }) with initScripts(false) and (true), on the fixture page. */
export async function compareScenes(plain, batched) {
  for (const [scene, [calls, real]] of Object.entries(SCENES)) {
    const want = await plain.evaluate((s) => window.check(s), scene), got = await batched.evaluate((s) => window.check(s), scene);
    expect(want.real, `${scene}: the page's draw calls`).toBe(calls);
    expect(got.errors, `${scene}: the errors the page's getError gives`).toEqual(want.errors);
    expect(got.png, `${scene}: the canvas`).toBe(want.png);
    expect(got.right, `${scene}: the canvas read right after the last draw`).toBe(want.right);
    expect(got.counted, `${scene}: the draws the grader counts`).toBe(calls);
    if (real !== undefined) expect(got.real, `${scene}: the draw calls that reach WebGL`).toBe(real ?? calls);
  }
  // what the page drew reaches WebGL by the end of its task, with nothing read
  const held = await batched.evaluate(() => window.drawOnly());
  expect(await batched.evaluate(() => window.__real), 'the held draw, sent at the end of the task').toBe(held + 1);
}

/** The errors the page's getError gives after drawing past the end of its buffer (a browser that checks: INVALID_OPERATION). */
export const pastTheEndErrors = (page) => page.evaluate(() => window.check('pastTheEnd').errors);
