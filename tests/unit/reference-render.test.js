// The exact reference renderer (common/exact-render.js), checked against values worked out by
// hand: colours at chosen points, the silhouette, highlights, point lights, clipping and culling,
// bad scenes, speed; and its pictures as 8-bit RGBA and PNG (tools/reference/png.js).
// The scenes and helpers are in reference-scenes.js.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { BACKGROUND, shadePoint, renderReference } from '../../common/exact-render.js';
import { toRGBA8, writePNG } from '../../tools/reference/png.js';
import { camera, lit, normals, at, covered, close, grey } from './reference-scenes.js';

const sub = (a, b) => a.map((v, k) => v - b[k]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a) => a.map((v) => v / Math.hypot(...a));

// Silhouette of the unit sphere seen from distance 3: the tangent rays make asin(1/3) with the
// axis, tan(asin(1/3)) = (1/3)/√(8/9) = 1/√8 ≈ 0.353553, so in NDC R = 0.353553/0.414214 ≈ 0.853553.
const R_NDC = Math.tan(Math.asin(1 / 3)) / Math.tan(Math.PI / 8);

test('centre pixel: n = w_i = w_o = (0,0,1), so w_r = w_o and L_o = kd + ks + ka La', () => {
  // 101 × 101: pixel 50's centre is at NDC 2·50.5/101 − 1 = 0 exactly; the ray hits p = (0, 0, 1).
  const ref = renderReference(lit(), 101, 101);
  assert.ok(covered(ref, 50, 50));
  // w_r = 2(w_i·n)n − w_i = (0,0,1), w_r·w_o = 1, 1^40 = 1: 0.5·1 + 0.2·1 + 0.5·0.1 = 0.75
  close(at(ref, 50, 50), grey(0.75));
  // Blinn-Phong agrees there: w_h = normalize(w_i + w_o) = n, n·w_h = 1
  close(at(renderReference(lit({ model: 'blinn-phong' }), 101, 101), 50, 50), grey(0.75));
  // the brief's numbers clamp: kd 0.8 + ks 0.5 + ka La 0.8·0.2 = 1.46 → 1
  const bright = lit({ light: { position: [0, 0, -1, 0], Le: 1, La: 0.2 }, material: { kd: 0.8, ka: 0.8, ks: 0.5, s: 40 } });
  close(at(renderReference(bright, 101, 101), 50, 50), grey(1));
  // colours per channel: kd (1, 0.5, 0), ks 0.2, La 0.1 → (1 + 0.2 + 0.1, 0.5 + 0.2 + 0.05, 0 + 0.2 + 0) → (1, 0.75, 0.2)
  close(shadePoint(lit({ material: { kd: [1, 0.5, 0], ks: 0.2, s: 40 } }), [0, 0, 1]), [1, 0.75, 0.2]);
  // Le per channel scales the direct part only: Le (1, 0, 2) → (0.7 + 0.05, 0 + 0.05, 1.4 + 0.05)
  close(shadePoint(lit({ light: { position: [0, 0, -1, 0], Le: [1, 0, 2], La: 0.1 } }), [0, 0, 1]), [0.75, 0.05, 1.45].map((v) => Math.min(v, 1)));
});

test('WP04P3 scenes: no ks, s or La (they count as 0) and ka defaults to kd', () => {
  const p3 = { camera, shading: 'gouraud', light: { position: [0, 0, -1, 0], Le: 1 }, material: { kd: 0.5 } };
  // kd Le max(n·w_i, 0) = 0.5 at the centre, nothing else
  close(shadePoint(p3, [0, 0, 1]), grey(0.5));
  // p = (0.6, 0, 0.8): n·w_i = 0.8 → 0.4
  close(shadePoint(p3, [0.6, 0, 0.8]), grey(0.4));
  // with La 0.1 and no ka: ka = kd = 0.5 → + 0.05
  close(shadePoint({ ...p3, light: { ...p3.light, La: 0.1 } }, [0.6, 0, 0.8]), grey(0.45));
});

test('grazing light from the side: n·w_i = 0 on the centre column, ambient only, no NaN', () => {
  // position (−1, 0, 0, 0) → w_i = (1, 0, 0). Column 50 of 101 has NDC x = 0, so its rays stay in
  // the plane x = 0 (d = f + y u has no x part): every hit there has n·w_i = p_x = 0 exactly,
  // up to the silhouette at the top and bottom. L_o = ka La = 0.5·0.1 = 0.05.
  const scene = lit({ light: { position: [-1, 0, 0, 0], Le: 1, La: 0.1 } });
  const ref = renderReference(scene, 101, 101);
  let top = 0;
  while (!covered(ref, 50, top)) top++;
  assert.ok(top > 0 && top < 10, `the top of the sphere is at row ${top}`);
  for (let j = top; j <= 100 - top; j++) close(at(ref, 50, j), grey(0.05), 1e-12, `row ${j}`);
  // the left half faces away from the light (n·w_i < 0): ambient only, even where Phong's
  // w_r·w_o would be positive; the right half is lit, brighter than ambient
  for (let j = 0; j < 101; j++) {
    for (let i = 0; i < 101; i++) {
      if (!covered(ref, i, j)) continue;
      const [r, g, b] = at(ref, i, j);
      assert.ok(Number.isFinite(r) && r === g && g === b, `pixel ${i},${j} is grey and finite`);
      if (i < 50) assert.equal(r, 0.05);
      if (i > 50) assert.ok(r > 0.05, `pixel ${i},${j} is lit`);
    }
  }
  // a point just past the terminator: p = (0.01, 0, √0.9999), n·w_i = 0.01 → 0.05 + 0.5·0.01 =
  // 0.055; w_r·w_o ≈ 0.025 there, and 0.025^40 ≈ 1e−64 adds nothing
  close(shadePoint(scene, [0.01, 0, Math.sqrt(0.9999)]), grey(0.055), 1e-12);
});

test('no highlight on the side facing away from the light', () => {
  // Light from behind: position (0, 0, 1, 0) → w_i = (0, 0, −1). At p = (√3/2, 0, 1/2) (visible:
  // n·(eye − p) = 3·0.5 − 1 > 0): w_o = (−√3/2, 0, 5/2)/√7, n·w_o = 0.5/√7, n·w_i = −1/2, so
  // w_r·w_o = 2(−1/2)(0.5/√7) − w_i·w_o = −0.5/√7 + 2.5/√7 = 2/√7 ≈ 0.756 > 0:
  // an ungated Phong term would add ks·0.756 = 0.151. The model gives ambient only: 0.05.
  const p = [Math.sqrt(3) / 2, 0, 0.5];
  const wo = unit(sub(camera.eye, p));
  const wi = [0, 0, -1];
  const wr = sub(p.map((v) => 2 * dot(wi, p) * v), wi);
  close(dot(wr, wo), 2 / Math.sqrt(7), 1e-12, 'w_r · w_o');
  const scene = lit({ light: { position: [0, 0, 1, 0], Le: 1, La: 0.1 }, material: { kd: 0.5, ks: 0.2, s: 1 } });
  close(shadePoint(scene, p), grey(0.05));
});

test('silhouette: pixel centres just inside R = tan(asin(1/3))/tan(22.5°) are sphere, just outside background', () => {
  // R ≈ 0.853553 NDC. At 101 × 101, pixel centres of the middle row sit k pixels from the centre
  // and R = 0.853553·50.5 ≈ 43.104 px: |k| ≤ 43 is sphere, 44 is not.
  const ref101 = renderReference(normals(), 101, 101);
  close(R_NDC * 50.5, 43.10444622, 1e-8, 'R in pixels');
  for (const k of [43, -43]) assert.ok(covered(ref101, 50 + k, 50), `offset ${k}`);
  for (const k of [44, -44]) assert.ok(!covered(ref101, 50 + k, 50), `offset ${k}`);
  // the same vertically (row 0 at the top)
  assert.ok(covered(ref101, 50, 7) && covered(ref101, 50, 93));
  assert.ok(!covered(ref101, 50, 6) && !covered(ref101, 50, 94));
  // 512 × 512, a tight one: R = 0.853553·256 ≈ 218.5097 px. Row 255's centre is 0.5 px off the
  // axis, so its half chord is √(218.5097² − 0.25) ≈ 218.5091: the centre 218.5 px out (column
  // 256 + 218 = 474, or 256 − 219 = 37) is inside by 0.009 px, the next (475, 36) outside.
  const ref512 = renderReference(normals(), 512, 512);
  assert.ok(covered(ref512, 474, 255) && covered(ref512, 37, 255));
  assert.ok(!covered(ref512, 475, 255) && !covered(ref512, 36, 255));
  assert.ok(covered(ref512, 255, 37) && !covered(ref512, 255, 36));
  // the background is the course's cornflower blue
  close(at(ref512, 0, 0), BACKGROUND, 0);
});

test('coverage ≈ π R² pixels, and a non-square picture keeps the sphere round', () => {
  // 512²: π (218.5097)² ≈ 150,000 pixels
  const ref = renderReference(normals(), 512, 512);
  const count = ref.coverage.reduce((a, v) => a + v, 0);
  const expected = Math.PI * (R_NDC * 256) ** 2;
  assert.ok(Math.abs(count - expected) / expected < 0.01, `${count} pixels, π R² = ${expected}`);
  // 161 × 81 with no camera.aspect: aspect = 161/81, and the sphere's radius in pixels is the same
  // across and up: R = 0.853553 · 40.5 ≈ 34.57 px either way
  const wide = renderReference(normals({ camera: { ...camera, aspect: undefined } }), 161, 81);
  const across = [...Array(161).keys()].filter((i) => covered(wide, i, 40)).length;
  const up = [...Array(81).keys()].filter((j) => covered(wide, 80, j)).length;
  assert.equal(across, up);
  assert.equal(across, 2 * Math.floor(R_NDC * 40.5) + 1); // centres at 0, ±1, ..., ±34 px
});

test('row 0 is the top: normals shading c = 0.5 n + 0.5', () => {
  // the centre (0, 0, 1) → (0.5, 0.5, 1); p = (0.6, 0, 0.8) → (0.8, 0.5, 0.9)
  close(shadePoint(normals(), [0, 0, 1]), [0.5, 0.5, 1]);
  close(shadePoint(normals(), [0.6, 0, 0.8]), [0.8, 0.5, 0.9]);
  close(shadePoint(normals(), [0, -1, 0]), [0.5, 0, 0.5]);
  const ref = renderReference(normals(), 101, 101);
  close(at(ref, 50, 50), [0.5, 0.5, 1]);
  // top of the picture: n_y > 0, green above 0.5; bottom below; right: red above 0.5
  assert.ok(at(ref, 50, 10)[1] > 0.75 && at(ref, 50, 90)[1] < 0.25);
  assert.ok(at(ref, 90, 50)[0] > 0.75 && at(ref, 10, 50)[0] < 0.25);
  // a WP04P1 scene has neither light nor material, and needs neither
  assert.doesNotThrow(() => renderReference({ ...normals(), light: undefined, material: undefined }, 8, 8));
});

test('highlight: the Phong peak is where w_r = w_o, the Blinn-Phong peak where n = w_h', () => {
  // Build the light so that the mirror direction of w_o about n at p = (0.6, 0, 0.8) is w_i:
  // eye − p = (−0.6, 0, 2.2), |.| = √5.2, w_o ≈ (−0.263117, 0, 0.964764), n·w_o ≈ 0.613941,
  // w_i = 2(n·w_o)n − w_o ≈ (0.999846, 0, 0.017542): a light from the right, nearly from the side.
  const p = [0.6, 0, 0.8];
  const wo = unit(sub(camera.eye, p));
  const wi = sub(p.map((v) => 2 * dot(wo, p) * v), wo);
  close(wi, [0.999846, 0, 0.017542], 1e-6, 'w_i');
  const scene = (model) => lit({ model, light: { position: [...wi.map((v) => -v), 0], Le: 1, La: 0 }, material: { kd: 0, ka: 0, ks: 1, s: 200 } });
  // at p both terms peak at 1: w_r = w_o (Phong), w_h = normalize(w_i + w_o) = n (Blinn-Phong)
  close(shadePoint(scene('phong'), p), grey(1), 1e-9);
  close(shadePoint(scene('blinn-phong'), p), grey(1), 1e-9);
  // and fall off around it
  for (const q of [[0.62, 0, 0.7846], [0.58, 0.05, 0.8131], [0.6, -0.05, 0.7984]]) {
    const n = unit(q);
    assert.ok(shadePoint(scene('phong'), n)[0] < 1 - 1e-3, `phong at ${q}`);
    assert.ok(shadePoint(scene('blinn-phong'), n)[0] < 1 - 1e-3, `blinn at ${q}`);
  }
  // in a 201 × 201 picture p projects to NDC x = (0.6/2.2)/0.414214 ≈ 0.658419, y = 0, i.e.
  // column (x + 1)/2 · 201 − 0.5 ≈ 166.17, row 100: the brightest pixel, for both models
  for (const model of ['phong', 'blinn-phong']) {
    const ref = renderReference(scene(model), 201, 201);
    let best = -1, bestAt = null;
    for (let j = 0; j < 201; j++) for (let i = 0; i < 201; i++) if (at(ref, i, j)[0] > best) { best = at(ref, i, j)[0]; bestAt = [i, j]; }
    assert.deepEqual(bestAt, [166, 100], model);
    assert.ok(best > 0.99, `${model} peak ${best}`);
  }
});

test('Phong and Blinn-Phong differ as cos φ and cos ψ = cos(φ/2) at the centre', () => {
  // n = w_o = (0, 0, 1), light at 60° from the axis: w_i = (sin 60°, 0, cos 60°).
  // Phong: w_r = (−sin 60°, 0, cos 60°), w_r·w_o = 0.5, s = 2 → 0.25.
  // Blinn-Phong: w_h halfway between w_i and w_o, 30° from n: n·w_h = cos 30°, squared = 0.75.
  const wi = [Math.sin(Math.PI / 3), 0, Math.cos(Math.PI / 3)];
  const scene = (model) => lit({ model, light: { position: [...wi.map((v) => -v), 0], Le: 1, La: 0 }, material: { kd: 0, ka: 0, ks: 1, s: 2 } });
  // eye at (0, 0, 3) sees p = (0, 0, 1) along w_o = (0, 0, 1) exactly
  close(shadePoint(scene('phong'), [0, 0, 1]), grey(0.25));
  close(shadePoint(scene('blinn-phong'), [0, 0, 1]), grey(0.75));
});

test('w_i = −w_o (no halfway vector) and shininess 0', () => {
  // The inside of the back, p = (0, 0, −1), n = p, seen from the eye: w_o = (0, 0, 1); light
  // position (0, 0, 1, 0) → w_i = (0, 0, −1) = −w_o, n·w_i = 1. Blinn-Phong: w_i + w_o = 0, no
  // highlight; Phong: w_r = 2n − w_i = (0, 0, −1), w_r·w_o = −1, none either. 0.5 + 0.05 = 0.55.
  const scene = (model) => lit({ model, light: { position: [0, 0, 1, 0], Le: 1, La: 0.1 } });
  close(shadePoint(scene('blinn-phong'), [0, 0, -1]), grey(0.55));
  close(shadePoint(scene('phong'), [0, 0, -1]), grey(0.55));
  // s = 0: max(cos, 0)^0 is 1 where the cosine is positive, and 0 where it is not (there we take
  // 0^0 = 0, where Math.pow(0, 0) = 1, as the pages' shaders do). Frontal light, w_i = (0, 0, 1):
  const s0 = lit({ light: { position: [0, 0, -1, 0], Le: 1, La: 0 }, material: { kd: 0, ka: 0, ks: 0.2, s: 0 } });
  // at the centre w_r·w_o = 1 → 0.2 · 1^0 = 0.2
  close(shadePoint(s0, [0, 0, 1]), grey(0.2));
  // at p = (0.8, 0, 0.6) (lit: n·w_i = 0.6): w_r = 1.2 p − w_i = (0.96, 0, −0.28),
  // w_o = (−0.8, 0, 2.4)/√6.4 ≈ (−0.3162, 0, 0.9487), w_r·w_o ≈ −0.3036 − 0.2656 < 0 → 0, not 0.2
  close(shadePoint(s0, [0.8, 0, 0.6]), grey(0));
});

test('point light: L_i = Le / r², w_i = normalize(p_l − p), position divided by w', () => {
  // light at (0, 0, 3, 1), p = (0, 0, 1): r = 2, L_i = 4/4 = 1, w_i = (0, 0, 1):
  // 0.5·1 + 0.2·1 + 0.05 = 0.75 at the centre pixel
  const scene = (position, Le = 4) => lit({ light: { position, Le, La: 0.1 } });
  close(at(renderReference(scene([0, 0, 3, 1]), 101, 101), 50, 50), grey(0.75));
  // (0, 0, 6, 2) is the same point
  close(shadePoint(scene([0, 0, 6, 2]), [0, 0, 1]), grey(0.75));
  // twice as far (r = 4): a quarter: (0.5 + 0.2)/4 + 0.05 = 0.225
  close(shadePoint(scene([0, 0, 5, 1]), [0, 0, 1]), grey(0.225));
  // off-axis: light at (3, 0, 1, 1), p = (0.6, 0, 0.8): p_l − p = (2.4, 0, 0.2), r² = 5.8,
  // w_i = (2.4, 0, 0.2)/√5.8, n·w_i = (1.44 + 0.16)/√5.8 = 1.6/√5.8; diffuse only (ks 0, La 0):
  // 0.5 · (5.8/5.8) · 1.6/√5.8 = 0.8/√5.8 ≈ 0.332182 with Le = 5.8
  const off = lit({ light: { position: [3, 0, 1, 1], Le: 5.8, La: 0 }, material: { kd: 0.5, ks: 0 } });
  close(shadePoint(off, [0.6, 0, 0.8]), grey(0.8 / Math.sqrt(5.8)));
  // a light inside the sphere lights none of it: (p_l − p)·p = p_l·p − 1 < 0 everywhere
  close(shadePoint(lit({ light: { position: [0, 0, 0.5, 1], Le: 1, La: 0.1 } }), [0, 0, 1]), grey(0.05));
  // a light on the surface point itself has no direction there: ambient only, no NaN
  close(shadePoint(lit({ light: { position: [0, 0, 1, 1], Le: 1, La: 0.1 } }), [0, 0, 1]), grey(0.05));
});

test('near and far planes clip by view depth; culling decides whether the inside shows', () => {
  // eye (0, 0, 3), near 2.5: the front point (0, 0, 1) is at depth 2 < 2.5, clipped. Front hits
  // are visible where p_z ≤ 0.5, i.e. outside the circle of radius √0.75 at depth 2.5:
  // NDC (0.866025/2.5)/0.414214 ≈ 0.836308, 214.09 px at 512. The sphere becomes a ring.
  const clipped = (over) => normals({ camera: { ...camera, near: 2.5 }, ...over });
  const ring = renderReference(clipped({ cullFace: true }), 512, 512);
  assert.ok(!covered(ring, 256, 256), 'the centre shows the background');
  close(at(ring, 256, 256), BACKGROUND, 0);
  assert.ok(!covered(ring, 256 + 213, 255), '213.5 px: clipped');
  assert.ok(covered(ring, 256 + 214, 255) && covered(ring, 256 + 218, 255), '214.5 and 218.5 px: the ring');
  // without culling the far root shows through the hole: at the centre pixel of 101 × 101,
  // p = (0, 0, −1), n = p → (0.5, 0.5, 0)
  const inside = renderReference(clipped({ cullFace: false }), 101, 101);
  close(at(inside, 50, 50), [0.5, 0.5, 0]);
  assert.ok(!covered(renderReference(clipped({ cullFace: true }), 101, 101), 50, 50));
  // far 2.2 < the silhouette's depth √8·cos(asin(1/3)) = 8/3: only a cap around the front point
  const cap = renderReference(normals({ camera: { ...camera, far: 2.2 } }), 101, 101);
  assert.ok(covered(cap, 50, 50) && !covered(cap, 50 + 40, 50));
  // an eye so close that the whole front is nearer than the near plane: eye (0, 0, 1.05), near
  // 0.1. The farthest front points, the silhouette's, are at depth (d² − 1)/d = 0.1025/1.05 ≈
  // 0.098 < 0.1: with culling nothing shows; without, the far side does (centre: (0.5, 0.5, 0))
  const closeUp = (cullFace) => renderReference(normals({ camera: { ...camera, eye: [0, 0, 1.05], fovy: 120 }, cullFace }), 65, 65);
  assert.equal(closeUp(true).coverage.reduce((a, v) => a + v, 0), 0);
  close(at(closeUp(false), 32, 32), [0.5, 0.5, 0]);
  // an eye inside the sphere sees only back faces: nothing with culling, everything without
  const inEye = (cullFace) => renderReference(normals({ camera: { ...camera, eye: [0, 0, 0.5] }, cullFace }), 32, 32);
  assert.equal(inEye(true).coverage.reduce((a, v) => a + v, 0), 0);
  assert.equal(inEye(false).coverage.reduce((a, v) => a + v, 0), 32 * 32);
  // frontFace "cw" with culling (WP04P2's "Clockwise front faces"): the inside of the back half
  close(at(renderReference(normals({ cullFace: true, frontFace: 'cw' }), 101, 101), 50, 50), [0.5, 0.5, 0]);
});

test('toRGBA8 and writePNG: round(v·255), alpha 255, row 0 on top', () => {
  const ref = renderReference(normals(), 33, 33);
  const bytes = toRGBA8(ref);
  assert.ok(bytes instanceof Uint8ClampedArray);
  assert.equal(bytes.length, 33 * 33 * 4);
  assert.deepEqual([...bytes.subarray(0, 4)], [100, 149, 237, 255]); // the background
  assert.deepEqual([...bytes.subarray(4 * (16 * 33 + 16), 4 * (16 * 33 + 16) + 4)], [128, 128, 255, 255]); // (0.5, 0.5, 1)
  const dir = mkdtempSync(path.join(tmpdir(), 'reference-'));
  try {
    const file = path.join(dir, 'ref.png');
    writePNG(file, ref);
    const png = PNG.sync.read(readFileSync(file));
    assert.equal(png.width, 33);
    assert.deepEqual([...png.data], [...bytes]);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('bad scenes fail with a clear message', () => {
  assert.throws(() => renderReference(lit({ light: { Le: 1 } }), 8, 8), /light\.position/);
  assert.throws(() => renderReference(lit({ material: { kd: 'red' } }), 8, 8), /material\.kd/);
  assert.throws(() => renderReference(lit({ model: 'cook-torrance' }), 8, 8), /model/);
  assert.throws(() => renderReference(normals({ camera: { ...camera, up: [0, 0, 1] } }), 8, 8), /parallel/);
  assert.throws(() => renderReference(normals(), 0, 8), /positive integers/);
});

