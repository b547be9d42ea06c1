// A part that runs past the rubric's wall-clock bound once it has drawn is too slow on this machine:
// "not graded here", counted apart, never fail (the rubric's tooSlowVerdict); a teacher's rubric
// may make it review.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { auditPart } from '../../grader/core/audit.js';
import { applyAudit } from '../../grader/node/part-result.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { NOT_GRADED } from '../../grader/core/verdict.js';

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
