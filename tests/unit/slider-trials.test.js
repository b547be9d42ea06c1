// The slider trials read against the picture just before each (gather/sliders.js), on the recorded
// artifact of a fixture page (sune P4) whose material starts where its script set it, not where its
// sliders show: kd put back after its trial turns the sphere white. The sliders' audit says so, and
// a trial that showed nothing from a washed-out picture is one whose effect cannot be seen, not a
// slider that does nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { readArtifact } from '../../grader/node/run/artifacts.js';
import { judged } from '../../grader/core/grade-part.js';
import { restoredElsewhere, auditSliders } from '../../grader/core/audits/units/sliders.js';
import { checkList } from '../../grader/core/verdict.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const thresholds = rubric.thresholds;
const artifact = readArtifact(fileURLToPath(new URL('../fixtures/artifacts/sune/WP04P4', import.meta.url)));

test('each slider trial is read against the picture before it: kd put back to its slider\'s value left the page in another state', () => {
  const [kd, ks] = artifact.facts.sliders;
  assert.equal(kd.role, 'kd');
  assert.ok(restoredElsewhere(kd, thresholds), 'the picture after kd was put back is not the one before its trial');
  assert.ok(!restoredElsewhere(ks, thresholds));
  assert.ok(ks.before && ks.before !== kd.before, 'ks has its own picture before its trial');
  // what ks at 0 changed, against the washed-out picture before it (not against the judged one)
  assert.ok(ks.changed.input <= thresholds.sliderChange);
});

test('the audit names the slider put back, and says that ks and s cannot be seen acting on a washed-out picture', () => {
  const sliders = judged(artifact, rubric, {}).checks.filter((c) => c.id === 'sliders').map((c) => c.reason);
  assert.ok(sliders.some((t) => /^note: putting the kd slider back to 1 \(its value on the page\) changed the picture/.test(t)), sliders.join('\n'));
  assert.ok(sliders.some((t) => /\(ks, s\) showed no change from a picture that clips to white over \d+% of the sphere/.test(t)), sliders.join('\n'));
  assert.ok(!sliders.some((t) => /no slider found for ks|change nothing/.test(t)), sliders.join('\n'));
});

test('several sliders put back elsewhere are named together, each with the value it was put back to', () => {
  const { checks, sayAs } = checkList(rubric);
  const trial = (role, to, moved) => ({ control: 0, role, levelSlider: false, target: 0, how: 'input', changed: { input: 0.5, change: null }, image: 'x',
    restored: { to, changed: moved ? 0.5 : 0 } });
  const facts = { sliders: [trial('kd', '0.5', true), trial('ks', '0.6', false), trial('La', '0.2', true)], slidersFound: 3 };
  auditSliders({ facts, images: {}, thresholds, must: new Set(['sliders']), sayAs, rubric, part: 'WP04P4' }, null, null);
  const notes = checks.filter((c) => c.id === 'sliders').map((c) => c.reason);
  assert.ok(notes.includes('note: putting 2 sliders back to their values on the page (kd to 0.5, La to 0.2) changed the picture: the page starts with other values than its sliders show (each slider was tried from the picture just before it)'), notes.join('\n'));
});

