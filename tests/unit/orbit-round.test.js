// The orbit looked along no farther than once round where no view is lit (gather/orbit.js), on the
// recorded artifact of a fixture page (tyra P3) whose lit side always faces away from its camera:
// its view matrix says when the camera has gone all the way round, well before orbitSamples positions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { readArtifact } from '../../grader/node/run/artifacts.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const { facts } = readArtifact(fileURLToPath(new URL('../fixtures/artifacts/tyra/WP04P3', import.meta.url)));

test('no lit view along the orbit: sampled once round, not orbitSamples positions', () => {
  const sampled = facts.actions.map((a) => /^sampled the orbit at (\d+) positions .*\(0 lit; the camera went all the way round\)$/.exec(a)).find(Boolean);
  assert.ok(sampled, facts.actions.join('\n'));
  assert.ok(Number(sampled[1]) < rubric.thresholds.orbitSamples, sampled[0]);
  assert.equal(facts.views.filter((v) => v.orbiting).length, 0);
});
