// npm run grade's teacher's loop end to end, with no browser: a Canvas download whose every hand-in
// is hostile (a zip bomb, a corrupt zip) is taken in, said, each student failed with the message,
// and the report, grade files and feedback written; --report-only applies an override from
// OUT/overrides.tsv (grades.csv too); a bad overrides line is bad usage (exit 2); --help still answers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { unzipSync } from 'fflate';
import { makeZip } from './downloads.js';
import { readTable } from '../../grader/files/csv.js';

const grade = fileURLToPath(new URL('../../grader/node/cli/grade.js', import.meta.url));
const run = (args) => spawnSync(process.execPath, [grade, ...args], { encoding: 'utf8' });

test('a download of hostile hand-ins only: each student told why, every part fail, the files written, overrides applied by --report-only', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'grade-cli-'));
  try {
    const bomb = makeZip([{ name: 'z.bin', data: new Uint8Array(120 << 20) }]);
    const broken = makeZip([{ name: 'a.html', data: 'x'.repeat(500) }]).slice(0, 90);
    const dl = path.join(dir, 'submissions.zip');
    writeFileSync(dl, makeZip([
      { name: 'rodriguezaiden_640693_39786_handin.zip', data: bomb, store: true },
      { name: 'aerosoeren_late_000123_39787_ws4.zip', data: broken, store: true },
    ]));
    const out = path.join(dir, 'out');
    // Canvas's gradebook export as the roster: ID (Canvas's user id) and the SIS columns
    const roster = path.join(dir, 'gradebook.csv');
    writeFileSync(roster, 'Student,ID,SIS User ID,SIS Login ID,Section,Worksheet 4 (77)\n"Ærø, Søren",000123,s0099,soeren,Hold 2,\n');
    const r = run(['--batch', dl, '--out', out, '--roster', roster]);
    assert.equal(r.status, 0, r.stderr);
    assert.match(r.stdout, /^grade: found Canvas download: .*2 hand-in\(s\); 1 late; 2 could not be unpacked/m, 'Canvas\'s "_late" counted');
    assert.match(r.stdout, /rodriguezaiden: the hand-in could not be unpacked: .*more than 100 MB/);
    assert.match(r.stdout, /aerosoeren: the hand-in could not be unpacked: "ws4\.zip": it is not a zip file/);
    const report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    const aero = report.submissions.find((s) => s.name === 'aerosoeren');
    assert.deepEqual({ userId: aero.identity.userId, fileIds: aero.identity.fileIds, late: aero.identity.late }, { userId: '000123', fileIds: ['39787'], late: true });
    assert.ok(aero.parts.every((p) => p.verdict === 'fail' && p.status === 'not unpacked' && /not a zip file/.test(p.reasons[0])));
    const canvas = readTable(readFileSync(path.join(out, 'grades-canvas.csv'), 'utf8'));
    assert.deepEqual(canvas[0], ['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', 'Worksheet 4']);
    assert.deepEqual(canvas.find((l) => l[1] === '000123').slice(0, 5), ['Søren Ærø', '000123', 's0099', 'soeren', 'Hold 2'], 'the roster\'s columns, the id with its leading zeros');
    assert.deepEqual(canvas.find((l) => l[1] === '640693').slice(0, 3), ['rodriguezaiden', '640693', ''], 'a student the roster does not have: the download\'s name and id');
    assert.match(readFileSync(path.join(out, 'feedback', 'aerosoeren.html'), 'utf8'), /it is not a zip file/);
    // Canvas's Re-Upload Submissions reads the first two all-digit "_"-parts of a file's name as the
    // user id and the id of one of that student's files (canvas-lms Assignment#infer_comment_context_from_filename)
    const back = Object.keys(unzipSync(readFileSync(path.join(out, 'feedback-canvas.zip')))).sort();
    assert.deepEqual(back, ['aerosoeren_late_000123_39787_feedback.html', 'rodriguezaiden_640693_39786_feedback.html']);
    for (const name of back) {
      const s = report.submissions.find((x) => name.startsWith(`${x.name}_`));
      assert.deepEqual(name.split('_').filter((p) => /^\d+$/.test(p)).slice(0, 2), [s.identity.userId, s.identity.fileIds[0]], name);
    }

    writeFileSync(path.join(out, 'overrides.tsv'), 'student\tpart\tverdict\tnote\n000123\tWP04P1\treview\tSend me the zip again by mail.\n');
    const again = run(['--report-only', '--out', out]);
    assert.equal(again.status, 0, again.stderr);
    assert.match(again.stdout, /grade: 1 verdict\(s\) set by the teacher/);
    const line = readTable(readFileSync(path.join(out, 'grades-canvas.csv'), 'utf8')).find((l) => l[1] === '000123');
    assert.deepEqual([line[2], line[5]], ['s0099', '0.5'], 'the roster kept in OUT from the first run; the override counted');
    assert.match(readFileSync(path.join(out, 'feedback', 'aerosoeren.html'), 'utf8'), /Your teacher set this verdict \(the grader said fail\)\. Send me the zip again by mail\./);
    const grades = readTable(readFileSync(path.join(out, 'grades.csv'), 'utf8'));
    assert.equal(grades.find((l) => l[0] === 'aerosoeren')[grades[0].indexOf('WP04P1')], 'review', 'grades.csv written again by --report-only, never left from before');

    writeFileSync(path.join(out, 'overrides.tsv'), 'student\tpart\tverdict\n000123\tWP04P7\tpass\n');
    const bad = run(['--report-only', '--out', out]);
    assert.equal(bad.status, 2);
    assert.match(bad.stderr, /overrides\.tsv, line 2: part "WP04P7"/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('--help names the download and the loop\'s options; a missing download is an error (exit 1)', () => {
  const help = run(['--help']);
  assert.equal(help.status, 0);
  for (const s of ['download.zip', '--overrides FILE', '--roster FILE', '--due', 'feedback-<site>.zip']) assert.ok(help.stdout.includes(s), s);
  const badDue = run(['--batch', 'x.zip', '--due', 'Friday 23:59']);
  assert.equal(badDue.status, 2);
  assert.match(badDue.stderr, /--due takes the due date and time as "2025-10-10 23:59"/);
  // an option's value is never the next option (it once graded into a folder named "--out")
  const optionAsValue = run(['--audit-only', '--out', path.join(os.tmpdir(), 'grade-cli-none')]);
  assert.equal(optionAsValue.status, 2);
  assert.match(optionAsValue.stderr, /^grade: --audit-only needs a value/);
  const missing = run(['--batch', path.join(os.tmpdir(), 'no-such-download.zip'), '--out', path.join(os.tmpdir(), 'grade-cli-none')]);
  assert.equal(missing.status, 1);
  assert.match(missing.stderr, /no such file or folder/);
  rmSync(path.join(os.tmpdir(), 'grade-cli-none'), { recursive: true, force: true });
});
