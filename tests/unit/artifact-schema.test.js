// An artifact's shape by number (grader/core/artifact-schema.js): one of each older shape is read
// in today's shape (the rubric's must in older names, in gatheredWith, read as audit ids), today's is left as it is, a newer one is refused with a message, and what
// writeArtifact writes carries today's number.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ARTIFACT_SCHEMA, currentFacts } from '../../grader/core/artifact-schema.js';
import { readArtifact, writeArtifact } from '../../grader/node/run/artifacts.js';
import { rolesInWords } from '../../grader/core/computed/roles.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { staleKeys } from '../../grader/core/gather/reads.js';

const SHIPPED = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const T = mergeRubric({}).thresholds;
const ROLE = { control: 3, what: 'button "Subdivide"', listens: ['click'], found: 'rounder' };

test('shape 1 (no schema; a role kept as a sentence) is read in today\'s shape, its sentence kept', () => {
  const old = { part: 'WP04P2', roles: { subdivide: 'button "Subdivide": the silhouette got rounder', coarsen: ROLE } };
  const now = currentFacts(old);
  assert.equal(now.schema, ARTIFACT_SCHEMA);
  assert.deepEqual(now.roles, { subdivide: { words: 'button "Subdivide": the silhouette got rounder' }, coarsen: ROLE });
  assert.deepEqual(rolesInWords(now, T), { subdivide: 'button "Subdivide": the silhouette got rounder', coarsen: 'button "Subdivide" (listens: click): the silhouette got rounder' });
  assert.equal(typeof old.roles.subdivide, 'string', 'the facts read are not changed in place');
  assert.deepEqual(currentFacts({ part: 'WP04P1' }), { part: 'WP04P1', schema: ARTIFACT_SCHEMA }, 'a part with no roles');
});

test('shape 2 (the rubric\'s must in older names, as the gathering read it) is read with audit ids, so that today\'s rubric finds nothing to gather again', () => {
  const old = { schema: 2, part: 'WP04P4', gatheredWith: { 'parts.WP04P4.must': ['diffuse', 'highlight', 'sliders', 'sliderEffects'], sliderChange: 0.01 } };
  const now = currentFacts(old);
  assert.deepEqual(now.gatheredWith, { 'parts.WP04P4.must': ['diffuse', 'highlight', 'sliders'], sliderChange: 0.01 });
  assert.deepEqual(staleKeys(now.gatheredWith, mergeRubric({ ...SHIPPED, thresholds: { ...SHIPPED.thresholds, sliderChange: 0.01 } })), []);
  assert.deepEqual(staleKeys(old.gatheredWith, mergeRubric({ ...SHIPPED, thresholds: { ...SHIPPED.thresholds, sliderChange: 0.01 } })), ['parts.WP04P4.must'], 'read as it was written, it would be');
  assert.deepEqual(currentFacts({ schema: 2, part: 'WP04P4' }), { schema: ARTIFACT_SCHEMA, part: 'WP04P4' }, 'no gatheredWith');
});

test('today\'s shape is left as it is; a newer or a made-up one is refused, with what to do', () => {
  const today = { schema: ARTIFACT_SCHEMA, part: 'WP04P2', roles: { subdivide: ROLE } };
  assert.deepEqual(currentFacts(today), today);
  assert.throws(() => currentFacts({ ...today, schema: ARTIFACT_SCHEMA + 1 }), /written by a newer grader \(schema \d+; this grader reads up to \d+\)/);
  assert.throws(() => currentFacts({ ...today, schema: 'two' }), /schema \("two"\) is not one the grader knows/);
  assert.throws(() => currentFacts({ ...today, schema: 0 }), /not one the grader knows/);
});

test('writeArtifact writes today\'s schema first; readArtifact reads an older file in today\'s shape', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'schema-'));
  const img = { width: 1, height: 1, data: new Uint8Array([1, 2, 3, 255]) };
  writeArtifact(dir, { facts: { part: 'WP04P2', roles: { subdivide: ROLE } }, images: { first: img } });
  const text = readFileSync(path.join(dir, 'facts.json'), 'utf8');
  assert.equal(Object.keys(JSON.parse(text))[0], 'schema');
  assert.equal(JSON.parse(text).schema, ARTIFACT_SCHEMA);
  const back = readArtifact(dir);
  assert.deepEqual(back.facts, { schema: ARTIFACT_SCHEMA, part: 'WP04P2', roles: { subdivide: ROLE } });
  assert.deepEqual([...back.images.first.data], [1, 2, 3, 255]);
});
