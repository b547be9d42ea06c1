// A part that runs past the rubric's wall-clock bound once it has drawn is too slow on this machine:
// "not graded here", counted apart, never fail (the rubric's tooSlowVerdict); a teacher's rubric
// may make it review.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { auditPart } from '../../grader/core/audit.js';
import { applyAudit } from '../../grader/core/part-result.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { NOT_GRADED } from '../../grader/core/verdict.js';
import { readArtifact } from '../../grader/node/run/artifacts.js';
import { RECORDED } from '../fixtures/record.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const artifact = { facts: { part: 'WP04P5', tooSlow: 'sampling the orbit', errors: [] }, images: {} };

test('too slow on this machine: not graded here, with what it was doing', () => {
  const judged = auditPart(artifact, rubric);
  const result = applyAudit({ errors: [] }, judged);
  assert.equal(result.verdict, NOT_GRADED);
  assert.equal(result.status, 'too slow');
  assert.match(result.reasons[0], /^not graded here: too slow on this machine: the rubric's bound of 90 s ran out while sampling the orbit; nothing was judged/);
});

test('a rubric that makes it review', () => {
  const judged = auditPart(artifact, mergeRubric(rubric, { tooSlowVerdict: 'review' }));
  const result = applyAudit({ errors: [] }, judged);
  assert.equal(result.verdict, 'review');
  assert.equal(result.status, 'too slow');
  assert.match(result.reasons[0], /^REVIEW: too slow on this machine/);
});

test('too heavy: the page\'s own work over the gathering passes gatherWork at the same frame on any machine, and is not graded here', async () => {
  const { openSession, TooHeavy } = await import('../../grader/core/gather/session.js');
  const T = rubric.thresholds;
  // a page whose every frame draws 2 million vertices in one draw call
  let vertices = 0, draws = 0;
  const page = { tick: async (ms, frames) => { vertices += 2e6 * (frames + 1); draws += frames + 1; return { vertices, draws }; } };
  const S = openSession(page, { part: 'WP04P5', rubric });
  S.step('climbing the levels');
  const perTick = 11 * (2e6 + T.drawCallWork);
  const ticks = Math.floor(T.gatherWork / perTick);
  for (let k = 0; k < ticks; k++) await S.tick(160, 10);
  const err = await S.tick(160, 10).then(() => null, (e) => e);
  assert.ok(err instanceof TooHeavy, String(err));
  assert.equal(err.doing, 'climbing the levels');
  assert.ok(err.work > T.gatherWork && err.work <= T.gatherWork + perTick);
  const judged = auditPart({ facts: { part: 'WP04P5', tooSlow: err.doing, tooHeavy: err.work, errors: [] }, images: {} }, rubric);
  const result = applyAudit({ errors: [] }, judged);
  assert.equal(result.verdict, NOT_GRADED);
  assert.equal(result.status, 'too heavy');
  assert.match(result.reasons[0], /^not graded here: too heavy to grade: the page's own work over the grading \(1012 million vertices, draw calls at 80 each\) passed the rubric's budget of 1000 million \(gatherWork\) while climbing the levels/);
});

// What a gathering holds when it stops on the work budget while looking all round, taken from a
// recorded fixture part: its first frames, its controls and the mesh it sent then (the orbit's first
// watch reads it); nothing of the views, levels and trials that come later.
const EARLY = ['schema', 'part', 'api', 'canvas', 'actions', 'controls', 'first', 'shown', 'frameDraws', 'geometryAtFirst', 'sources', 'errors', 'blocked', 'notes'];
function stoppedEarly(name, part) {
  const { facts } = readArtifact(path.join(RECORDED, name, part));
  const early = Object.fromEntries(EARLY.filter((k) => k in facts).map((k) => [k, facts[k]]));
  return { facts: { ...early, tooSlow: 'looking all round', tooHeavy: 1044e6 }, images: {} };
}

test('a mistake read from what the page sent before the bound stands: review with it, and the rest said not judged', () => {
  // ronja's P3 appends its sphere to its array every frame (tests/fixtures/handins/ronja)
  const result = applyAudit({ errors: [] }, auditPart(stoppedEarly('ronja', 'WP04P3'), rubric));
  assert.equal(result.verdict, 'review');
  assert.equal(result.status, 'too heavy');
  const asked = result.findings.filter((f) => f.level === 'review');
  assert.deepEqual(asked.map((f) => f.id), ['growth', 'too-slow']);
  assert.match(asked[0].reason, /the page draws more every frame/);
  assert.match(asked[1].reason, /^REVIEW: the rest was not judged: too heavy to grade: the page's own work over the grading \(1044 million vertices.* while looking all round; only what the page sent before was read \(growth\)/);
});

test('nothing wrong in what the page sent before the bound: not graded here, as before', () => {
  const result = applyAudit({ errors: [] }, auditPart(stoppedEarly('anna', 'WP04P3'), rubric));
  assert.equal(result.verdict, NOT_GRADED);
  assert.match(result.reasons[0], /^not graded here: too heavy to grade: .* while looking all round; nothing was judged/);
});

test('the browser failing itself (its renderer crashed) after a mistake on record: review with it; with none: not graded here', () => {
  const crashed = (name) => {
    const a = stoppedEarly(name, 'WP04P3');
    delete a.facts.tooSlow;
    delete a.facts.tooHeavy;
    return { ...a, facts: { ...a.facts, browserFailed: { message: 'Target crashed', doing: 'looking all round' } } };
  };
  const ronja = applyAudit({ errors: [] }, auditPart(crashed('ronja'), rubric));
  assert.equal(ronja.verdict, 'review');
  assert.deepEqual(ronja.findings.filter((f) => f.level === 'review').map((f) => f.id), ['growth', 'too-slow']);
  assert.match(ronja.reasons.join('\n'), /REVIEW: the rest was not judged: the browser failed while looking all round, not the page \("Target crashed"\); only what the page sent before was read \(growth\)/);
  const anna = applyAudit({ errors: [] }, auditPart(crashed('anna'), rubric));
  assert.equal(anna.verdict, NOT_GRADED);
  assert.match(anna.reasons[0], /^not graded here: the browser failed while grading this page, not the page \("Target crashed"\)/);
});

test('the gathering keeps what it gathered when the browser fails itself, and says where', async () => {
  const { gatherPart } = await import('../../grader/core/gather/index.js');
  const page = { state: async () => { throw new Error('page.evaluate: Target crashed'); }, errors: () => [] };
  const { facts } = await gatherPart(page, { part: 'WP04P3', rubric });
  assert.deepEqual(facts.browserFailed, { message: 'page.evaluate: Target crashed', doing: 'waiting for the first frame' });
  // the grader's own trouble is not the browser's: it goes on up
  const broken = { state: async () => { throw new Error('cannot read x of undefined'); }, errors: () => [] };
  await assert.rejects(gatherPart(broken, { part: 'WP04P3', rubric }), /cannot read x/);
});
