// The grader's intake (grader/node/sites/intake/): a download from each course site, built here from the
// fixture hand-ins (tests/fixtures/handins/, or the real ones in HANDINS_DIR) in the site's own
// names (a student's zip, a zip in a zip, loose files, a resubmission, __MACOSX/, a name with
// æ/ø/å), and hostile hand-ins, each a student of its own (a zip bomb, a "../" entry, a symbolic
// link, a corrupt zip, two entries of one name, a CP850 name, too many files, zips too deep):
// every real student's unpacked tree equals its folder file for file, each hostile one gets its
// message while the others are unpacked, and nothing is written outside the output folder. The
// same downloads wrapped in one more folder (zipped again on a Mac, or that zip unpacked) give the
// same class, and a folder that is no download is refused with what was found.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { intake, readIntake } from '../../grader/node/sites/intake/intake.js';
import { brightspaceTime, detectSite, dueTime, groupBySite, lateOf } from '../../grader/class/intake/formats.js';
import { decodeName, safeSegments } from '../../grader/class/intake/names.js';
import { IntakeError } from '../../grader/class/intake/zip.js';
import { feedbackZipPath } from '../../grader/class/feedback-zip.js';
import { findParts } from '../../grader/files/parts.js';
import { copyHandins } from '../fixtures/handins.js';
import { makeZip, cp850, tree, entriesOf, idsOf, lastFirst, siteName } from './downloads.js';

const here = path.dirname(fileURLToPath(import.meta.url));
// the hand-ins the downloads are built from: HANDINS_DIR (the real ones, ../shared/handins) when
// given, else the fixture hand-ins copied out (their borrowed files put in, as the students had them)
const fixtureCopy = process.env.HANDINS_DIR ? null : mkdtempSync(path.join(os.tmpdir(), 'intake-handins-'));
if (fixtureCopy) copyHandins(fixtureCopy);
after(() => fixtureCopy && rmSync(fixtureCopy, { recursive: true, force: true }));
const HANDINS = process.env.HANDINS_DIR || fixtureCopy;
const students = readdirSync(HANDINS).filter((n) => statSync(path.join(HANDINS, n)).isDirectory()).sort();
const rubric = JSON.parse(readFileSync(path.join(here, '../../grader/core/rubric.json'), 'utf8'));
// small bounds, so that the bomb is small to build: 8 MB unpacked, 500 files, zips 3 deep
const BOUNDS = { ...rubric.unpack, maxBytes: 8 << 20, maxFiles: 500 };

/** How each real student packs the hand-in (k: the student's index). */
function handinZip(name, k) {
  const own = entriesOf(path.join(HANDINS, name));
  if (k % 4 === 1) return makeZip([{ name: 'inner.zip', data: makeZip(own), store: true }]); // a zip in a zip
  if (k % 4 === 2) return makeZip([...own, { name: '__MACOSX/._x.html', data: 'junk' }, { name: '.DS_Store', data: 'junk' }, { name: 'Thumbs.db', data: 'junk' }]);
  return makeZip(own);
}

/** `n` small files, as zip entries. */
const manyFiles = (n) => Array.from({ length: n }, (_, k) => ({ name: `f/${k}.txt`, data: 'x' }));
/** A student's zip holding p1/index.html `depth` zips deep (1: in the student's zip itself). */
const nested = (depth) => (depth === 1 ? makeZip([{ name: 'p1/index.html', data: '<p>' }]) : makeZip([{ name: 'inner.zip', data: nested(depth - 1), store: true }]));

const bomb = () => makeZip([{ name: 'zeros.bin', data: new Uint8Array(40 << 20) }]);
// each hostile hand-in: [name, zip, what its student must get]
const HOSTILE = [
  ['Zip Bomb', bomb, { error: /more than 8 MB .*unpack\.maxBytes/ }],
  ['Lying Bomb', () => makeZip([{ name: 'a.html', data: '<p>' }, { name: 'zeros.bin', data: new Uint8Array(40 << 20), declared: 1000 }]), { error: /more than 8 MB .*unpack\.maxBytes/ }],
  ['Climb Out', () => makeZip([{ name: '../../evil.txt', data: 'x' }, { name: 'ok/index.html', data: '<p>' }]), { note: /left out "\.\.\/\.\.\/evil\.txt".*"\.\." that climbs out/, files: ['ok/index.html'] }],
  ['Link Maker', () => makeZip([{ name: 'link', data: '/etc/passwd', symlink: true }, { name: 'a.html', data: '<p>' }]), { note: /symbolic link/, files: ['a.html'] }],
  ['Broken Zip', () => makeZip([{ name: 'a.html', data: 'hello world '.repeat(100) }]).slice(0, 120), { error: /could not be unpacked: .*not a zip file/ }],
  ['Twice Named', () => makeZip([{ name: 'p1/index.html', data: 'first' }, { name: 'p1/index.html', data: 'second' }]), { files: ['p1/index (2).html', 'p1/index.html'] }],
  ['Zip Sixtyfour', () => makeZip([{ name: 'p1/index.html', data: '<p>64</p>' }, { name: 'zeros.bin', data: new Uint8Array(40 << 20), declared: 10 }], { zip64: true }), { error: /more than 8 MB/ }],
  ['Deep Path', () => makeZip([{ name: `${'deep/'.repeat(1000)}x.html`, data: '<p>' }]), { error: /could not be written here \(ENAMETOOLONG\)/ }],
  ['Åse Bødker-Ærø', () => makeZip([{ nameBytes: cp850('æble/øl å.html'), data: 'cp850' }, { name: 'utf8/æøå.html', data: 'utf8' }]), { files: ['utf8/æøå.html', 'æble/øl å.html'] }],
  // unpack.maxFiles: as many files as the bound is a hand-in, one more is not
  ['Files Enough', () => makeZip(manyFiles(BOUNDS.maxFiles)), { error: null, count: BOUNDS.maxFiles }],
  ['Files Galore', () => makeZip(manyFiles(BOUNDS.maxFiles + 1)), { error: /more than 500 files \(the rubric's unpack\.maxFiles\)/ }],
  // unpack.maxDepth: the student's zip is the first level, each zip inside it one more
  ['Deep Enough', () => nested(BOUNDS.maxDepth), { files: ['p1/index.html'] }],
  ['Deep Zips', () => nested(BOUNDS.maxDepth + 1), { error: /nested more than 3 deep \(the rubric's unpack\.maxDepth\)/ }],
];

/** A download of `site` in `dir`: the real students and the hostile ones, as `site` names them. */
function buildDownload(site, dir) {
  const files = [];
  const all = [...students.map((n, k) => ({ name: `${n} Student`, zip: () => handinZip(n, k), real: n, k, late: k === 2 })), ...HOSTILE.map(([name, zip], k) => ({ name, zip, k: 100 + k }))];
  for (const s of all) {
    // the fourth student's files loose, where the site keeps folders
    if (s.k === 3 && site !== 'canvas') files.push(...entriesOf(path.join(HANDINS, s.real), siteName(site, s, '')));
    else files.push({ name: siteName(site, s, 'handin.zip'), data: s.zip() });
    // the first student handed in twice: an earlier, wrong hand-in the day before (Brightspace keeps both)
    if (site === 'brightspace' && s.k === 0) files.push({ name: siteName(site, s, 'old.zip', { sid: String(Number(idsOf(s.k).sid) - 50), when: 'Oct 9, 2025 958 PM' }), data: makeZip([{ name: 'wrong.html', data: 'old' }]) });
    if (site === 'moodle') files.push({ name: `${s.name}_${idsOf(s.k).uid}_assignsubmission_onlinetext/onlinetext.html`, data: '<p>text</p>' });
  }
  if (site === 'brightspace') files.push({ name: 'index.html', data: '<table>the listing</table>' });
  files.push({ name: '.git/config', data: '[core]' }, { name: '.DS_Store', data: 'junk' }); // nobody's
  const file = path.join(dir, `${site}-download.zip`);
  // (Moodle's download written as ZIP64, as a large download is)
  writeFileSync(file, makeZip(files.map((f) => ({ ...f, store: true })), { zip64: site === 'moodle' }));
  return { file, all };
}

for (const site of ['brightspace', 'canvas', 'moodle']) {
  test(`a ${site} download: the site said, each real hand-in unpacked file for file, each hostile one its message, nothing outside`, () => {
    const dir = mkdtempSync(path.join(os.tmpdir(), `intake-${site}-`));
    try {
      const { file, all } = buildDownload(site, dir);
      const out = path.join(dir, 'out');
      mkdirSync(out);
      const t0 = performance.now();
      // Brightspace's names give the time, so a due date makes a hand-in after it late
      const got = intake(file, out, BOUNDS, site === 'brightspace' ? dueTime('2025-10-10 10:00') : null);
      const ms = performance.now() - t0;
      console.log(`${site}: ${(statSync(file).size / 1048576).toFixed(1)} MB download, ${got.submissions.length} hand-ins unpacked in ${ms.toFixed(0)} ms`);
      assert.equal(got.site, site);
      assert.deepEqual(readIntake(out).site, site, 'intake.json says the site');
      assert.equal(got.submissions.length, all.length, got.submissions.map((s) => s.name).join(', '));
      const byUser = new Map(got.submissions.map((s) => [s.identity.userId, s]));
      const find = (s) => byUser.get(idsOf(s.k).uid);
      for (const s of all) {
        const sub = find(s);
        assert.ok(sub, `${s.name} is found`);
        assert.equal(sub.identity.name, site === 'canvas' ? lastFirst(s.name) : s.name, `${s.name}'s name, as the site gives it`);
        if (site === 'brightspace') assert.equal(sub.identity.submissionId, idsOf(s.k).sid, `${s.name}'s submission id`);
        if (site === 'canvas') assert.deepEqual(sub.identity.fileIds, [idsOf(s.k).sid], `${s.name}'s file id`);
        if (s.real) {
          assert.equal(sub.error, null, `${s.name}: ${sub.error}`);
          assert.deepEqual(tree(sub.root), tree(path.join(HANDINS, s.real)), `${s.name}'s unpacked tree is its folder, file for file`);
        }
      }
      for (const [k, [name, , want]] of HOSTILE.entries()) {
        const sub = find({ k: 100 + k });
        if (want.error) assert.match(String(sub.error), want.error, name);
        else assert.equal(sub.error, null, `${name}: ${sub.error}`);
        if (want.note) assert.ok(sub.notes.some((n) => want.note.test(n)), `${name}: ${sub.notes.join(' | ')}`);
        if (want.files) assert.deepEqual(Object.keys(tree(sub.root)).sort(), want.files.sort(), name);
        if (want.count) assert.equal(Object.keys(tree(sub.root)).length, want.count, name);
      }
      if (site === 'brightspace') {
        const first = find(all[0]);
        assert.equal(first.identity.time, '2025-10-10T10:22', 'the latest hand-in is graded');
        assert.deepEqual(first.earlier.map((e) => [e.time, e.late]), [['2025-10-09T21:58', false]], 'the earlier one is listed with its time, before the due date');
        assert.equal(first.identity.late, true, 'the latest, 22 minutes after the due date, is late');
        assert.ok(!existsSync(path.join(first.root, 'wrong.html')));
      }
      if (site === 'canvas') assert.equal(find(all[2]).identity.late, true, 'late is read from the name');
      if (site === 'canvas') assert.equal(find(all[0]).identity.late, false);
      // nothing written outside the output folder: the temp folder holds the download and out only
      assert.deepEqual(readdirSync(dir).sort(), [path.basename(file), 'out'].sort());
      assert.ok(!existsSync(path.join(os.tmpdir(), 'evil.txt')) && !existsSync(path.join(dir, 'evil.txt')) && !existsSync(path.join(out, 'evil.txt')));
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
}

test('the download unpacked by the teacher (a folder) is read as the zip is', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'intake-folder-'));
  try {
    // Brightspace's folders, unpacked into "Assignment 4 Download ..." with the hand-ins loose
    const root = path.join(dir, 'Assignment 4 Download Oct 11, 2025 803 PM');
    for (const [k, n] of students.entries()) {
      const file = path.join(root, siteName('brightspace', { name: `${n} Student`, k }, 'handin.zip'));
      mkdirSync(path.dirname(file), { recursive: true });
      writeFileSync(file, handinZip(n, k));
    }
    const out = path.join(dir, 'out');
    mkdirSync(out);
    const got = intake(dir, out, BOUNDS);
    assert.equal(got.site, 'brightspace');
    for (const [k, n] of students.entries()) {
      const sub = got.submissions.find((s) => s.identity.userId === idsOf(k).uid);
      assert.deepEqual(tree(sub.root), tree(path.join(HANDINS, n)), n);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a folder a student with no zip is graded where it is, as before', () => {
  const out = mkdtempSync(path.join(os.tmpdir(), 'intake-plain-'));
  try {
    const got = intake(HANDINS, out, BOUNDS);
    assert.equal(got.site, 'folders');
    assert.deepEqual(got.submissions.map((s) => s.name), students);
    for (const s of got.submissions) assert.equal(s.root, path.join(HANDINS, s.name), 'the folder itself, as --batch gave it before');
    assert.ok(!existsSync(path.join(out, 'handins')) || !readdirSync(path.join(out, 'handins')).length);
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
});

test('names: UTF-8 by the flag, CP850 otherwise; paths that climb out, absolute or with a drive letter are refused', () => {
  assert.equal(decodeName(cp850('æøå ÆØÅ.txt'), false), 'æøå ÆØÅ.txt');
  assert.equal(decodeName(new TextEncoder().encode('æøå.txt'), true), 'æøå.txt');
  assert.equal(decodeName(new TextEncoder().encode('æøå.txt'), false), 'æøå.txt', 'macOS writes UTF-8 without the flag');
  for (const bad of ['../x', 'a/../../x', '/etc/passwd', 'C:/x', 'C:\\x', '..\\x', 'a\\..\\..\\x']) assert.ok(safeSegments(bad).unsafe, bad);
  assert.deepEqual(safeSegments('a\\b/./c.html').segments, ['a', 'b', 'c.html']);
  assert.deepEqual(safeSegments('con.js/a:b?.html').segments, ['_con.js', 'a_b_.html']);
  assert.equal(brightspaceTime('Oct 10, 2025 1022 AM'), '2025-10-10T10:22');
  assert.equal(brightspaceTime('Sep 29, 2015 4:17 PM'), '2015-09-29T16:17');
  assert.equal(brightspaceTime('Jan 1, 2026 1205 AM'), '2026-01-01T00:05');
  assert.equal(dueTime('2025-10-10 9:05'), '2025-10-10T09:05');
  assert.equal(dueTime('2025-10-10T23:59'), '2025-10-10T23:59');
  for (const bad of ['tomorrow', '2025-13-01 10:00', '2025-10-10 24:00', '10/10/2025 10:00', '2025-10-10']) assert.equal(dueTime(bad), null, bad);
  // late: after the due minute; the site's own word stands; no time or no due date: not known
  assert.equal(lateOf({ time: '2025-10-10T10:00', late: null }, '2025-10-10T10:00'), false);
  assert.equal(lateOf({ time: '2025-10-10T10:01', late: null }, '2025-10-10T10:00'), true);
  assert.equal(lateOf({ time: null, late: true }, '2025-10-10T10:00'), true);
  assert.equal(lateOf({ time: null, late: null }, '2025-10-10T10:00'), null);
  assert.equal(lateOf({ time: '2025-10-10T10:01', late: null }, null), null);
  assert.equal(detectSite([{ top: 'aiden_1_2_x.zip', isFile: true }, { top: 'bo_late_3_4_y.html', isFile: true }]), 'canvas');
  assert.equal(detectSite([{ top: 'ada', isFile: false }, { top: 'bo', isFile: false }]), 'folders');
});

test('the sites\' other shapes: Brightspace\'s and Moodle\'s loose files, Canvas\'s several files a student', () => {
  const f = (...names) => names.map((n) => ({ segments: n.split('/') }));
  const shape = (g) => g.students.map((s) => [s.identity.name, s.identity.userId, s.files.map((x) => x.segments.join('/')).sort().join(' ')]).sort();
  const bs = groupBySite(f('39786-640693 - Aiden Rodriguez - Oct 10, 2025 10:22 AM - handin.zip', '39786-640693 - Aiden Rodriguez - Oct 10, 2025 10:22 AM - notes.txt', '39790-640700 - Bo Ek - Sep 1, 2025 1:05 PM - p1.html', 'index.html'));
  assert.equal(bs.site, 'brightspace');
  assert.deepEqual(shape(bs), [['Aiden Rodriguez', '640693', 'handin.zip notes.txt'], ['Bo Ek', '640700', 'p1.html']]);
  const md = groupBySite(f('Aiden Rodriguez_77_assignsubmission_file_handin.zip', 'Bo Ek_78_assignsubmission_file_/w4/p1.html', 'Bo Ek_78_assignsubmission_onlinetext_/onlinetext.html'));
  assert.equal(md.site, 'moodle');
  assert.deepEqual(shape(md), [['Aiden Rodriguez', '77', 'handin.zip'], ['Bo Ek', '78', 'w4/p1.html']]);
  // each file a Canvas student handed in has its own id (the attachment's): one hand-in still
  const cv = groupBySite(f('rodriguezaiden_640693_39786_p1.html', 'rodriguezaiden_640693_39791_common.js', 'ekbo_late_640700_39790_ws4-1.zip'));
  assert.equal(cv.site, 'canvas');
  assert.deepEqual(shape(cv), [['ekbo', '640700', 'ws4-1.zip'], ['rodriguezaiden', '640693', 'common.js p1.html']]);
  const aiden = cv.students.find((s) => s.identity.name === 'rodriguezaiden');
  assert.deepEqual([aiden.identity.fileIds, aiden.earlier], [['39786', '39791'], []], 'both files graded together, neither an earlier hand-in');
  assert.equal(cv.students.find((s) => s.identity.name === 'ekbo').identity.late, true);
  // a name of no site beside a site's names is left out, and said
  const mixed = groupBySite(f('39786-640693 - Aiden Rodriguez - Oct 10, 2025 1022 AM/a.html', 'stray/b.html'));
  assert.equal(mixed.site, 'brightspace');
  assert.deepEqual(mixed.notes, ['left out "stray": not named as brightspace names a hand-in']);
});

/** The class as the intake found it: each student's name, identity and the parts the grader finds in the hand-in. */
const classOf = (got) => got.submissions.map((s) => ({ name: s.name, identity: s.identity, earlier: s.earlier, error: s.error, parts: s.error ? null : findParts(s.root) }));

/** Writes `entries` ([{ name, data }]) as files under `dir`, as unpacking their zip would. */
function writeEntries(dir, entries) {
  for (const e of entries) {
    mkdirSync(path.join(dir, path.dirname(e.name)), { recursive: true });
    writeFileSync(path.join(dir, e.name), e.data);
  }
}

/**
 * `entries` zipped again one folder down, as macOS's Compress makes it: everything under `top`/,
 * a .DS_Store in it, and __MACOSX/ beside it with a "._" file for each.
 */
const macWrapped = (top, entries) => [
  ...entries.map((e) => ({ ...e, name: `${top}/${e.name}` })),
  { name: `${top}/.DS_Store`, data: 'junk' },
  ...entries.map((e) => ({ name: `__MACOSX/${top}/${path.posix.dirname(e.name)}/._${path.posix.basename(e.name)}`, data: 'junk' })),
];

// the downloads wrapped: a few real students (their own zips, a zip in a zip, loose files), each site's names
const FEW = students.slice(0, 6);
/** `site`'s download of FEW as zip entries ('folders': a folder a student, some with their zip, some loose). */
function fewEntries(site) {
  const entries = [];
  for (const [k, n] of FEW.entries()) {
    const s = { name: `${n} Student`, k };
    const where = (file) => (site === 'folders' ? `${n}/${file}` : siteName(site, s, file));
    if (k % 2 && site !== 'canvas') entries.push(...entriesOf(path.join(HANDINS, n), where('')));
    else entries.push({ name: where('handin.zip'), data: handinZip(n, k) });
  }
  if (site === 'brightspace') entries.push({ name: 'index.html', data: '<table>the listing</table>' });
  return entries;
}

for (const site of ['brightspace', 'canvas', 'moodle', 'folders']) {
  test(`a ${site} download zipped again one folder down (with __MACOSX/), as a zip and unpacked, gives the same class as the download`, () => {
    const dir = mkdtempSync(path.join(os.tmpdir(), `intake-wrapped-${site}-`));
    try {
      const entries = fewEntries(site);
      const top = 'Worksheet 4 Download Oct 11, 2025 803 PM';
      const inputs = {
        download: path.join(dir, 'download.zip'),
        unpacked: path.join(dir, 'unpacked'),
        'zipped again': path.join(dir, 'again.zip'),
        'zipped again, unpacked': path.join(dir, 'again'),
      };
      writeFileSync(inputs.download, makeZip(entries));
      writeEntries(inputs.unpacked, entries);
      writeFileSync(inputs['zipped again'], makeZip(macWrapped(top, entries)));
      writeEntries(inputs['zipped again, unpacked'], macWrapped(top, entries));
      const got = {};
      for (const [how, input] of Object.entries(inputs)) {
        const out = path.join(dir, `out-${how}`);
        mkdirSync(out);
        got[how] = intake(input, out, BOUNDS);
      }
      const want = classOf(got.download);
      assert.equal(got.download.site, site);
      assert.equal(want.length, FEW.length, want.map((s) => s.name).join(', '));
      for (const s of want) assert.ok(s.error === null && Object.values(s.parts).some(Boolean), `${s.name}: parts found (${s.error})`);
      for (const how of ['unpacked', 'zipped again', 'zipped again, unpacked']) {
        assert.equal(got[how].site, site, how);
        assert.deepEqual(classOf(got[how]), want, `${how}: the same students, identities and parts`);
      }
      for (const how of ['zipped again', 'zipped again, unpacked']) assert.ok(got[how].notes.includes(`looked through "${top}/": one folder around the download`), `${how}: ${got[how].notes.join(' | ')}`);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
}

test('a folder of mixed junk is refused, as a folder and as a zip, saying what was found and what each site\'s download looks like', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'intake-junk-'));
  try {
    const junk = [
      { name: 'notes.txt', data: 'remember the milk' }, { name: 'slides.pdf', data: '%PDF' }, { name: 'photo.jpg', data: 'jpeg' },
      { name: 'old stuff/readme.md', data: '# old' }, { name: 'saved page/index.html', data: '<p>a web page</p>' }, { name: 'misc/data.csv', data: 'a,b' },
      { name: '.DS_Store', data: 'junk' }, { name: '__MACOSX/._notes.txt', data: 'junk' },
    ];
    writeEntries(path.join(dir, 'junk'), junk);
    writeFileSync(path.join(dir, 'junk.zip'), makeZip(junk));
    writeFileSync(path.join(dir, 'junk-again.zip'), makeZip(macWrapped('Stuff', junk)));
    for (const input of ['junk', 'junk.zip', 'junk-again.zip']) {
      const out = path.join(dir, `out-${input}`);
      mkdirSync(out);
      assert.throws(() => intake(path.join(dir, input), out, BOUNDS), (err) => {
        assert.ok(err instanceof IntakeError, String(err));
        if (input !== 'junk-again.zip') assert.match(err.message, /holds 3 folder\(s\) \("misc", "old stuff", "saved page"\) and 3 file\(s\) \("notes\.txt", "photo\.jpg", "slides\.pdf"\): no folder holding a zip or a page named as a part/, input);
        for (const site of [/Brightspace .*"<submission id>-<user id> - <name> - <date time>"/, /Canvas .*"<lastfirst>_<user id>_<file id>_<name>"/, /Moodle .*"<Full Name>_<participant id>_assignsubmission_file"/, /a folder a student/]) assert.match(err.message, site, input);
        return true;
      }, input);
      assert.ok(!existsSync(path.join(out, 'handins')) && !existsSync(path.join(out, 'intake.json')), `${input}: nothing taken in`);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a download is never one student: a folder holding a site\'s download beside others, and one student\'s hand-in given as a class, are refused', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'intake-never-one-'));
  try {
    writeEntries(path.join(dir, 'two', 'Section A'), fewEntries('brightspace'));
    writeEntries(path.join(dir, 'two', 'anna'), entriesOf(path.join(HANDINS, FEW[0])));
    const out = path.join(dir, 'out');
    mkdirSync(out);
    assert.throws(() => intake(path.join(dir, 'two'), out, BOUNDS), /"Section A", each a course site's download, beside other folders: a download is never one student/);
    // one student's hand-in (its pages named as parts at the top) is not a class of p1, p2, ...
    writeEntries(path.join(dir, 'one'), [1, 2, 3].map((n) => ({ name: `p${n}/index.html`, data: '<p>' })));
    assert.throws(() => intake(path.join(dir, 'one'), out, BOUNDS), /holds 3 folder\(s\) \("p1", "p2", "p3"\): folders or pages named as parts at the top: one student's hand-in, not a class/);
    // and a class of one is that one student, not the folders of their hand-in
    writeEntries(path.join(dir, 'class of one', 'anna'), [{ name: 'week4/p1.html', data: '<p>' }, { name: 'common/MV.js', data: '' }]);
    assert.deepEqual(intake(path.join(dir, 'class of one'), out, BOUNDS).submissions.map((s) => s.name), ['anna']);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('Moodle\'s feedback zip: each page in the folder the download gave the student, as "download as folders" or loose files', () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'intake-moodle-feedback-'));
  try {
    const s = (k) => ({ name: `${FEW[k]} Student`, k });
    const folders = fewEntries('moodle');
    // Moodle without "download as folders": "<Full Name>_<participant id>_assignsubmission_file_<file>"
    const loose = [{ name: `${s(0).name}_${idsOf(0).uid}_assignsubmission_file_handin.zip`, data: handinZip(FEW[0], 0) }];
    for (const [how, entries] of [['folders', folders], ['loose', loose]]) {
      const input = path.join(dir, `${how}.zip`), out = path.join(dir, `out-${how}`);
      writeFileSync(input, makeZip(entries));
      mkdirSync(out);
      const got = intake(input, out, BOUNDS);
      assert.equal(got.site, 'moodle');
      // mod/assign/feedback/file/importziplib.php reads the participant from the folder's name
      for (const sub of got.submissions) {
        const k = FEW.indexOf(sub.identity.name.replace(/ Student$/, ''));
        assert.equal(feedbackZipPath(sub, 'moodle'), `${s(k).name}_${idsOf(k).uid}_assignsubmission_file/feedback.html`, `${how}: ${sub.name}`);
      }
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
