// The values a level slider or number input is stepped through (grader/core/gather/level.js): from
// its least up, as far as the page's max or the rubric's count of steps allows, never a top the
// grader guesses.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { levelValues } from '../../grader/core/gather/level.js';

const { maxSubdivisions } = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;

test('a level slider is stepped from its min to its max, at most the rubric\'s maxSubdivisions steps', () => {
  assert.deepEqual(levelValues({ min: '0', max: '4' }, maxSubdivisions), [0, 1, 2, 3, 4]);
  assert.deepEqual(levelValues({ min: '2', max: '20' }, maxSubdivisions), Array.from({ length: maxSubdivisions + 1 }, (_, k) => 2 + k));
  // the trial of a slider's effect: its least, then one up
  assert.deepEqual(levelValues({ min: '1', max: '6' }, 1), [1, 2]);
});

test('without a max the count of steps is the only bound: no top is guessed', () => {
  // (min 0: the same values a guessed top of 8 gave; min 3: three more)
  assert.deepEqual(levelValues({ min: '', max: '' }, 8), [0, 1, 2, 3, 4, 5, 6, 7, 8]);
  assert.deepEqual(levelValues({ min: '3', max: '' }, 8), [3, 4, 5, 6, 7, 8, 9, 10, 11]);
  assert.deepEqual(levelValues({ min: '1' }, 1), [1, 2]);
});

test('a slider that cannot move (its max at its min) gives one value: it cannot be a level control', () => {
  assert.deepEqual(levelValues({ min: '5', max: '5' }, maxSubdivisions), [5]);
});
