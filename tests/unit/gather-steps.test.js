// Where a part's gathering spends its time, by step (gather/session.js's clock): each step said
// (step) or only timed (mark) gets the time until the next, from the first step on; mark(null) ends
// the count. Read by no gatherer: the benchmark adds the steps up.
import { test, mock } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openSession, FIRST_FRAME } from '../../grader/core/gather/session.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));

test('each step and mark gets the time until the next; the first step counts from the session\'s opening', () => {
  mock.timers.enable({ apis: ['Date'], now: 1000 });
  try {
    const steps = {}, said = [];
    const session = openSession({}, { part: 'WP04P4', rubric, steps, progress: (w) => said.push(w) });
    mock.timers.tick(100);
    session.step('sampling the orbit');
    mock.timers.tick(50);
    session.mark('reading the shading');
    mock.timers.tick(30);
    session.step('sampling the orbit');
    mock.timers.tick(20);
    session.mark(null);
    mock.timers.tick(1000);
    assert.deepEqual(steps, { [FIRST_FRAME]: 100, 'sampling the orbit': 70, 'reading the shading': 30 });
    assert.deepEqual(said, ['sampling the orbit', 'sampling the orbit'], 'a mark is said to nobody');
    assert.equal(session.doing, 'sampling the orbit', 'a mark does not rename what runs out of time');
  } finally {
    mock.timers.reset();
  }
});
