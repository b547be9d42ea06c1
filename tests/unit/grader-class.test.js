// Our fixture class, judged from its recorded artifacts (tests/fixtures/artifacts/, made by
// tests/fixtures/record.js): the audits give every labelled part the verdict a teacher gives, with
// the reason, in seconds and with no browser. grader.spec.js gathers a few of these hand-ins live
// and holds them to the same artifacts, so what is recorded here is what the grader sees.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { readArtifact } from '../../grader/node/artifacts.js';
import { judged } from '../../grader/core/grade-part.js';
import { verdictOf, reasonsOf } from '../../grader/core/verdict.js';
import { mergeRubric } from '../../grader/core/rubric.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
const shipped = read(path.join(here, '../../grader/core/rubric.json'));
const rubric = mergeRubric(shipped, read(path.join(here, '../fixtures/test-rubric.json')));
const labels = read(path.join(RECORDED, 'labels.json'));
const results = read(path.join(RECORDED, 'results.json'));

/** A recorded part judged under `r`: { verdict, reasons, api }, as report.json gives them. */
function grade(name, part, r = rubric) {
  const dir = path.join(RECORDED, name, part);
  if (!existsSync(path.join(dir, 'facts.json'))) return results[name] && results[name][part];
  const artifact = readArtifact(dir);
  const j = judged(artifact, r);
  const pageErrors = (artifact.facts.errors || []).filter((e) => /page error/.test(e));
  return { verdict: verdictOf(j.checks, j.fail), reasons: reasonsOf({ fail: j.fail, checks: j.checks, pageErrors }), api: j.api };
}

const labelled = Object.entries(labels).flatMap(([name, parts]) => Object.entries(parts).map(([part, label]) => ({ name, part, label })));

test('the recorded class is whole: every labelled part has an artifact or a result', () => {
  assert.ok(labelled.length >= 100, `${labelled.length} labelled parts`);
  const lost = labelled.filter(({ name, part }) => !grade(name, part)).map(({ name, part }) => `${name} ${part}`);
  assert.deepEqual(lost, []);
});

test('every labelled part of the fixture class gets the verdict a teacher gives, with the reason, and says its API', () => {
  const disagree = [];
  for (const { name, part, label } of labelled) {
    const got = grade(name, part);
    if (!got) continue;
    const reasonOk = !label.reason || got.reasons.some((r) => new RegExp(label.reason).test(r));
    if (got.verdict !== label.verdict || !reasonOk || got.api !== label.api) {
      disagree.push(`${name} ${part}: labelled ${label.verdict} (${label.because}; ${label.api}), graded ${got.verdict} (${got.api}): ${got.reasons.join(' | ')}`);
    }
    if (label.verdict === 'fail') assert.notEqual(got.verdict, 'pass', `${name} ${part}: a broken part passes`);
  }
  assert.deepEqual(disagree, []);
});

test('a rubric with mistakeVerdict "fail" fails the parts that draw but miss a point; broken parts fail either way', () => {
  // cy: one mistake a part (P1 colour = p, P2 no depth test, P3 no orbit button, P4 no highlight, P5 Gouraud)
  const strict = mergeRubric(rubric, { mistakeVerdict: 'fail' });
  const parts = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];
  assert.deepEqual(parts.map((p) => grade('cy', p, strict).verdict), ['fail', 'fail', 'review', 'fail', 'fail']);
  assert.deepEqual(parts.map((p) => grade('cy', p).verdict), ['review', 'review', 'review', 'review', 'review']);
  assert.deepEqual(['WP04P1', 'WP04P2', 'WP04P5'].map((p) => grade('eve', p).verdict), ['fail', 'fail', 'fail']);
});

test('a threshold changed in the rubric changes the verdicts it should, and only by judging again', () => {
  // the sphere's roundness bound made impossibly strict: every part that drew a sphere is no longer round
  const strict = mergeRubric(rubric, { thresholds: { roundness: 0.0001 } });
  const ada = grade('ada', 'WP04P1', strict);
  assert.equal(ada.verdict, 'review');
  assert.ok(ada.reasons.some((r) => /not a round closed sphere/.test(r)), ada.reasons.join(' | '));
  assert.equal(grade('ada', 'WP04P1').verdict, 'pass');
});
