// grader/browser/draw-batch.js in Chromium, WebGL 1 and 2: what a page shows and reads is what it
// would be without it, and runs of separate triangles are one draw (tests/browser/draw-batch-check.js).
import { test, expect } from '@playwright/test';
import { compareScenes, initScripts } from './draw-batch-check.js';

test('each scene shows and reads the same as without batching, in WebGL 1 and 2; runs of separate triangles are one draw', async ({ browser, baseURL }, testInfo) => {
  test.skip(testInfo.project.name !== 'webgl2', 'its own pages in WebGL 1 and 2; once is enough');
  const problems = [];
  const open = async (batched) => {
    const context = await browser.newContext();
    for (const script of initScripts(batched)) await context.addInitScript(script);
    return context;
  };
  const contexts = [await open(false), await open(true)];
  try {
    for (const api of ['webgl', 'webgl2']) {
      const [plain, batched] = await Promise.all(contexts.map(async (context) => {
        const page = await context.newPage();
        page.on('pageerror', (e) => problems.push(e.message));
        await page.goto(`${baseURL}/tests/fixtures/draw-batch.html?api=${api}`);
        return page;
      }));
      await test.step(api, () => compareScenes(plain, batched));
    }
    expect(problems).toEqual([]);
  } finally {
    for (const c of contexts) await c.close();
  }
});
