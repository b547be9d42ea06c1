// A part whose page skipped the draws of frames nobody looked at, where that could have shown
// (grader/browser/unseen-frames.js says `unsafe`), is gathered again on a page that draws every
// frame, and that gathering is the one kept: what is gathered never depends on the skipping.
// gatherDrawn (grader/node/run/run-part.js) over openers and a gathering that only record calls.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { gatherDrawn, EVERY_FRAME_STEP } from '../../grader/node/run/run-part.js';

/** gatherDrawn with a first page whose skipping says `unseen`; the calls made, and what it returned. */
async function run(unseen, { everyFrame = true } = {}) {
  const calls = [];
  const driver = (name) => ({ name, unseen: async () => { calls.push(`${name}.unseen`); return unseen; } });
  const opener = (name) => ({
    open: async () => { calls.push(`${name}.open`); return { driver: driver(`${name}'s page`) }; },
    done: async (clean) => { calls.push(`${name}.done(${clean})`); },
  });
  const openers = { student: opener('student'), ...(everyFrame ? { everyFrame: opener('everyFrame') } : {}) };
  const steps = {};
  const out = await gatherDrawn({
    opened: { driver: driver('student\'s page') }, opener: openers.student, openers, steps,
    open: (o) => o.open(),
    gather: async (d) => { calls.push(`gather on ${d.name}`); return { artifact: d.name }; },
  });
  return { calls, steps, graded: out.graded.artifact, opener: out.opener === openers.student ? 'student' : 'everyFrame' };
}

test('skipping that could have shown: the part gathered again with every frame drawn, that gathering kept, its time a step of its own', async () => {
  const r = await run({ skipped: 12, unsafe: 'a run of frames ended with draws skipped and not cleared away' });
  assert.deepEqual(r.calls, ['gather on student\'s page', 'student\'s page.unseen', 'student.done(true)', 'everyFrame.open', 'gather on everyFrame\'s page']);
  assert.equal(r.graded, 'everyFrame\'s page');
  assert.equal(r.opener, 'everyFrame', 'the page open now, to be closed');
  assert.deepEqual(Object.keys(r.steps), [EVERY_FRAME_STEP]);
});

test('skipping that could not show, or none, or no page that draws every frame (Firefox): the one gathering kept', async () => {
  for (const [unseen, options] of [[{ skipped: 12, unsafe: null }, {}], [null, {}], [{ skipped: 3, unsafe: 'x' }, { everyFrame: false }]]) {
    const r = await run(unseen, options);
    assert.equal(r.graded, 'student\'s page');
    assert.equal(r.opener, 'student');
    assert.deepEqual(r.steps, {});
    assert.ok(!r.calls.includes('everyFrame.open'));
  }
});
