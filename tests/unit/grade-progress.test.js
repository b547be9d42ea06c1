// npm run grade's progress as a person reads it (grader/node/cli/progress.js and the Playwright
// reporter progress-reporter.js), on a clock the test moves: the line's words from the counts and
// times (the time left from the parts opened in the browser, none counted for a part not handed
// in), and in a log (not a terminal) a plain line a part with its verdict, never a rewritten line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { clock, timeLeft, progressText, doneText } from '../../grader/node/cli/progress.js';
import ProgressReporter from '../../grader/node/cli/progress-reporter.js';

test('a time reads as a clock: m:ss, and h:mm:ss past the hour', () => {
  assert.deepEqual([0, 7000, 59_600, 205_000, 3_729_000].map(clock), ['0:00', '0:07', '1:00', '3:25', '1:02:09']);
});

test('the time left: the time so far spread over the parts opened, for those still to open', () => {
  assert.equal(timeLeft({ opened: 0, toOpen: 4, elapsedMs: 9000 }), null, 'not known before a part is done');
  assert.equal(timeLeft({ opened: 2, toOpen: 3, elapsedMs: 20_000 }), 30_000);
  assert.equal(timeLeft({ opened: 0, toOpen: 0, elapsedMs: 1000 }), 0, 'nothing left to open: nothing left');
  assert.equal(progressText({ parts: 12, partsAll: 40, handins: 2, handinsAll: 8, elapsedMs: 48_000, leftMs: 112_000 }),
    '12 of 40 parts · 2 of 8 hand-ins · 0:48 so far · about 1:52 left');
  assert.equal(progressText({ parts: 0, partsAll: 5, handins: 0, handinsAll: 1, elapsedMs: 0, leftMs: null }),
    '0 of 5 parts · 0 of 1 hand-ins · 0:00 so far · time left: after the first part');
  assert.equal(doneText({ parts: 40, handinsAll: 8, elapsedMs: 205_000 }), 'graded 40 part(s) of 8 hand-in(s) in 3:25');
});

/** The reporter run over `items` as Playwright would, each test ending 10 s after the one before, on a stream that is a terminal or not. */
function report(items, { isTTY, statuses = {} }) {
  let written = '', t = 0;
  const stream = { isTTY, columns: 200, write: (s) => { written += s; } };
  const reporter = new ProgressReporter({ items, stream, now: () => t });
  const tests = items.map((x) => ({ title: `${x.name} ${x.part}` }));
  reporter.onBegin({}, { allTests: () => tests });
  for (const x of tests) {
    t += 10_000;
    const status = statuses[x.title] || 'passed';
    reporter.onTestEnd(x, { status, ...(status === 'failed' ? { error: { message: 'browser has been closed\nat ...' } } : {}) });
  }
  reporter.onEnd({ status: 'passed' });
  return written;
}

test('not a terminal (CI): a plain line a part, its verdict first, then the counts; a failed test said on a line of its own', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'grade-progress-'));
  try {
    const result = (name, part, r) => {
      const file = path.join(dir, name, `${part}.json`);
      mkdirSync(path.dirname(file), { recursive: true });
      writeFileSync(file, JSON.stringify(r));
      return file;
    };
    const items = [
      { name: 'ada', part: 'WP04P2', page: 'p2.html', resultFile: result('ada', 'WP04P2', { status: 'ok', verdict: 'pass' }) },
      { name: 'bo', part: 'WP04P2', page: null, resultFile: result('bo', 'WP04P2', { status: 'missing', verdict: 'fail' }) },
      { name: 'ada', part: 'WP04P1', page: 'p1.html', resultFile: result('ada', 'WP04P1', { status: 'ok', verdict: 'review' }) },
      { name: 'bo', part: 'WP04P1', page: 'b.html', resultFile: path.join(dir, 'bo', 'none.json') },
    ];
    const lines = report(items, { isTTY: false, statuses: { 'bo WP04P1': 'failed' } }).split('\n');
    assert.equal(lines.pop(), '', 'every line ends');
    assert.deepEqual(lines, [
      '[grade] ada WP04P2 pass · 1 of 4 parts · 0 of 2 hand-ins · 0:10 so far · about 0:20 left',
      '[grade] bo WP04P2 not handed in · 2 of 4 parts · 0 of 2 hand-ins · 0:20 so far · about 0:40 left',
      '[grade] ada WP04P1 review · 3 of 4 parts · 1 of 2 hand-ins · 0:30 so far · about 0:15 left',
      'grade: bo WP04P1: the grader\'s own trouble: browser has been closed',
      '[grade] bo WP04P1 stopped · 4 of 4 parts · 2 of 2 hand-ins · 0:40 so far · about 0:00 left',
      '[grade] graded 4 part(s) of 2 hand-in(s) in 0:40',
    ]);
    // on a terminal the same run is one line rewritten in place, left as the last one at the end
    const tty = report(items, { isTTY: true });
    assert.ok(tty.includes('\r[grade] 3 of 4 parts · 1 of 2 hand-ins · 0:30 so far · about 0:15 left\x1b[K'), tty);
    assert.equal(tty.split('\n').length, 2, 'one line, ended once');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
