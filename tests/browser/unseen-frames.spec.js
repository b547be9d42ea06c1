// The draws of WebGL frames nobody looks at are left undone (grader/browser/unseen-frames.js), and
// where that could show, the run says so (`unsafe`: the grader then gathers the part again with
// every frame drawn). A small loop page (tests/fixtures/unseen/loop.html) in the grader's own page
// opener, once skipping and once drawing every frame: the pictures read after each run of frames
// must be the same bytes. Project webgl2 only: the opener launches nothing, the browser is the test's.
import path from 'node:path';
import { test, expect } from '@playwright/test';
import { partOpener } from '../../grader/node/run/playwright-page.js';

const ROOT = path.resolve(import.meta.dirname, '../fixtures/unseen');

/** loop.html?query opened by an opener that skips unseen frames (`skipUnseen`) or draws them all. */
async function opened(browser, query, skipUnseen) {
  const opener = partOpener(browser, 'submission.localhost', { skipUnseen });
  const log = { errors: [], blocked: [], notes: [] };
  const o = await opener.open({ root: ROOT, rel: 'loop.html', query, loadSeconds: 20, log });
  expect(o.why, 'opened').toBeUndefined();
  return o.driver;
}

/** The pictures after three runs of frames (a jump, then 8 frames; 2 frames; a jump alone), and what was skipped. */
async function runs(driver) {
  const pictures = [];
  for (const [ms, frames] of [[800, 8], [100, 2], [100, 0]]) {
    await driver.tick(ms, frames);
    pictures.push(Buffer.from((await driver.snap()).data));
  }
  return { pictures, unseen: await driver.unseen() };
}

test.describe('frames nobody looks at', () => {
  // eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
  test.beforeEach(({}, testInfo) => test.skip(testInfo.project.name !== 'webgl2', 'the grader\'s own page opener; once is enough'));

  test('a loop that clears the canvas first: its unseen frames\' draws are skipped, and every picture read is the one every frame drawn gives', async ({ browser }) => {
    const skipping = await runs(await opened(browser, '', true));
    const drawn = await runs(await opened(browser, '', false));
    expect(drawn.unseen, 'an opener that draws every frame skips nothing').toBeNull();
    expect(skipping.unseen.unsafe).toBeNull();
    // (8 frames after the jump: 7 unseen; 2 frames: 1; a jump alone: none)
    expect(skipping.unseen.skipped).toBe(8);
    for (let k = 0; k < drawn.pictures.length; k++) expect(skipping.pictures[k].equals(drawn.pictures[k]), `picture ${k}`).toBe(true);
    expect(skipping.pictures[0].equals(skipping.pictures[1]), 'the triangle turned between the runs').toBe(false);
  });

  test('where skipping could show, it says so: a loop that stops by itself, one that reads its canvas back; one that never clears is drawn whole', async ({ browser }) => {
    // it stops after 4 frames, in the middle of the first run: its last frame would be skipped
    const stops = await runs(await opened(browser, 'stop=4', true));
    expect(stops.unseen.unsafe).toMatch(/^a run of frames ended with draws skipped and not cleared away/);
    const reads = await runs(await opened(browser, 'read=1', true));
    expect(reads.unseen.unsafe).toMatch(/^readPixels after skipped draws/);
    // each frame drawn over the last: nothing is skipped, so the pictures are every frame's
    const accumulates = await runs(await opened(browser, 'clear=0', true));
    const drawn = await runs(await opened(browser, 'clear=0', false));
    expect(accumulates.unseen).toEqual({ skipped: 0, unsafe: null });
    for (let k = 0; k < drawn.pictures.length; k++) expect(accumulates.pictures[k].equals(drawn.pictures[k]), `picture ${k}`).toBe(true);
  });
});
