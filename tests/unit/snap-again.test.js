// A picture snapped again unchanged (the same PNG bytes from the same canvas) is the picture
// snapped before, so that what was measured of it (core/computed/memo.js: by the picture) is not
// measured again; a changed picture is a new one, and so is one further back than the driver keeps.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { pageDriver } from '../../grader/node/run/playwright-page.js';
import { litView } from '../../grader/core/computed/views.js';

const W = 6, H = 6;
const pngOf = (shade) => {
  const p = new PNG({ width: W, height: H });
  for (let i = 0; i < p.data.length; i++) p.data[i] = i % 4 === 3 ? 255 : shade;
  return `data:image/png;base64,${PNG.sync.write(p).toString('base64')}`;
};

test('a picture snapped again unchanged is the same picture, its measurements made once', async () => {
  let next = null;
  const driver = pageDriver({ evaluate: async () => next }, { errors: [] });
  const snap = async (shade, api = 'webgl') => {
    next = { width: W, height: H, api, png: pngOf(shade) };
    return driver.snap();
  };
  const a = await snap(10), again = await snap(10), b = await snap(200);
  assert.equal(again, a, 'the same bytes: the same picture');
  assert.notEqual(b, a);
  assert.equal(await snap(10), a, 'the one before the one before');
  assert.notEqual(await snap(10, 'webgl2'), a, 'another API: another picture');
  for (const shade of [1, 2, 3, 4, 5]) await snap(shade);
  assert.notEqual(await snap(10), a, 'further back than the driver keeps: a new picture (the same pixels)');
  const { thresholds } = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
  assert.equal(litView(again, thresholds), litView(a, thresholds), 'measured once');
});
