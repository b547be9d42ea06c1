// The two channels of a picture (grader/core/measure/shown.js, audits/channels.js): the canvas as
// read back against the canvas as the browser shows it, on pictures built here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { shownDifference } from '../../grader/core/measure/shown.js';
import { auditShown } from '../../grader/core/audits/units/shown-channels.js';

const thresholds = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
/** A w×h picture: pixel (x, y) is f(x, y) → [r, g, b, a]. */
const picture = (w, h, f) => {
  const data = new Uint8Array(w * h * 4);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) data.set(f(x, y), 4 * (y * w + x));
  return { width: w, height: h, data };
};
const disc = (cx, cy, r, inside, outside) => (x, y) => (Math.hypot(x + 0.5 - cx, y + 0.5 - cy) < r ? inside : outside);
const sphere = (x0 = 0, y0 = 0, k = 1) => disc(x0 + 20 * k, y0 + 20 * k, 15 * k, [200, 100, 50, 255], [30, 30, 30, 255]);
const raw = picture(40, 40, sphere());
// the canvas's box on the page, and a screenshot of it with a pixel more around it
const box = { x: 100, y: 50, width: 40, height: 40 };
const clip = { x: 99, y: 49, width: 42, height: 42 };
const page = (f) => picture(42, 42, (x, y) => f(x - 1, y - 1));

test('the same picture on both channels, also a pixel off (a fractional place) and shown at twice its size', () => {
  assert.deepEqual(shownDifference({ raw, shown: page(sphere()), box, clip }, thresholds), { compared: true, opaque: 1600, share: 0 });
  assert.equal(shownDifference({ raw, shown: page(sphere(0, 1)), box, clip }, thresholds).share, 0, 'a row lower');
  // CSS width 80px: each canvas pixel shown as four
  const big = { x: 100, y: 50, width: 80, height: 80 };
  // (a circle drawn at twice the size against one scaled up: its edge alone differs)
  const scaled = shownDifference({ raw, shown: picture(82, 82, (x, y) => sphere(0, 0, 2)(x - 1, y - 1)), box: big, clip: { x: 99, y: 49, width: 82, height: 82 } }, thresholds);
  assert.ok(scaled.compared && scaled.share < 0.02, JSON.stringify(scaled));
});

test('a black disc shown over the sphere read back: the share that differs; transparent pixels are not compared; nothing to compare, said', () => {
  const d = shownDifference({ raw, shown: page(disc(20, 20, 15, [0, 0, 0, 255], [30, 30, 30, 255])), box, clip }, thresholds);
  assert.ok(d.compared && d.share > 0.4 && d.share < 0.5, JSON.stringify(d));
  const clear = picture(40, 40, disc(20, 20, 15, [200, 100, 50, 255], [0, 0, 0, 0]));
  assert.equal(shownDifference({ raw: clear, shown: page(disc(20, 20, 15, [200, 100, 50, 255], [128, 128, 128, 255])), box, clip }, thresholds).share, 0, 'a transparent clear colour over the page\'s own background');
  assert.deepEqual(shownDifference({ why: 'the canvas is mostly out of view' }, thresholds), { compared: false, why: 'the canvas is mostly out of view' });
  assert.deepEqual(shownDifference({ raw: picture(40, 40, () => [0, 0, 0, 0]), shown: page(sphere()), box, clip }, thresholds), { compared: false, why: 'no opaque pixel of the canvas is in view' });
});

test('the audit: review where the channels differ, the browser\'s picture shown; a first frame that differed is no reason to fail', () => {
  const said = [];
  const C = (shown) => ({ facts: { shown }, thresholds, sayAs: () => (level, reason) => said.push([level, reason]), imagesShown: {} });
  const same = C([{ at: 'first', compared: true, opaque: 900, share: 0.001 }, { at: 'last', compared: false, why: 'not read' }]);
  assert.equal(auditShown(same), false);
  assert.deepEqual(said, []);
  const off = C([{ at: 'first', compared: true, opaque: 900, share: 0.46, image: 'shown-first' }]);
  assert.equal(auditShown(off), true);
  assert.equal(said[0][0], 'review');
  assert.match(said[0][1], /^what the page reads back differs from what the browser shows, at the first frame: 46% /);
  assert.deepEqual(off.imagesShown, { shownFirst: 'shown-first' });
  assert.equal(auditShown(C([{ at: 'last', compared: true, opaque: 900, share: 0.3 }])), false, 'differing at the end only: the first frame stands');
});
