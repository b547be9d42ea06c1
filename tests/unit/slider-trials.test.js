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


test('ks at 0 on a picture clipped to white is not judged: the clipped white is no highlight that stayed', async () => {
  const { renderReference, toRGBA8 } = await import('../../common/exact-render.js');
  const { fullFit } = await import('../../grader/core/computed/views.js');
  const camera = { eye: [0, 0, 3], at: [0, 0, 0], up: [0, 1, 0], fovy: 45, aspect: 1, near: 0.1, far: 10 };
  const picture = (ks, kd, La) => {
    const scene = { shading: 'phong', model: 'phong', camera, cullFace: true, frontFace: 'ccw',
      light: { position: [-1, -1, -1, 0], Le: 1, La }, material: { kd, ka: kd, ks, s: 20 } };
    return { width: 96, height: 96, data: toRGBA8(renderReference(scene, 96, 96)) };
  };
  // the trial of ks from 1 to 0, read as the sliders' audit reads it
  const ksTrial = (kd, La, ksAfter = 0) => {
    const images = { before: picture(1, kd, La), after: picture(ksAfter, kd, La) };
    const { checks, sayAs } = checkList(rubric);
    const trial = { control: 0, role: 'ks', levelSlider: false, target: 0, how: 'input', changed: { input: 0.2, change: null }, image: 'after', before: 'before' };
    auditSliders({ facts: { sliders: [trial], slidersFound: 1 }, images, thresholds, must: new Set(['sliders']), sayAs, rubric, part: 'WP04P4' },
      null, { judgedFit: fullFit(images.before, thresholds) });
    return checks.filter((c) => c.id === 'ks-used');
  };
  // kd = ka = 1 with La = 0.6: two thirds of the sphere white, with ks at 1 and at 0 alike
  const clipped = ksTrial(1, 0.6);
  assert.deepEqual(clipped.map((c) => c.level), ['pass'], clipped.map((c) => c.reason).join('\n'));
  assert.match(clipped[0].reason, /^note: ks at 0 is not judged: the picture clips to white over \d+% of the sphere/);
  // a material that does not clip: ks at 0 took the highlight away, and nothing is said
  assert.deepEqual(ksTrial(0.6, 0.3).map((c) => c.level), []);
  // kd = 1 with no ambient: the diffuse term reaches white at its peak, a sliver above the diffuse
  // fit far toward white but not as high as the highlight was: no highlight left
  assert.deepEqual(ksTrial(1, 0).map((c) => c.level), []);
  // a page whose ks slider changes nothing in the specular term: the highlight stays as it was
  const unused = ksTrial(0.6, 0.3, 1);
  assert.deepEqual(unused.map((c) => c.level), ['review']);
  assert.match(unused[0].reason, /^ks at 0 leaves the highlight as it was \(1\.00\): is ks used in the specular term\?/);
});
