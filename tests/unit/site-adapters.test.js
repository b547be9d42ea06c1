// The course sites as adapters (grader/class/adapters/index.js): each says how its download names a
// hand-in, its grade import file and where a student's feedback goes in the zip, and nothing else
// names a site. A site made up here (an adapter put in the list, nothing else touched) is told from
// its download's names, its hand-ins grouped, its grade file made and its feedback placed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SITE_ADAPTERS, siteAdapter } from '../../grader/class/adapters/index.js';
import { detectSite, groupBySite } from '../../grader/class/intake/formats.js';
import { gradeFiles } from '../../grader/class/grade-files.js';
import { feedbackZipPath } from '../../grader/class/feedback-zip.js';
import { importText, studentPoints } from '../../grader/class/adapters/points.js';
import { PARTS } from '../../grader/files/parts.js';

const POINTS = { item: 'Worksheet 4', pass: 1, review: 0.5, fail: 0, weights: Object.fromEntries(PARTS.map((p) => [p, 1])) };

test('every adapter has what the intake, the grade files and the feedback zip ask of it; one is the fallback', () => {
  for (const a of SITE_ADAPTERS) {
    assert.equal(typeof a.id, 'string');
    assert.equal(typeof a.describe, 'string');
    assert.equal(typeof a.parseTopName, 'function');
    assert.equal(typeof a.leftOut, 'string');
    assert.equal(typeof a.feedbackPath, 'function');
    assert.ok(a.gradeFile === null || (typeof a.gradeFile.name === 'string' && typeof a.gradeFile.make === 'function'), a.id);
  }
  assert.deepEqual(SITE_ADAPTERS.filter((a) => a.fallback).map((a) => a.id), ['folders']);
  assert.equal(siteAdapter('no such site').id, 'folders');
});

test('a made-up site: one adapter in the list, and the intake tells it, groups its hand-ins, writes its grade file and places its feedback', () => {
  const blackboard = {
    id: 'blackboard',
    describe: 'Blackboard download: files "<assignment>_<username>_attempt_<date>_<name>"',
    parseTopName(top, isFile) {
      const m = isFile ? /^[^_]+_([a-z0-9]+)_attempt_([\d-]+)_(.+)$/.exec(top) : null;
      return m ? { name: m[1], userId: m[1], submissionId: null, time: m[2], late: null, rest: m[3] } : null;
    },
    leftOut: 'not named as blackboard names a hand-in',
    siteFile: null,
    gradeFile: { name: 'grades-blackboard.csv', make: (rows, points) => ({ text: importText([['Username', points.item], ...rows.map((s) => [s.identity.userId, studentPoints(s, points).total])]), left: [] }) },
    feedbackPath: (s, file) => `${s.identity.userId}_${file}`,
  };
  SITE_ADAPTERS.splice(SITE_ADAPTERS.length - 1, 0, blackboard);
  try {
    const names = ['ws4_aiden_attempt_2025-10-10_p1.html', 'ws4_aiden_attempt_2025-10-10_common.js', 'ws4_bo_attempt_2025-10-09_handin.zip'];
    assert.equal(detectSite(names.map((top) => ({ top, isFile: true }))), 'blackboard');
    const { site, students } = groupBySite(names.map((n) => ({ segments: [n] })));
    assert.equal(site, 'blackboard');
    assert.deepEqual(students.map((s) => [s.identity.userId, s.files.map((f) => f.segments.join('/'))]), [['aiden', ['p1.html', 'common.js']], ['bo', ['handin.zip']]]);
    const rows = students.map((s) => ({ name: s.identity.name, identity: s.identity, parts: PARTS.map((part) => ({ part, verdict: 'pass' })) }));
    const { files } = gradeFiles(rows, site, POINTS);
    assert.deepEqual(Object.keys(files), ['grades-points.csv', 'grades-blackboard.csv']);
    assert.equal(files['grades-blackboard.csv'], 'Username,Worksheet 4\r\naiden,5\r\nbo,5\r\n');
    assert.equal(feedbackZipPath(rows[1], site), 'bo_feedback.html');
  } finally {
    SITE_ADAPTERS.splice(SITE_ADAPTERS.indexOf(blackboard), 1);
  }
});
