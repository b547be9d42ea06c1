// Our reference beside a student's picture: the exact render (common/exact-render.js; WP04P1: our
// mesh drawn in order, common/mesh-render.js) of the scene our page shows for the query, at the
// student's canvas size, lit from the fitted light; kept per query by a worker for the parts that
// ask again. The scenes here are written out from the slides' defaults (common/params.js: kd 0.8,
// ks 0.5, s 40, Le 1, La 0.2; the eye at (0, 0, 3), 45°), not read from the module under test.
import { test, beforeEach, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { drawReference, forgetDrawings, REFERENCE_STEP } from '../../grader/node/run/reference.js';
import { decodePng } from '../../grader/node/run/png.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { renderReference, toRGBA8 } from '../../common/exact-render.js';
import { renderMeshInOrder } from '../../common/mesh-render.js';
import { sphereMesh } from '../../common/sphere.js';

const RUBRIC = mergeRubric(JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')), {});
const dir = mkdtempSync(path.join(os.tmpdir(), 'reference-'));
after(() => rmSync(dir, { recursive: true, force: true }));
beforeEach(() => forgetDrawings());

/** A picture of `width`×`height` on black with a square of `grey` in its middle half. */
function picture(width, grey, height = width) {
  const data = Buffer.alloc(4 * width * height, 255);
  for (let p = 0; p < width * height; p++) {
    const x = p % width, y = Math.floor(p / width);
    const inside = x >= width / 4 && x < (3 * width) / 4 && y >= height / 4 && y < (3 * height) / 4;
    data[4 * p] = data[4 * p + 1] = data[4 * p + 2] = inside ? grey : 0;
  }
  return { width, height, data };
}

/** drawReference for `name`'s `part` judged at `width`×`height` with `numbers`: the result it fills in. */
async function compared(name, part, width, { height = width, numbers = {} } = {}) {
  const result = { notes: [], numbers, images: {}, steps: {} }; // (as run-part.js starts it)
  const item = { name, part, resultFile: path.join(dir, name, `${part}.json`), referenceQuery: {} };
  rmSync(path.join(dir, name), { recursive: true, force: true });
  mkdirSync(path.join(dir, name), { recursive: true });
  await drawReference({ item, plan: { rubric: RUBRIC, out: dir }, result, graded: { images: { judged: picture(width, 100, height) } } });
  return result;
}

const referenceOf = (name, part) => decodePng(readFileSync(path.join(dir, name, `${part}-reference.png`)));
const camera = (aspect) => ({ eye: [0, 0, 3], at: [0, 0, 0], up: [0, 1, 0], fovy: 45, aspect, near: 0.1, far: 10 });

test('WP04P1: our mesh at the level of the page\'s own, drawn in order with no depth test, in the normals\' colours', async () => {
  // the page sent 4·4^3 triangles: our level 3, drawn as our WP04P1 draws it (the last face drawn shows)
  const r = await compared('ada', 'WP04P1', 40, { numbers: { geometry: { triangles: 256 } } });
  const expected = renderMeshInOrder({ camera: camera(1) }, sphereMesh(3), 40, 40);
  assert.deepEqual(referenceOf('ada', 'WP04P1').data, new Uint8Array(toRGBA8(expected).buffer));
  assert.ok(Number.isFinite(r.rmse) && r.rmse > 0);
  assert.deepEqual(r.referenceState.level, 3);
  assert.match(r.referenceState.levelFrom, /the level of the page's own mesh/);
  assert.equal(r.referenceState.light, null);
  // not the exact sphere: the depth test is what the slides' first step leaves out
  assert.notDeepEqual(referenceOf('ada', 'WP04P1').data, new Uint8Array(toRGBA8(renderReference({ shading: 'normals', camera: camera(1) }, 40, 40)).buffer));
});

test('WP04P2: the exact sphere in the normals\' colours, no level', async () => {
  const r = await compared('ada', 'WP04P2', 40, { numbers: { geometry: { triangles: 256 } } });
  const expected = renderReference({ shading: 'normals', camera: camera(1) }, 40, 40);
  assert.deepEqual(referenceOf('ada', 'WP04P2').data, new Uint8Array(toRGBA8(expected).buffer));
  assert.deepEqual(r.referenceState.level, null, 'no mesh, no level');
});

test('WP04P4: the slide\'s Phong reflection model with its defaults, lit from the fitted light', async () => {
  const toward = [0.6, 0, 0.8]; // the fitted direction toward the light, in view space
  const r = await compared('bob', 'WP04P4', 32, { numbers: { fit: { light: toward } } });
  const expected = renderReference({
    shading: 'gouraud', model: 'phong', camera: camera(1), cullFace: true, frontFace: 'ccw',
    light: { position: [-0.6, 0, -0.8, 0], Le: 1, La: 0.2 }, material: { kd: 0.8, ka: 0.8, ks: 0.5, s: 40 },
  }, 32, 32);
  assert.deepEqual(referenceOf('bob', 'WP04P4').data, new Uint8Array(toRGBA8(expected).buffer));
  assert.deepEqual(r.referenceState.light, { kind: 'directional', xyz: [-0.6, 0, -0.8] });
  // a highlight where the slide puts it: the brightest pixel is not the diffuse peak alone
  assert.ok(Math.max(...referenceOf('bob', 'WP04P4').data.filter((_, k) => k % 4 === 0)) > 0.8 * 255);
});

test('a second part asking the same query gets the same comparison and the same picture', async () => {
  const first = await compared('ada', 'WP04P1', 16);
  const second = await compared('bob', 'WP04P1', 16);
  const withoutFiles = ({ images, steps: _steps, ...rest }) => ({ ...rest, images: Object.keys(images) });
  assert.deepEqual(withoutFiles(second), withoutFiles(first), 'the same comparison, notes and reference state');
  assert.deepEqual(readFileSync(path.join(dir, 'bob', 'WP04P1-reference.png')), readFileSync(path.join(dir, 'ada', 'WP04P1-reference.png')));
  assert.notDeepEqual(referenceOf('ada', 'WP04P1').data, (await compared('cy', 'WP04P1', 24), referenceOf('cy', 'WP04P1').data));
});

test("the time our reference took is a step of the part's, drawn, recalled or not drawn", async () => {
  for (const [name, size] of [['ada', 16], ['bob', 16], ['cy', 4000]]) {
    const result = await compared(name, 'WP04P1', size);
    assert.deepEqual(Object.keys(result.steps), [REFERENCE_STEP], name);
    assert.ok(result.steps[REFERENCE_STEP] >= 0, name);
  }
});

test('WP04P3 at the judged canvas\'s aspect: Gouraud\'s diffuse light, no ambient, no highlight', async () => {
  await compared('ada', 'WP04P3', 40, { height: 30, numbers: { fit: { light: [0, 0, 1] } } });
  const expected = renderReference({ shading: 'gouraud', model: 'phong', camera: camera(40 / 30), cullFace: true,
    light: { position: [0, 0, -1, 0], Le: 1 }, material: { kd: 0.8 } }, 40, 30);
  assert.deepEqual(referenceOf('ada', 'WP04P3').data, new Uint8Array(toRGBA8(expected).buffer));
});

test('a canvas our page cannot draw at is not compared, and the note says why', async () => {
  const r = await compared('ada', 'WP04P3', 4000, { height: 10 });
  assert.equal(r.rmse, undefined);
  assert.match(r.notes.join('\n'), /our WP04P3 draws 2048×16 for this canvas, not 4000×10: not compared/);
  assert.deepEqual(Object.keys(r.images), []);
  // WP04P1 and WP04P2 have square canvases only
  assert.match((await compared('bob', 'WP04P2', 40, { height: 30 })).notes.join('\n'), /our WP04P2 draws 40×40 for this canvas, not 40×30/);
});
