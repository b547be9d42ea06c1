// The grader's own steps graded against themselves: our site, graded as a hand-in (the fixture
// hand-ins own, in WebGL, and own-gpu, in WebGPU: tests/fixtures/build.js), is within 1% of our
// reference in every part (the mismatch the report and the feedback pages show beside a student's
// picture). WP04P1 draws with neither the depth test nor culling, as the slides' step does: its
// reference is its mesh drawn in order (common/mesh-render.js), not the exact sphere.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { auditPart } from '../../grader/core/audit.js';
import { referenceQuery, referencePicture, referenceStateOf, meshLevel } from '../../grader/core/reference-state.js';
import { compareImages } from '../../grader/class/compare-images.js';
import { readArtifact } from '../../grader/node/run/artifacts.js';
import { RECORDED } from '../fixtures/record.js';
import { PARTS } from '../../grader/core/part-names.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
/** The most of our own picture that may differ from our reference: the bound. */
const MOST_MISMATCH = 0.01;

for (const who of ['own', 'own-gpu']) {
  test(`${who}: each part within ${100 * MOST_MISMATCH}% of our reference`, () => {
    for (const part of PARTS) {
      const artifact = readArtifact(path.join(RECORDED, who, part));
      const judged = auditPart(artifact, rubric);
      const img = artifact.images[judged.shown.judged];
      const query = referenceQuery(img, judged.numbers, rubric.thresholds, {}, part);
      const drawn = referencePicture(part, query, img);
      assert.ok(drawn.img, `${who} ${part}: ${drawn.why}`);
      const { mismatch } = compareImages(drawn.img, img);
      assert.ok(mismatch <= MOST_MISMATCH, `${who} ${part}: ${(100 * mismatch).toFixed(2)}% of the pixels differ from our reference (${query})`);
    }
  });
}

test('WP04P1\'s reference is drawn at the level of the page\'s own mesh, and says so', () => {
  assert.deepEqual(meshLevel({ geometry: { triangles: 4 * 4 ** 5 } }), { level: 5 });
  assert.deepEqual(meshLevel({ geometry: { triangles: 1000 } }), {});
  assert.deepEqual(meshLevel({}), {});
  const img = { width: 64, height: 64 };
  const query = referenceQuery(img, { geometry: { triangles: 256 } }, rubric.thresholds, {}, 'WP04P1');
  assert.equal(query.get('level'), '3');
  assert.equal(referenceQuery(img, { geometry: { triangles: 256 } }, rubric.thresholds, {}, 'WP04P2').get('level'), null, 'the exact sphere needs no level');
  const drawn = referencePicture('WP04P1', query, img);
  assert.equal(drawn.scene.level, 3);
  assert.equal(referenceStateOf(query, drawn.scene).level, 3);
  assert.equal(referenceStateOf(query, referencePicture('WP04P2', query, img).scene).level, null);
});
