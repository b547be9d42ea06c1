// A rubric key the gathering reads (a slider's change bound, how many controls to try) decides what
// is gathered, so --audit-only under another value cannot judge what was never gathered: each
// artifact keeps the keys its gathering read (facts.gatheredWith, grader/core/gather/reads.js), and
// --audit-only names the parts to gather again. Held on the recorded fixture class: dee's and
// carla's WP04P4 have sliders that act only on the change event.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { auditDirs } from '../../grader/node/run/audit-pool.js';
import { regatherLines } from '../../grader/node/run/audit-only.js';
import { recording, staleKeys } from '../../grader/core/gather/reads.js';
import { memo } from '../../grader/core/computed/memo.js';
import { rolesInWords } from '../../grader/core/computed/roles.js';
import { currentFacts } from '../../grader/core/artifact-schema.js';
import { mergeRubric } from '../../grader/core/rubric.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.join(here, '../..');
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
const shipped = read(path.join(root, 'grader/core/rubric.json'));
const rubric = mergeRubric(shipped, read(path.join(here, '../fixtures/test-rubric.json')));
const changed = mergeRubric(rubric, { thresholds: { sliderChange: rubric.thresholds.sliderChange * 2 } });
const PARTS = [['dee', 'WP04P4'], ['carla', 'WP04P4'], ['ada', 'WP04P1']];
const dirOf = (name, part) => path.join(RECORDED, name, part);

test('the recorder notes each key read once, with its value; staleKeys names the keys a rubric changes', () => {
  const into = {};
  const T = recording({ a: 1, b: [2, 3], c: 4 }, into);
  assert.equal(T.a + T.a + T.b[1], 5);
  assert.equal(T.missing, undefined);
  assert.deepEqual(into, { a: 1, b: [2, 3] });
  const P = recording({ orbit: 'orbit|spin' }, into, 'controls.');
  assert.equal(P.orbit, 'orbit|spin');
  assert.deepEqual(staleKeys({ ...into, 'controls.orbit': 'orbit|spin' }, { thresholds: { a: 1, b: [2, 3] }, controls: { orbit: 'orbit|spin' } }), []);
  assert.deepEqual(staleKeys({ ...into, 'controls.orbit': 'orbit' }, { thresholds: { a: 2, b: [2, 3] }, controls: { orbit: 'orbit|spin' } }), ['a', 'controls.orbit']);
  assert.deepEqual(staleKeys({ 'parts.WP04P1.must': ['sphere'] }, { thresholds: {}, parts: { WP04P1: { must: ['sphere', 'perspective'] } } }), ['parts.WP04P1.must']);
  assert.equal(staleKeys(undefined, rubric), null); // gathered before artifacts kept what they read: not known
});

test("a fit made in gathering (thresholds read through the recorder) is the audit's (thresholds as they are): made once, its reads recorded", () => {
  const thresholds = { k: 2, unread: 3 }, into = {};
  let made = 0;
  const fit = memo((img, t) => (made++, img.v * t.k));
  const img = { v: 5 };
  assert.equal(fit(img, recording(thresholds, into)), 10); // gathering
  assert.deepEqual(into, { k: 2 });
  assert.equal(fit(img, thresholds), 10); // the audit, later in the same worker
  assert.equal(made, 1, 'the audit made the fit again');
  assert.equal(fit({ v: 5 }, thresholds), 10); // another picture: its own fit
  assert.equal(made, 2);
});

test('--audit-only under a changed sliderChange names the parts whose gathering read it, and no others', async () => {
  const dee = read(path.join(dirOf('dee', 'WP04P4'), 'facts.json'));
  assert.ok('sliderChange' in dee.gatheredWith, 'the gathering of a part with sliders reads sliderChange');
  // a key only the audits read, and one the gathering of these parts never did: nothing to gather again
  const auditOnlyKey = Object.keys(rubric.thresholds).find((k) => typeof rubric.thresholds[k] === 'number' &&
    PARTS.every(([n, p]) => !(k in read(path.join(dirOf(n, p), 'facts.json')).gatheredWith)));
  assert.ok(auditOnlyKey, 'some threshold is read by the audits alone');
  const judged = await auditDirs(PARTS.map(([n, p]) => dirOf(n, p)), changed);
  assert.deepEqual(PARTS.map(([n, p]) => judged.get(dirOf(n, p)).stale), [['sliderChange'], ['sliderChange'], []]);
  const same = await auditDirs(PARTS.map(([n, p]) => dirOf(n, p)), mergeRubric(rubric, { thresholds: { [auditOnlyKey]: rubric.thresholds[auditOnlyKey] * 2 } }));
  assert.deepEqual(PARTS.map(([n, p]) => same.get(dirOf(n, p)).stale), [[], [], []]);
  assert.deepEqual(regatherLines([{ name: 'dee', part: 'WP04P4', keys: ['sliderChange'] }, { name: 'carla', part: 'WP04P4', keys: ['sliderChange'] }]),
    ['re-gather these 2 parts for `sliderChange` (their gathering read it, under another value): dee WP04P4, carla WP04P4']);
});

test('npm run grade -- --audit-only OUT --rubric names them on its output and in their results', () => {
  const out = mkdtempSync(path.join(os.tmpdir(), 'regather-'));
  try {
    for (const [name, part] of PARTS) {
      cpSync(dirOf(name, part), path.join(out, 'artifacts', name, part), { recursive: true });
      mkdirSync(path.join(out, 'parts', name), { recursive: true });
      writeFileSync(path.join(out, 'parts', name, `${part}.json`), JSON.stringify({ name, part, status: 'ok', verdict: 'pass', reasons: [], errors: [], blocked: [], notes: [] }));
    }
    const file = path.join(out, 'changed.json');
    writeFileSync(file, JSON.stringify({ ...read(path.join(here, '../fixtures/test-rubric.json')), thresholds: { sliderChange: changed.thresholds.sliderChange } }));
    const run = spawnSync(process.execPath, [path.join(root, 'grader/node/cli/grade.js'), '--audit-only', out, '--rubric', file], { encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    assert.match(run.stdout, /re-gather these 2 parts for `sliderChange` \(their gathering read it, under another value\): carla WP04P4, dee WP04P4 \(--regather-changed does it\)/);
    assert.deepEqual(read(path.join(out, 'parts', 'dee', 'WP04P4.json')).regather, ['sliderChange']);
    assert.equal(read(path.join(out, 'parts', 'ada', 'WP04P1.json')).regather, undefined);
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
});

test("the audit decides a slider's event from the picture changes the gathering recorded, under the rubric it is given", async () => {
  const carla = dirOf('carla', 'WP04P4');
  const facts = read(path.join(carla, 'facts.json'));
  assert.ok(facts.sliders.every((x) => x.changed && x.changed.input <= rubric.thresholds.sliderChange), 'carla\'s sliders show nothing on input');
  const said = async (r) => (await auditDirs([carla], r)).get(carla).checks.filter((c) => c.id === 'input-event' || c.id === 'sliders').map((c) => c.reason).join(' | ');
  assert.match(await said(rubric), /update the picture only on the change event/);
  // a change bound above every change recorded: no slider changes the picture (and the part is named to gather again)
  const most = Math.max(...facts.sliders.map((x) => x.changed.change ?? 0));
  const strict = mergeRubric(rubric, { thresholds: { sliderChange: most + 0.01 } });
  assert.match(await said(strict), /no slider changes the material or light/);
  assert.deepEqual((await auditDirs([carla], strict)).get(carla).stale, ['sliderChange']);
});

test('the roles are kept as facts and put in words under the rubric given: a slider\'s event too', () => {
  const facts = read(path.join(dirOf('carla', 'WP04P4'), 'facts.json'));
  const sliders = Object.entries(facts.roles).filter(([, r]) => r.found === 'shading');
  assert.ok(sliders.length >= 3, JSON.stringify(facts.roles));
  for (const [role, r] of sliders) {
    assert.equal(typeof r.what, 'string');
    assert.match(rolesInWords(facts, rubric.thresholds)[role], /: changes the shading on change$/);
    const most = Math.max(...facts.sliders.map((x) => x.changed.change ?? 0));
    assert.match(rolesInWords(facts, { ...rubric.thresholds, sliderChange: most + 0.01 })[role], /changed less than this rubric's sliderChange asks$/);
  }
  const ada = read(path.join(dirOf('ada', 'WP04P1'), 'facts.json'));
  assert.match(rolesInWords(ada, rubric.thresholds).subdivide, /\(listens: click\): the silhouette got rounder$/);
  // an artifact from before roles were kept as facts, read as readArtifact reads it: its sentences as they were
  assert.deepEqual(rolesInWords(currentFacts({ roles: { orbit: 'button "Spin": the picture stopped moving' } }), rubric.thresholds), { orbit: 'button "Spin": the picture stopped moving' });
});

