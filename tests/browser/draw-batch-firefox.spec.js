// grader/browser/draw-batch.js in Firefox (the check page's browser), WebGL 1 and 2: as in Chromium
// (tests/browser/draw-batch-check.js), and Firefox refuses a draw past the end of a buffer, so a run
// that goes past it is refused as one and drawn again one by one: the triangles before it show.
import { expect } from '@playwright/test';
import { test } from './firefox-fixtures.js';
import { compareScenes, initScripts, pastTheEndErrors } from './draw-batch-check.js';

test('Firefox: each scene shows and reads the same as without batching, in WebGL 1 and 2; a run refused as one is drawn one by one', async ({ firefox, baseURL }) => {
  const pages = [], problems = [];
  const open = async (batched, api) => {
    const page = await firefox.newPage();
    pages.push(page);
    page.on('pageerror', (e) => problems.push(e.message));
    for (const script of initScripts(batched)) await page.evaluateOnNewDocument(script);
    await page.goto(new URL(`/tests/fixtures/draw-batch.html?api=${api}`, baseURL).href);
    return page;
  };
  try {
    for (const api of ['webgl', 'webgl2']) {
      const plain = await open(false, api), batched = await open(true, api);
      expect(await pastTheEndErrors(plain), `${api}: Firefox refuses a draw past the end of the buffer`).toEqual([1282]);
      await test.step(api, () => compareScenes(plain, batched));
    }
    expect(problems).toEqual([]);
  } finally {
    for (const p of pages) await p.close();
  }
});
