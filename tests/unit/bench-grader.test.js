// The grader benchmark's numbers (tools/bench-grader/stats.js) from a built report.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { quantile, gradingStats, statsLines, medianRun } from '../../tools/bench-grader/stats.js';
import { NOT_GRADED } from '../../grader/core/verdict.js';

test('seconds a part: median, p90 and slowest by nearest rank; missing parts not counted; parts past the bound named', () => {
  assert.equal(quantile([], 0.5), null);
  assert.equal(quantile([3, 1, 2], 0.5), 2);
  assert.equal(quantile([1, 2, 3, 4, 5, 6, 7, 8, 9, 10], 0.9), 9);
  assert.equal(quantile([1, 2, 3, 4, 5, 6, 7, 8, 9, 10], 1), 10);
  const part = (name, p, seconds, verdict = 'pass', status = 'graded') => ({ name, part: p, seconds, verdict, status });
  const report = {
    submissions: [
      { parts: [part('a', 'WP04P1', 2), part('a', 'WP04P2', 4), { name: 'a', part: 'WP04P3', verdict: 'fail', status: 'missing' }] },
      { parts: [part('b', 'WP04P1', 6), part('b', 'WP04P2', 91, NOT_GRADED, 'too slow')] },
    ],
    labels: { rows: [
      { label: 'correct', want: 'pass', verdict: 'pass', agree: true }, { label: 'partial', want: 'review', verdict: 'pass', agree: false },
      { label: 'correct', want: 'pass', verdict: NOT_GRADED, agree: false }, { label: 'broken', want: 'fail', verdict: 'fail', agree: true },
    ] },
  };
  const st = gradingStats(report);
  assert.deepEqual([st.parts, st.median, st.p90, st.max], [4, 4, 91, 91]);
  assert.deepEqual(st.slowest.map((s) => `${s.name} ${s.part}`), ['b WP04P2', 'b WP04P1', 'a WP04P2']);
  assert.deepEqual(st.notGraded, ['b WP04P2']);
  assert.deepEqual(st.agreement, { exact: 2, of: 4, correctPassed: 1, correct: 2, partialPassed: 1, brokenPassed: 0 });
  const lines = statsLines(st, 100);
  assert.match(lines[0], /^4 parts in 100\.0 s: a part median 4\.0 s, p90 91\.0 s, slowest 91\.0 s/);
  assert.equal(lines[1], 'past the time bound: b WP04P2');
  assert.equal(lines[2], 'labels: 2 of 4 exact, correct parts passed 1 of 2, partial parts passed 1, broken parts passed 0');
});

test('where the time went: each step\'s seconds added up over the parts, most first, the most named in a line', () => {
  const part = (seconds, steps) => ({ name: 'a', part: 'WP04P1', seconds, verdict: 'pass', status: 'graded', steps });
  const st = gradingStats({ submissions: [{ parts: [
    part(3, { 'waiting for the first frame': 1000, judging: 500, 'sampling the orbit': 1500 }),
    part(2, { 'sampling the orbit': 1000, judging: 1000 }),
    { name: 'a', part: 'WP04P3', verdict: 'fail', status: 'missing' },
  ] }] });
  assert.deepEqual(st.steps, [{ step: 'sampling the orbit', seconds: 2.5 }, { step: 'judging', seconds: 1.5 }, { step: 'waiting for the first frame', seconds: 1 }]);
  assert.equal(statsLines(st, 10)[2], 'where the parts\' 5.0 s went: sampling the orbit 2.5 s, judging 1.5 s, waiting for the first frame 1.0 s');
});

test('where the time went by page call: each call\'s seconds and count added up over the parts, most seconds first', () => {
  const part = (timing) => ({ name: 'a', part: 'WP04P1', seconds: 3, verdict: 'pass', status: 'graded', timing });
  const st = gradingStats({ submissions: [{ parts: [
    part({ snap: { ms: 500, calls: 8 }, tick: { ms: 900, calls: 10 } }),
    part({ snap: { ms: 1000, calls: 12 }, open: { ms: 600, calls: 1 } }),
    { name: 'a', part: 'WP04P3', verdict: 'fail', status: 'missing', timing: { open: { ms: 5000, calls: 1 } } },
  ] }] });
  assert.deepEqual(st.calls, [{ call: 'snap', calls: 20, seconds: 1.5 }, { call: 'tick', calls: 10, seconds: 0.9 }, { call: 'open', calls: 1, seconds: 0.6 }]);
  assert.equal(statsLines(st, 10)[2], 'by page call: snap 1.5 s in 20, tick 0.9 s in 10, open 0.6 s in 1');
});

test('runs of the same grading: the median run\'s numbers (the lower middle of an even count), every run\'s wall time in the order run', () => {
  const run = (wall) => ({ wall, st: { tag: wall } });
  assert.deepEqual(medianRun([run(70), run(66), run(81)]), { wall: 70, st: { tag: 70 }, walls: [70, 66, 81] });
  assert.deepEqual(medianRun([run(70), run(66)]), { wall: 66, st: { tag: 66 }, walls: [70, 66] });
  assert.deepEqual(medianRun([run(5)]), { wall: 5, st: { tag: 5 }, walls: [5] });
});

test('the page\'s own surface: read on how many graded lit parts (P3-P5), and why not on the rest, most parts first', () => {
  const part = (name, p, verdict = 'pass') => ({ name, part: p, seconds: 3, verdict, status: 'graded' });
  const report = { submissions: [
    { parts: [part('a', 'WP04P1'), part('a', 'WP04P3'), part('a', 'WP04P4'), part('a', 'WP04P5', 'fail')] },
    { parts: [part('b', 'WP04P2'), part('b', 'WP04P3'), part('b', 'WP04P4'), { name: 'b', part: 'WP04P5', verdict: 'fail', status: 'missing' }] },
    { parts: [part('c', 'WP04P3')] },
  ] };
  const COVERS = 'the page\'s triangles cover no pixel when drawn again';
  const facts = {
    'a WP04P1': undefined, 'a WP04P3': { width: 64 }, 'a WP04P4': { why: COVERS }, 'a WP04P5': undefined,
    'b WP04P2': undefined, 'b WP04P3': { why: COVERS }, 'b WP04P4': { width: 64 }, 'c WP04P3': { why: 'no separate triangles' },
  };
  const st = gradingStats(report, (p) => facts[`${p.name} ${p.part}`]);
  assert.deepEqual(st.surface, { read: 2, of: 6, why: [{ why: COVERS, parts: 2 }, { why: 'none gathered (fail)', parts: 1 }, { why: 'no separate triangles', parts: 1 }] });
  assert.ok(statsLines(st, 10).includes(`the page's own surface read on 2 of 6 lit parts (P3-P5); not on 4: ${COVERS} (2); none gathered (fail) (1); no separate triangles (1)`),
    statsLines(st, 10).join('\n'));
  const all = gradingStats(report, () => ({ width: 64 }));
  assert.ok(statsLines(all, 10).includes('the page\'s own surface read on 6 of 6 lit parts (P3-P5)'));
  assert.equal(gradingStats(report).surface, null);
});

test('the slider trials: on how many the terms were read on the page\'s own surface, and why the rest on the pictures, most trials first', () => {
  const MOVES = 'the picture moves by itself while a slider is tried';
  const part = (name, sliderTrials) => ({ name, part: 'WP04P4', seconds: 3, verdict: 'pass', status: 'graded', numbers: sliderTrials ? { sliderTrials } : {} });
  const report = { submissions: [
    { parts: [part('a', { read: 5, onSurface: 5, why: {} })] },
    { parts: [part('b', { read: 4, onSurface: 1, why: { [MOVES]: 2, 'no surface': 1 } })] },
    { parts: [part('c', { read: 2, onSurface: 0, why: { [MOVES]: 2 } }), part('c2', null)] },
  ] };
  const st = gradingStats(report);
  assert.deepEqual(st.trials, { read: 6, of: 11, why: [{ why: MOVES, trials: 4 }, { why: 'no surface', trials: 1 }] });
  assert.ok(statsLines(st, 10).includes(`the slider trials (P4) read on the page's own surface: 6 of 11; on the pictures 5: ${MOVES} (4); no surface (1)`), statsLines(st, 10).join('\n'));
  assert.equal(gradingStats({ submissions: [{ parts: [part('d', null)] }] }).trials, null);
});
