// The teacher's loop after grading, on RECORDED results (tests/fixtures/artifacts/, judged without a
// browser): the identity from intake.json (with an earlier hand-in) and a roster into the report and the grade import files (each site's
// documented columns, Brightspace's "#", ids keeping their leading zeros), an override that
// changes the grade file and the feedback page without grading again, the feedback pages (every
// part's verdict, pictures inlined, no other student named) and zip (the download's names), and
// the report's item analysis.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { recordedOut } from './recorded-out.js';
import { readClass } from '../../grader/node/report/class-results.js';
import { prepareClass } from '../../grader/node/cli/teacher-loop.js';
import { writeClass } from '../../grader/node/report/report.js';
import { parseOverrides } from '../../grader/node/report/overrides.js';
import { studentPoints } from '../../grader/class/adapters/points.js';
import { readTable } from '../../grader/files/csv.js';
import { zipEntries, entryData } from '../../grader/class/intake/zip.js';
import { PARTS } from '../../grader/files/parts.js';
import { agreement } from '../../grader/node/report/labels.js';

const NAMES = ['ada', 'cy', 'eve', 'gus'];
// who they are on the course site (Brightspace): the names and ids the download and the roster give
const WHO = {
  ada: { name: 'Ada Lovelace', userId: '640601', submissionId: '39701', org: '00012345', time: '2025-10-10T10:22' },
  cy: { name: 'Cy Twombly', userId: '640602', submissionId: '39702', org: '0099', time: '2025-10-10T11:05' },
  eve: { name: 'Eve Ærø Ås', userId: '640603', submissionId: '39703', org: '31415', time: '2025-10-11T09:00' },
  gus: { name: 'Gus Grissom', userId: '640604', submissionId: '39704', org: '27182', time: '2025-10-09T23:59' },
};
let out, rubric;

/** The class as a run of the report reads it: parts, identity, roster, overrides; then the report and the teacher's files. */
function runReport() {
  const graded = readClass(path.join(out, 'parts'));
  const loop = prepareClass(out, graded);
  const { rows } = writeClass(out, graded, { site: loop.site, rubric });
  return { rows, report: JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')) };
}

/** The class with identity and overrides, as the report is given it. */
function readClassWithLoop() {
  const graded = readClass(path.join(out, 'parts'));
  prepareClass(out, graded);
  return graded;
}

before(async () => {
  out = mkdtempSync(path.join(os.tmpdir(), 'teacher-loop-'));
  rubric = await recordedOut(out, NAMES);
  const source = (w) => `${w.submissionId}-${w.userId} - ${w.name} - Oct 10, 2025 1022 AM/`;
  writeFileSync(path.join(out, 'intake.json'), JSON.stringify({ site: 'brightspace', submissions: NAMES.map((n) => ({ name: n, identity: { site: 'brightspace', name: WHO[n].name, userId: WHO[n].userId, submissionId: WHO[n].submissionId, time: WHO[n].time, late: null, source: [source(WHO[n])] }, earlier: n === 'ada' ? [{ time: '2025-10-09T21:58', submissionId: '39650', source: ['39650-640601 - Ada Lovelace - Oct 9, 2025 958 PM/'], files: 1 }] : [], notes: [], error: null })) }));
  // Brightspace's grade export as a roster: ids with "#", a name with a comma in a quoted cell
  writeFileSync(path.join(out, 'roster.csv'), ['OrgDefinedId,Username,Last Name,First Name,Email,End-of-Line Indicator',
    ...NAMES.map((n) => { const [first, ...last] = WHO[n].name.split(' '); return `#${WHO[n].org},#${n}1,"${last.join(' ')}",${first},${n}@example.edu,#`; })].join('\r\n'));
});
after(() => rmSync(out, { recursive: true, force: true }));

test('Brightspace grade import: OrgDefinedId with "#" (leading zeros kept), "<item> Points Grade", End-of-Line Indicator "#"', () => {
  const { rows } = runReport();
  const table = readTable(readFileSync(path.join(out, 'grades-brightspace.csv'), 'utf8'));
  assert.deepEqual(table[0], ['OrgDefinedId', 'Worksheet 4 Points Grade', 'End-of-Line Indicator']);
  assert.equal(table.length, 1 + NAMES.length - 1, 'gus has parts not graded here: left out, never a 0');
  for (const n of NAMES.filter((x) => x !== 'gus')) {
    const line = table.find((r) => r[0] === `#${WHO[n].org}`);
    assert.ok(line, `${n}: #${WHO[n].org}`);
    assert.equal(line[2], '#');
    const s = rows.find((x) => x.name === n);
    const expected = s.parts.reduce((a, p) => a + rubric.points[p.verdict] * rubric.points.weights[p.part], 0);
    assert.equal(Number(line[1]), expected, `${n}: ${s.parts.map((p) => p.verdict).join(' ')}`);
  }
  const html = readFileSync(path.join(out, 'report.html'), 'utf8');
  assert.match(html, /user id 640601 · submission 39701 · OrgDefinedId 00012345 · handed in 2025-10-10 10:22/, 'the report says who a hand-in is');
  assert.match(html, /Handed in earlier \(the latest is graded\):<\/p><ul class="earlier"><li>2025-10-09 21:58, submission 39650/, 'and the earlier hand-in with its time');
  const points = readTable(readFileSync(path.join(out, 'grades-points.csv'), 'utf8'));
  assert.deepEqual(points[0].slice(0, 6), ['name', 'site', 'user id', 'submission id', 'time', 'late']);
  assert.equal(points.find((r) => r[0] === 'gus')[PARTS.length + 6], '', 'no total with a part not graded');
});

test('an override changes the grade file, the report and the feedback page, without grading again', () => {
  const before = runReport();
  const cy = before.rows.find((s) => s.name === 'cy');
  const graderSaid = cy.parts.find((p) => p.part === 'WP04P2').verdict;
  assert.notEqual(graderSaid, 'pass');
  const total = () => Number(readTable(readFileSync(path.join(out, 'grades-brightspace.csv'), 'utf8')).find((r) => r[0] === '#0099')[1]);
  const was = total();
  writeFileSync(path.join(out, 'overrides.tsv'), 'student\tpart\tverdict\tnote\nCy Twombly\tWP04P2\tpass\tThe back faces are hidden in your own view: fine.\n');
  try {
    const after = runReport();
    assert.equal(total(), was + rubric.points.pass - rubric.points[graderSaid]);
    const p = after.report.submissions.find((s) => s.name === 'cy').parts.find((x) => x.part === 'WP04P2');
    assert.deepEqual({ verdict: p.verdict, teacher: p.teacher.verdict, grader: p.grader.verdict }, { verdict: 'pass', teacher: 'pass', grader: graderSaid });
    const html = readFileSync(path.join(out, 'report.html'), 'utf8');
    assert.ok(html.includes(`>teacher</span><span class="grader-said">grader: ${graderSaid}</span>`), 'the report marks the teacher\'s verdict, the grader\'s beside it');
    const page = readFileSync(path.join(out, 'feedback', 'cy.html'), 'utf8');
    assert.match(page, new RegExp(`Your teacher set this verdict \\(the grader said ${graderSaid}\\)\\. The back faces are hidden in your own view: fine\\.`));
    assert.match(page, /data-part="WP04P2" data-verdict="pass"/);
    const points = readTable(readFileSync(path.join(out, 'grades-points.csv'), 'utf8'));
    assert.equal(points.find((r) => r[0] === 'cy').at(-1), 'WP04P2', 'grades-points.csv says the teacher set it');
    const labelled = agreement([{ submission: 'cy', part: 'WP04P2', label: 'partial', reasons: '', unsure: false }], readClassWithLoop());
    assert.equal(labelled.agree, graderSaid === 'review' ? 1 : 0, 'a teacher\'s labels are held to the grader\'s verdict, not the override');
  } finally {
    rmSync(path.join(out, 'overrides.tsv'));
  }
  assert.equal(runReport().rows.find((s) => s.name === 'cy').parts.find((x) => x.part === 'WP04P2').verdict, graderSaid, 'the line deleted, the grader\'s verdict is back');
});

test('a feedback page: every part\'s verdict, pictures inlined, nothing fetched, no other student named', () => {
  const { rows } = runReport();
  for (const s of rows) {
    const page = readFileSync(path.join(out, 'feedback', `${s.name}.html`), 'utf8');
    for (const p of s.parts) assert.match(page, new RegExp(`data-part="${p.part}" data-verdict="${p.verdict}"`), `${s.name} ${p.part}`);
    assert.ok(page.includes(WHO[s.name].name.replace('Æ', '&#198;')) || page.includes(WHO[s.name].name), `${s.name}'s page names the student`);
    for (const other of NAMES.filter((n) => n !== s.name)) {
      for (const mark of [WHO[other].name, WHO[other].userId, WHO[other].org, `${other}@`]) assert.ok(!page.includes(mark), `${s.name}'s page names ${other} (${mark})`);
    }
    assert.doesNotMatch(page, /<script|<link|src="(?!data:image\/png;base64,)/, 'self-contained');
    if (s.parts.some((p) => p.images && p.images.judged)) assert.match(page, /<img src="data:image\/png;base64,/);
  }
});

test('the feedback zip holds each page under the download\'s own folder name (UTF-8 names)', () => {
  runReport();
  const zip = readFileSync(path.join(out, 'feedback-brightspace.zip'));
  const entries = zipEntries(zip);
  assert.deepEqual(entries.map((e) => e.name).sort(), NAMES.map((n) => `${WHO[n].submissionId}-${WHO[n].userId} - ${WHO[n].name} - Oct 10, 2025 1022 AM/feedback.html`).sort());
  const eve = entries.find((e) => e.name.includes('Ærø'));
  assert.equal(new TextDecoder().decode(entryData(zip, eve, 1 << 24)), readFileSync(path.join(out, 'feedback', 'eve.html'), 'utf8'));
});

test('item analysis: each part\'s checks with how many students each failed, reviewed or passed', () => {
  const { report, rows } = runReport();
  assert.equal(report.itemAnalysis.length, PARTS.length);
  for (const a of report.itemAnalysis) {
    assert.equal(a.students, rows.length);
    assert.equal(a.passed, rows.filter((s) => s.parts.find((p) => p.part === a.part).verdict === 'pass').length);
    assert.ok(a.checks.length > 0, a.part);
    for (const c of a.checks) assert.ok(c.count >= 1 && c.count <= a.students && !/^\d/.test(c.key), `${a.part}: ${c.key}`);
    for (const c of a.checks) assert.ok(!a.checks.some((d) => d !== c && d.key === c.key && d.level === c.level), `${a.part}: ${c.key} once`);
  }
  const p3 = report.itemAnalysis.find((a) => a.part === 'WP04P3');
  assert.ok(p3.checks.some((c) => c.level === 'fail'), 'eve\'s page that never loads is a failed check');
  // a part that could not be judged: its first reason is a failed check, whatever follows it
  for (const a of report.itemAnalysis) {
    for (const s of rows) {
      const r = s.parts.find((p) => p.part === a.part);
      if (r.verdict === 'fail' && r.reasons.length && !/^(FAIL|REVIEW): /.test(r.reasons[0])) assert.ok(a.checks.some((c) => c.level === 'fail' && r.reasons[0].startsWith(c.key)), `${s.name} ${a.part}: ${r.reasons[0]}`);
    }
  }
  assert.match(readFileSync(path.join(out, 'report.html'), 'utf8'), /<section id="items"><h2>Item analysis<\/h2>/);
});

test('Canvas and Moodle import files have their documented columns', async () => {
  const [{ canvasCsv }, { moodleCsv }] = await Promise.all([import('../../grader/class/adapters/canvas.js'), import('../../grader/class/adapters/moodle.js')]);
  const { rows } = runReport();
  const ids = (n, extra) => ({ ...rows.find((s) => s.name === n), identity: { name: WHO[n].name, userId: WHO[n].userId, ...extra } });
  const canvas = readTable(canvasCsv([ids('ada', { sisUserId: 's012', sisLoginId: 'ada1', section: 'A' })], rubric.points).text);
  assert.deepEqual(canvas[0], ['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', 'Worksheet 4']);
  assert.deepEqual(canvas[1].slice(0, 5), ['Ada Lovelace', '640601', 's012', 'ada1', 'A']);
  const moodle = readTable(moodleCsv([ids('cy', { idNumber: '007', email: 'cy@example.edu' })], rubric.points).text);
  assert.deepEqual(moodle[0], ['Full name', 'ID number', 'Email address', 'Worksheet 4', 'Feedback']);
  assert.deepEqual(moodle[1].slice(0, 3), ['Cy Twombly', '007', 'cy@example.edu']);
  assert.match(moodle[1][4], /^WP04P1 \w+; WP04P2/);
});

test('overrides.tsv: bad lines are named; points follow the rubric', () => {
  assert.throws(() => parseOverrides('student\tpart\tverdict\nada\tWP04P9\tpass\n'), /line 2: part "WP04P9"/);
  assert.throws(() => parseOverrides('student\tpart\tverdict\nada\tWP04P1\tgood\n'), /line 2: verdict "good"/);
  assert.throws(() => parseOverrides('who\tpart\n'), /must name the columns/);
  assert.deepEqual(parseOverrides('# teacher\nstudent\tpart\tverdict\tnote\nada\twp04p1\tpartial\tsee me\n'), [{ student: 'ada', part: 'WP04P1', verdict: 'review', note: 'see me', line: 3 }]);
  const s = { parts: PARTS.map((part, k) => ({ part, verdict: ['pass', 'review', 'fail', 'pass', 'review'][k] })) };
  assert.equal(studentPoints(s, { ...rubric.points, weights: { ...rubric.points.weights, WP04P5: 2 } }).total, 1 + 0.5 + 0 + 1 + 2 * 0.5);
});

test('one call gives every file the command writes, the same bytes (class/outputs.js: the page\'s way to the same files; the command writes them, report.js\'s writeClass)', async () => {
  const { classOutputs } = await import('../../grader/class/outputs.js');
  const { zipEntries: entries, entryData: data } = await import('../../grader/class/intake/zip.js');
  writeFileSync(path.join(out, 'overrides.tsv'), 'student\tpart\tverdict\tnote\nCy Twombly\tWP04P2\tpass\tFine in your own view.\n');
  try {
    // the command's way (grade.js: a class from a download, so grades.csv too), written into OUT
    writeClass(out, readClassWithLoop(), { aClass: true, site: 'brightspace', rubric });
    const written = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    // one call, the pictures read as the command reads them
    const { picturesIn } = await import('../../grader/node/report/feedback-page.js');
    const { files } = classOutputs(readClassWithLoop(), { aClass: true, site: 'brightspace', rubric, generated: written.generated, pictureOf: picturesIn(out) });
    const names = Object.keys(files).sort();
    assert.deepEqual(names, ['feedback-brightspace.zip', ...NAMES.map((n) => `feedback/${n}.html`), 'grades-brightspace.csv', 'grades-points.csv', 'grades.csv', 'report.html', 'report.json'].sort());
    for (const name of names.filter((n) => !n.endsWith('.zip'))) {
      assert.equal(String(files[name]), readFileSync(path.join(out, ...name.split('/')), 'utf8'), name);
    }
    // the zip: the same entries, the same bytes in each (its own bytes carry each entry's time)
    const zipped = (bytes) => Object.fromEntries(entries(bytes).map((e) => [e.name, Buffer.from(data(bytes, e, 1 << 26)).toString('base64')]));
    assert.deepEqual(zipped(files['feedback-brightspace.zip']), zipped(readFileSync(path.join(out, 'feedback-brightspace.zip'))));
  } finally {
    rmSync(path.join(out, 'overrides.tsv'));
  }
});
