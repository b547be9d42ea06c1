// grader/browser/instrument.js's present, in Chromium, WebGL 1 and 2: a page that did not ask to
// keep its drawing buffer (it is kept for the grader) gets its depth buffer cleared after each task
// that drew, as the browser clears it when it shows the frame, with everything the page had set
// left as it was; and the present asks WebGL for nothing it keeps itself (each such question waits
// for the GPU to finish the frame: tests/fixtures/present.html).
import { test, expect } from '@playwright/test';
import { instrumentScript } from '../../grader/browser/instrument.js';
import { drawBatchScript } from '../../grader/browser/draw-batch.js';

test('after each task that drew, the depth buffer is cleared and the page\'s state left as it was, asking WebGL only what the browser keeps', async ({ browser, baseURL }, testInfo) => {
  test.skip(testInfo.project.name !== 'webgl2', 'its own page in WebGL 1 and 2; once is enough');
  const context = await browser.newContext();
  try {
    for (const script of [drawBatchScript, instrumentScript]) await context.addInitScript(script);
    for (const api of ['webgl', 'webgl2']) {
      const page = await context.newPage();
      const problems = [];
      page.on('pageerror', (e) => problems.push(e.message));
      await page.goto(`${baseURL}/tests/fixtures/present.html?api=${api}`);
      const { left, pixel, asked } = await page.evaluate(async () => {
        // the questions the grader asks from now on (the page's own go through `ask`)
        const proto = Object.getPrototypeOf(window.gl), { getParameter } = proto, names = new Set();
        proto.getParameter = function (pname) {
          names.add(Object.keys(WebGL2RenderingContext).find((k) => WebGL2RenderingContext[k] === pname) || String(pname));
          return getParameter.call(this, pname);
        };
        return { ...(await window.drawFrames()), asked: [...names] };
      });
      expect(problems, api).toEqual([]);
      // the green square behind the red one shows: the depth buffer was cleared between the frames
      expect(pixel, api).toEqual([0, 255, 0, 255]);
      expect(left, api).toEqual({ clearDepth: 0.25, clearStencil: 3, depthMask: false, stencilFront: 0x0f, stencilBack: 0xf0,
        scissor: true, framebuffer: 'the page\'s' });
      expect(asked, api).toEqual(['FRAMEBUFFER_BINDING']);
      await page.close();
    }
  } finally {
    await context.close();
  }
});
