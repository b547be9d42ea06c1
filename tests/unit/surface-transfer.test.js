// The surface's two pictures leave a graded page deflated (grader/node/run/playwright-page.js,
// pageDriver's surface): the Node half takes them back byte for byte, and a picture that does not
// come out whole (too many bytes, too few, not deflate) is a reason, never a wrong picture.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { deflateSync } from 'node:zlib';
import { pageDriver } from '../../grader/node/run/playwright-page.js';

const W = 4, H = 3;
const picture = (seed) => Uint8Array.from({ length: W * H * 4 }, (_, i) => (i * seed) % 256);
const b64 = (bytes) => Buffer.from(bytes).toString('base64');
/** The driver over a page whose in-page reader gives `normals` and `points` as packed (the whole as one JSON string). */
const surfaceOf = (normals, points) =>
  pageDriver({ evaluate: async () => JSON.stringify({ width: W, height: H, position: 'vPosition', normal: null, fit: [[0.5, -0.25, 1, 0.1, 0.2, 0.3, 1]], normals, points }) }, { errors: [] })
    .surface({ fitSamples: 4 });

test('deflated or raw, each picture comes back as the page had it', async () => {
  const n = picture(7), p = picture(13);
  const s = await surfaceOf({ deflated: b64(deflateSync(n)) }, { raw: b64(p) });
  assert.equal(s.why, undefined);
  assert.deepEqual([s.normals.width, s.normals.height, s.points.width], [W, H, W]);
  assert.deepEqual(s.normals.data, n);
  assert.deepEqual(s.points.data, p);
  assert.equal(s.position, 'vPosition');
  assert.deepEqual(s.fit, [[0.5, -0.25, 1, 0.1, 0.2, 0.3, 1]]);
});

test('a picture that is not whole is a reason: more bytes, fewer bytes, not deflate', async () => {
  const n = picture(7), whole = { deflated: b64(deflateSync(n)) };
  for (const bad of [
    { deflated: b64(deflateSync(Buffer.concat([n, Buffer.from([1])]))) },
    { deflated: b64(deflateSync(n.subarray(1))) },
    { raw: b64(n.subarray(4)) },
    { deflated: b64(n) },
  ]) {
    const s = await surfaceOf(whole, bad);
    assert.match(s.why || '', /did not come out of the page whole/, JSON.stringify(bad).slice(0, 60));
  }
});
