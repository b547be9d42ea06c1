// A grade rests on the page, never on the browser that ran it: where the browser fails itself while
// a part is gathered (out of memory, a frame or its connection lost: what Firefox said on a heavy
// page Chromium grades), the part is not graded here, with the browser's message, and the next
// part gets a fresh browser; where the grader's own trouble is with the page, it stays a review.
// runPart over a driver that answers nothing but that error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { runPart } from '../../grader/node/run/run-part.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { NOT_GRADED } from '../../grader/core/verdict.js';

const RUBRIC = mergeRubric(JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')), { reference: false });

/** A page interface whose every call throws `message`, as a driver does once its browser has failed. */
function failingDriver(message) {
  const fail = async () => { throw new Error(message); };
  return { state: fail, snap: fail, controls: fail, click: fail, setValue: fail, press: fail, tick: fail,
    setNoCull: fail, sources: fail, sent: fail, geometry: fail, surface: fail, errors: () => [] };
}

/** The result runPart writes for a part whose driver throws `message`, and what runPart returns. */
async function gradedWith(message) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'run-part-'));
  try {
    const item = { name: 'ada', part: 'WP04P3', page: 'p3.html', root: dir,
      resultFile: path.join(dir, 'parts', 'ada', 'WP04P3.json'), artifactDir: path.join(dir, 'artifacts', 'ada', 'WP04P3') };
    const student = { open: async () => ({ page: null, driver: failingDriver(message) }), done: async () => {} };
    const returned = await runPart({ item, plan: { rubric: RUBRIC, out: dir }, openers: { student }, browserVersion: 'Firefox 140.5.0esr' });
    return { returned, result: JSON.parse(readFileSync(item.resultFile, 'utf8')) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('the browser failing itself (Firefox\'s detached frame, out of memory): not graded here, the browser named, a fresh browser next', async () => {
  for (const message of [
    'Attempted to use detached Frame \'4F1C\'.',
    'Protocol error (script.callFunction): unknown error out of memory',
  ]) {
    const { returned, result } = await gradedWith(message);
    assert.equal(result.verdict, NOT_GRADED, message);
    assert.equal(result.status, NOT_GRADED, message);
    assert.equal(result.findings[0].id, 'browser-failed', message);
    assert.match(result.reasons[0], /the browser \(Firefox 140\.5\.0esr\) failed while grading this page, not the page/);
    assert.ok(result.reasons[0].includes(message), 'the browser\'s own message');
    assert.deepEqual(returned, { browserFailed: true });
  }
});

test('the grader\'s own trouble with the page (its page navigated away under it): a review for a teacher, never a pass, the browser kept', async () => {
  const { returned, result } = await gradedWith('Execution context was destroyed, most likely because of a navigation');
  assert.equal(result.verdict, 'review');
  assert.equal(result.findings[0].id, 'grader-trouble');
  assert.match(result.reasons[0], /the grader could not finish on this page: Execution context was destroyed/);
  assert.deepEqual(returned, { browserFailed: false });
});
