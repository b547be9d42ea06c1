// Our fixture class, judged from its recorded artifacts (tests/fixtures/artifacts/, made by
// tests/fixtures/record.js): the audits give every labelled part the verdict a teacher gives, with
// the reason, in seconds and with no browser. grader.spec.js gathers a few of these hand-ins live
// and holds them to the same artifacts, so what is recorded here is what the grader sees.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { auditDirs } from '../../grader/node/run/audit-pool.js';
import { verdictOf, reasonsOf } from '../../grader/core/verdict.js';
import { mergeRubric } from '../../grader/core/rubric.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
const shipped = read(path.join(here, '../../grader/core/rubric.json'));
const rubric = mergeRubric(shipped, read(path.join(here, '../fixtures/test-rubric.json')));
const labels = read(path.join(RECORDED, 'labels.json'));
const results = read(path.join(RECORDED, 'results.json'));

const labelled = Object.entries(labels).flatMap(([name, parts]) => Object.entries(parts).map(([part, label]) => ({ name, part, label })));
const dirOf = (name, part) => path.join(RECORDED, name, part);
const recorded = labelled.map(({ name, part }) => dirOf(name, part)).filter((d) => existsSync(path.join(d, 'facts.json')));
// the class judged once under the test rubric (in one process a core: audit-pool.js), and again under others where a test asks;
// strictly: an audit unit that reads a fact it does not name fails it (audits/strict.js, tests/unit/audit-list.test.js)
const audits = new Map();
async function auditAll(r = rubric, dirs = recorded) {
  if (!audits.has(r)) audits.set(r, await auditDirs(dirs, r, { strict: true }));
  return audits.get(r);
}

/** A recorded part judged under `r`: { verdict, reasons, api }, as report.json gives them. */
async function grade(name, part, r = rubric) {
  const dir = dirOf(name, part);
  if (!existsSync(path.join(dir, 'facts.json'))) return results[name] && results[name][part];
  const j = (await auditAll(r, r === rubric ? recorded : [dir])).get(dir) || (await auditDirs([dir], r)).get(dir);
  const pageErrors = j.errors.filter((e) => /page error/.test(e));
  return { verdict: verdictOf(j.checks, j.fail), reasons: reasonsOf({ fail: j.fail, checks: j.checks, pageErrors }), api: j.api };
}

test('the recorded class is whole: every labelled part has an artifact or a result', async () => {
  assert.ok(labelled.length >= 100, `${labelled.length} labelled parts`);
  const lost = [];
  for (const { name, part } of labelled) if (!await grade(name, part)) lost.push(`${name} ${part}`);
  assert.deepEqual(lost, []);
});

test('every labelled part of the fixture class gets the verdict a teacher gives, with the reason, and says its API', async () => {
  const disagree = [];
  for (const { name, part, label } of labelled) {
    const got = await grade(name, part);
    if (!got) continue;
    const reasonOk = !label.reason || got.reasons.some((r) => new RegExp(label.reason).test(r));
    if (got.verdict !== label.verdict || !reasonOk || got.api !== label.api) {
      disagree.push(`${name} ${part}: labelled ${label.verdict} (${label.because}; ${label.api}), graded ${got.verdict} (${got.api}): ${got.reasons.join(' | ')}`);
    }
    if (label.verdict === 'fail') assert.notEqual(got.verdict, 'pass', `${name} ${part}: a broken part passes`);
  }
  assert.deepEqual(disagree, []);
});

test('a rubric with mistakeVerdict "fail" fails the parts that draw but miss a point; broken parts fail either way', async () => {
  // cy: one mistake a part (P1 colour = p, P2 no depth test, P3 no orbit button, P4 no highlight, P5 Gouraud)
  const strict = mergeRubric(rubric, { mistakeVerdict: 'fail' });
  const parts = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];
  const verdicts = async (name, ps, r) => Promise.all(ps.map(async (p) => (await grade(name, p, r)).verdict));
  await auditAll(strict, parts.map((p) => dirOf('cy', p)));
  assert.deepEqual(await verdicts('cy', parts, strict), ['fail', 'fail', 'review', 'fail', 'fail']);
  assert.deepEqual(await verdicts('cy', parts), ['review', 'review', 'review', 'review', 'review']);
  assert.deepEqual(await verdicts('eve', ['WP04P1', 'WP04P2', 'WP04P5']), ['fail', 'fail', 'fail']);
});

test('a threshold changed in the rubric changes the verdicts it should, and only by judging again', async () => {
  // the sphere's roundness bound made impossibly strict: every part that drew a sphere is no longer round
  const strict = mergeRubric(rubric, { thresholds: { roundness: 0.0001 } });
  const ada = await grade('ada', 'WP04P1', strict);
  assert.equal(ada.verdict, 'review');
  assert.ok(ada.reasons.some((r) => /not a round closed sphere/.test(r)), ada.reasons.join(' | '));
  assert.equal((await grade('ada', 'WP04P1')).verdict, 'pass');
});
