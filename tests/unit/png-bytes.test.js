// A picture the browser handed over as a PNG is written with the browser's own bytes (encoding it
// again was a tenth of a class's CPU), reads back as the same pixels, and a picture made here is
// encoded; a recording keeps the file of a picture whose pixels did not change.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { pageDriver } from '../../grader/node/run/playwright-page.js';
import { decodePng, pngBytes } from '../../grader/node/run/png.js';
import { writeArtifact, readArtifact } from '../../grader/node/run/artifacts.js';
import { picturesIn, keepSamePictures } from '../fixtures/same-pictures.js';

const W = 5, H = 4;
const pixels = Uint8Array.from({ length: W * H * 4 }, (_, i) => (i % 4 === 3 ? 255 : (i * 37) % 256));
/** `pixels` as a PNG encoded otherwise than pngBytes would (RGBA, no filter): bytes only a verbatim write keeps. */
const browserPng = () => {
  const p = new PNG({ width: W, height: H });
  p.data.set(pixels);
  return PNG.sync.write(p, { colorType: 6, filterType: 0 });
};
const tmp = () => mkdtempSync(path.join(os.tmpdir(), 'png-bytes-'));

test("a snapped picture keeps the page's PNG bytes, and the artifact writes them as they are", async () => {
  const png = browserPng();
  const url = `data:image/png;base64,${png.toString('base64')}`;
  const driver = pageDriver({ evaluate: async () => ({ width: W, height: H, api: 'webgl', png: url }) }, { errors: [] });
  const img = await driver.snap();
  assert.deepEqual([img.width, img.height, img.api], [W, H, 'webgl']);
  assert.deepEqual(img.data, pixels);
  assert.ok(img.png.equals(png));
  const dir = path.join(tmp(), 'part');
  const files = writeArtifact(dir, { facts: {}, images: { first: img } });
  assert.ok(readFileSync(path.join(dir, files.first)).equals(png), 'the file is the browser\'s bytes');
  assert.deepEqual(readArtifact(dir).images.first.data, pixels);
});

test('a picture made here, or a copy of a snapped one, is encoded and reads back the same', () => {
  const made = { width: W, height: H, data: pixels };
  const copy = { ...decodePng(browserPng()) };
  assert.equal(copy.png, undefined);
  for (const img of [made, copy]) {
    const bytes = pngBytes(img);
    assert.ok(!bytes.equals(browserPng()));
    assert.deepEqual(decodePng(bytes).data, pixels);
  }
});

test('a recording keeps the file of a picture drawn the same in other bytes, and takes a changed one', () => {
  const dir = tmp();
  mkdirSync(path.join(dir, 'a', 'WP04P1'), { recursive: true });
  const old = browserPng(), again = pngBytes({ width: W, height: H, data: pixels });
  const changed = pngBytes({ width: W, height: H, data: pixels.map((v, i) => (i === 0 ? v ^ 1 : v)) });
  writeFileSync(path.join(dir, 'a', 'WP04P1', 'first.png'), old);
  writeFileSync(path.join(dir, 'a', 'WP04P1', 'last.png'), old);
  const before = picturesIn(dir);
  assert.deepEqual([...before.keys()].sort(), [path.join('a', 'WP04P1', 'first.png'), path.join('a', 'WP04P1', 'last.png')]);
  writeFileSync(path.join(dir, 'a', 'WP04P1', 'first.png'), again);
  writeFileSync(path.join(dir, 'a', 'WP04P1', 'last.png'), changed);
  assert.equal(keepSamePictures(before, dir), 1);
  assert.ok(readFileSync(path.join(dir, 'a', 'WP04P1', 'first.png')).equals(old));
  assert.ok(readFileSync(path.join(dir, 'a', 'WP04P1', 'last.png')).equals(changed));
});
