// The error measures (tools/reference/measure.js): compareToReference's coverage, interior,
// rmse and maxError, NaN-black and saturated counts, and silhouetteErrorPx, on pictures made from
// the reference itself. The scenes and helpers are in reference-scenes.js.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { renderReference } from '../../common/exact-render.js';
import { compareToReference, silhouetteErrorPx } from '../../tools/reference/measure.js';
import { camera, lit, normals, at, close, asImage } from './reference-scenes.js';

test('compareToReference: itself gives no error, a shifted copy mismatches', () => {
  // a flat colour that 8 bits hold exactly: ka La = 1 · 51/255 = 0.2 → byte 51 → 0.2 again
  const flat = renderReference(lit({ light: { position: [0, 0, -1, 0], Le: 1, La: 0.2 }, material: { kd: 0, ka: 1, ks: 0 } }), 64, 64);
  const same = compareToReference(asImage(flat), flat);
  assert.equal(same.rmse, 0);
  assert.equal(same.maxError, 0);
  assert.equal(same.silhouetteMismatch, 0);
  assert.equal(same.silhouetteMismatchRatio, 0);
  assert.equal(same.spherePixels, flat.coverage.reduce((a, v) => a + v, 0));
  assert.ok(same.interiorPixels > 0 && same.interiorPixels < same.spherePixels);
  assert.equal(same.nanLike + same.saturated, 0);
  // a shaded one: only the 8-bit rounding, at most half a step
  const ref = renderReference(lit(), 64, 64);
  const self = compareToReference(asImage(ref), ref);
  assert.ok(self.maxError <= 0.5 / 255 + 1e-12 && self.rmse <= 0.5 / 255);
  assert.equal(self.silhouetteMismatch, 0);
  // shifted one pixel to the right: every row through the sphere mismatches at both ends
  const img = asImage(ref);
  const shifted = Buffer.alloc(img.data.length);
  for (let j = 0; j < 64; j++) {
    for (let i = 0; i < 64; i++) img.data.copy(shifted, 4 * (j * 64 + i), 4 * (j * 64 + Math.max(i - 1, 0)), 4 * (j * 64 + Math.max(i - 1, 0)) + 4);
  }
  const moved = compareToReference({ width: 64, height: 64, data: shifted }, ref);
  assert.ok(moved.silhouetteMismatch > 0 && moved.rmse > self.rmse, JSON.stringify(moved));
  assert.ok(moved.silhouetteMismatch >= 2 * 40, `${moved.silhouetteMismatch}`); // ≈ 2 × the diameter in rows
  assert.ok(silhouetteErrorPx({ width: 64, height: 64, data: shifted }, ref, lit()) > 0.5);
  assert.ok(silhouetteErrorPx(asImage(ref), ref, lit()) === 0);
});

test('compareToReference: NaN-black and saturated pixels, maxErrorAt, and sizes must match', () => {
  const ref = renderReference(lit(), 64, 64);
  const img = asImage(ref);
  const o = 4 * (32 * 64 + 32);
  img.data[o] = img.data[o + 1] = img.data[o + 2] = 0; // black where the sphere is lit
  const o2 = 4 * (30 * 64 + 20);
  img.data[o2] = img.data[o2 + 1] = img.data[o2 + 2] = 255;
  const stats = compareToReference(img, ref);
  assert.equal(stats.nanLike, 1);
  assert.equal(stats.saturated, 1);
  // the black pixel is off by its whole reference value (≈ 0.74), more than the white one
  assert.deepEqual(stats.maxErrorAt, [32, 32]);
  close(stats.maxError, at(ref, 32, 32)[0], 1e-12);
  assert.ok(1 - at(ref, 20, 30)[0] < stats.maxError);
  assert.equal(stats.silhouetteMismatch, 0);
  assert.throws(() => compareToReference({ width: 63, height: 64, data: img.data }, ref), /63×64 but the reference is 64×64/);
  assert.throws(() => compareToReference(img, ref, { interior: 'image' }), /options\.interior/);
});

test('compareToReference: interior pixels by the reference, or by both pictures', () => {
  // A picture whose sphere is ≈ 2.7 px too small all round (R 24.6 px from eye distance 3.3, not
  // 27.3; as a coarse mesh's silhouette is): its ring of
  // background inside the reference's interior counts as shading error by default, and only as
  // silhouette mismatch with { interior: 'both' }.
  const ref = renderReference(lit(), 64, 64);
  const img = asImage(ref);
  const small = renderReference(normals({ camera: { ...camera, eye: [0, 0, 3.3] } }), 64, 64);
  for (let p = 0; p < 64 * 64; p++) if (!small.coverage[p]) img.data.set([100, 149, 237], 4 * p);
  const byRef = compareToReference(img, ref);
  const byBoth = compareToReference(img, ref, { interior: 'both' });
  assert.equal(byRef.silhouetteMismatch, byBoth.silhouetteMismatch);
  assert.ok(byRef.silhouetteMismatch > 0);
  assert.ok(byRef.interiorPixels > byBoth.interiorPixels);
  assert.ok(byRef.maxError > 0.1, `by the reference: ${byRef.maxError}`);
  assert.ok(byBoth.maxError <= 0.5 / 255 + 1e-12, `by both: ${byBoth.maxError}`);
});

