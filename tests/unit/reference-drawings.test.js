// Our reference beside a student's picture: our page draws the same pixels for the same query, so a
// worker opens it once per query and compares every later part that asks the same with the picture
// it kept. A drawing that failed is never kept. drawReference over a fake opener that counts.
import { test, beforeEach, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { drawReference, forgetDrawings, REFERENCE_STEP } from '../../grader/node/run/reference.js';
import { mergeRubric } from '../../grader/core/rubric.js';

const RUBRIC = mergeRubric(JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')), {});
const dir = mkdtempSync(path.join(os.tmpdir(), 'reference-'));
after(() => rmSync(dir, { recursive: true, force: true }));
globalThis.window = { scene: { frame: 1, level: 4 } };
beforeEach(() => forgetDrawings());

/** A picture of `size`² on black with a square of `grey` in its middle half. */
function picture(size, grey) {
  const data = Buffer.alloc(4 * size * size, 255);
  for (let p = 0; p < size * size; p++) {
    const x = p % size, y = Math.floor(p / size);
    const inside = x >= size / 4 && x < (3 * size) / 4 && y >= size / 4 && y < (3 * size) / 4;
    data[4 * p] = data[4 * p + 1] = data[4 * p + 2] = inside ? grey : 0;
  }
  return { width: size, height: size, data };
}

/** An opener of our page that draws a grey picture of the size asked for, counting its opens; `failures` opens throw first. */
function countingOpener(failures = 0) {
  const opener = { opens: 0, failed: 0 };
  opener.open = async ({ query }) => {
    opener.opens++;
    if (opener.failed < failures) { opener.failed++; throw new Error('net::ERR_CONNECTION_RESET'); }
    const size = Number(new URLSearchParams(query).get('size'));
    return {
      // (the page's functions read window.scene, which our page publishes after each frame)
      page: { evaluate: async (fn) => fn() },
      driver: { tick: async () => {}, snap: async () => picture(size, 128) },
    };
  };
  opener.done = async () => {};
  return opener;
}

/** drawReference for `name`'s `part` judged at `size`: the result it fills in. */
async function compared(opener, name, part, size) {
  const result = { notes: [], numbers: {}, images: {}, steps: {} }; // (as run-part.js starts it)
  const item = { name, part, resultFile: path.join(dir, name, `${part}.json`) };
  rmSync(path.join(dir, name), { recursive: true, force: true });
  mkdirSync(path.join(dir, name), { recursive: true });
  await drawReference({ item, plan: { rubric: RUBRIC, repo: '/ours', out: dir }, openers: { reference: opener }, result, graded: { images: { judged: picture(size, 100) } } });
  return result;
}

test('a second part asking the same query is compared with the kept picture: our page is not opened again', async () => {
  const opener = countingOpener();
  const first = await compared(opener, 'ada', 'WP04P1', 16);
  const second = await compared(opener, 'bob', 'WP04P1', 16);
  assert.equal(opener.opens, 1);
  assert.ok(Number.isFinite(first.rmse) && first.rmse > 0);
  // (the time each took aside: result.steps)
  const withoutFiles = ({ images, steps: _steps, ...rest }) => ({ ...rest, images: Object.keys(images) });
  assert.deepEqual(withoutFiles(second), withoutFiles(first), 'the same comparison, notes and reference state');
  assert.deepEqual(readFileSync(path.join(dir, 'bob', 'WP04P1-reference.png')), readFileSync(path.join(dir, 'ada', 'WP04P1-reference.png')));
  await compared(opener, 'cy', 'WP04P2', 16);
  await compared(opener, 'dan', 'WP04P1', 24);
  assert.equal(opener.opens, 3, 'another part or another canvas size is another query');
});

test("the time our reference took is a step of the part's, drawn or recalled, failed or not", async () => {
  const opener = countingOpener(1);
  for (const name of ['ada', 'bob', 'cy']) {
    const result = await compared(opener, name, 'WP04P1', 16);
    assert.deepEqual(Object.keys(result.steps), [REFERENCE_STEP], name);
    assert.ok(result.steps[REFERENCE_STEP] >= 0, name);
  }
  assert.equal(opener.opens, 2, 'failed, drawn, recalled');
});

test('a drawing that failed is not kept: the next part asking the same opens our page again', async () => {
  const opener = countingOpener(1);
  const failed = await compared(opener, 'ada', 'WP04P1', 16);
  assert.match(failed.notes.join('\n'), /our reference could not be drawn: net::ERR_CONNECTION_RESET/);
  assert.equal(failed.rmse, undefined);
  const drawn = await compared(opener, 'bob', 'WP04P1', 16);
  assert.equal(opener.opens, 2);
  assert.ok(Number.isFinite(drawn.rmse));
});
