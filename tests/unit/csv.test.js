// The grader's CSV and TSV (grader/files/csv.js over csv-parse and csv-stringify) where a teacher's
// files come in: each site's class list as the site exports it (Brightspace's "#" before ids and
// its BOM, Canvas's "Last, First" and Points Possible row, Moodle's fputcsv quoting and its tab
// choice), labels.tsv and overrides.tsv as a spreadsheet saves them (quoted cells holding a tab, a
// quote or a line break, a BOM, CRLF, comment lines), and what the grader writes read back cell for cell.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { csvText, readRows, readTable } from '../../grader/files/csv.js';
import { matchRoster, parseRoster } from '../../grader/class/roster.js';
import { parseLabels } from '../../grader/node/report/labels.js';
import { parseOverrides } from '../../grader/node/report/overrides.js';
import { overridesText } from '../../grader/class/overrides.js';

const BOM = '\uFEFF';
const crlf = (lines) => `${lines.join('\r\n')}\r\n`;

test('Brightspace\'s grade export as the roster: BOM, CRLF, "#" before ids (leading zeros kept), a quoted name with a comma', () => {
  // Grades → Export, key field Both, user details names and email (the item's column as Brightspace heads it)
  const text = BOM + crlf(['OrgDefinedId,Username,Last Name,First Name,Email,Worksheet 4 Points Grade <Numeric MaxPoints:5>,End-of-Line Indicator',
    '#00012345,#s012345,"Ærø, Jr.",Søren,s012345@student.dtu.dk,,#', '#0099,#s0099,Twombly,Cy,s0099@student.dtu.dk,4,#']);
  const roster = parseRoster(text);
  assert.deepEqual(roster.map((r) => [r.orgDefinedId, r.username, r.email, r.display]), [
    ['00012345', 's012345', 's012345@student.dtu.dk', 'Søren Ærø, Jr.'], ['0099', 's0099', 's0099@student.dtu.dk', 'Cy Twombly']]);
  const subs = [{ name: 'søren', identity: { name: 'Søren Ærø, Jr.', userId: '640601' } }];
  assert.deepEqual(matchRoster(subs, roster), []);
  assert.equal(subs[0].identity.orgDefinedId, '00012345', 'matched on the name, the id with its leading zeros');
});

test('Canvas\'s gradebook export as the roster: BOM, "Last, First" quoted, the Points Possible row, ids as text', () => {
  const text = BOM + ['Student,ID,SIS User ID,SIS Login ID,Section,Worksheet 4 (77)', '    Points Possible,,,,,5.00',
    '"Lovelace, Ada",000123,s0012,ada1,"Hold 1, mandag",4.5', '"O\'Brien ""Bo"", Jr.",640700,s0013,bo,Hold 2,'].join('\n');
  const roster = parseRoster(text);
  const ada = roster.find((r) => r.canvasId === '000123');
  assert.deepEqual([ada.display, ada.sisUserId, ada.sisLoginId, ada.section], ['Ada Lovelace', 's0012', 'ada1', 'Hold 1, mandag']);
  assert.equal(roster.find((r) => r.canvasId === '640700').display, 'Jr. O\'Brien "Bo"', 'a doubled quote inside a quoted cell is one quote');
  const subs = [{ name: 'lovelaceada', identity: { name: 'lovelaceada', userId: '000123' } }];
  assert.deepEqual(matchRoster(subs, roster), []);
  assert.equal(subs[0].identity.sisUserId, 's0012', 'matched on Canvas\'s user id, leading zeros kept');
});

test('Moodle\'s grade export as the roster: fputcsv\'s quoted headers, Surname, comma or tab as the teacher chose', () => {
  // Grades → Export → Plain text file (grade/export/txt, csv_export_writer: PHP's fputcsv quotes a cell with a space)
  const rows = [['First name', 'Surname', 'ID number', 'Institution', 'Department', 'Email address', 'Assignment: Worksheet 4 (Real)', 'Last downloaded from this course'],
    ['Søren', 'Ærø', '007', 'DTU', 'Compute', 'soeren@example.edu', '-', '1760000000'], ['Ada', 'Love, Lace', '0042', 'DTU', '', 'ada@example.edu', '4.00', '1760000000']];
  const fputcsv = (cells, sep) => cells.map((c) => (/[\s",]/.test(c) ? `"${c.replace(/"/g, '""')}"` : c)).join(sep);
  for (const sep of [',', '\t']) {
    const roster = parseRoster(crlf(rows.map((r) => fputcsv(r, sep))));
    assert.deepEqual(roster.map((r) => [r.idNumber, r.email, r.display]), [['007', 'soeren@example.edu', 'Søren Ærø'], ['0042', 'ada@example.edu', 'Ada Love, Lace']], JSON.stringify(sep));
  }
});

test('a roster with a BOM before a quoted header, a line break in a quoted cell, lines ending in CRLF, LF and CR mixed, and blank lines', () => {
  const text = `${BOM}"Student",ID,Section\r\n"Lovelace, Ada",1,"Hold 1\r\nmandag"\n\n,,\r"Twombly, Cy",2,B\r\n`;
  assert.deepEqual(readTable(text), [['Student', 'ID', 'Section'], ['Lovelace, Ada', '1', 'Hold 1\r\nmandag'], ['Twombly, Cy', '2', 'B']]);
  assert.deepEqual(parseRoster(text).map((r) => [r.canvasId, r.section]), [['1', 'Hold 1\r\nmandag'], ['2', 'B']]);
});

test('labels.tsv as a spreadsheet saves it: a BOM, CRLF, quoted reasons with a tab, quotes and a line break; a "#" inside a cell is no comment; lines counted in the file', () => {
  const text = BOM + crlf(['# labels of worksheet 4', 'submission\tpart\tlabel\treasons', 'ann\tWP04P1\tcorrect\t"fine,\tall ""five"" levels\r\nand the buttons"',
    'bob\tWP04P2\tpartial\tthe "Orbit" button (see #3) (unsure)', '', 'cy\tWP04P9\tbroken\tno page']);
  assert.throws(() => parseLabels(text, 'labels.tsv'), /labels\.tsv, line 7: part "WP04P9"/, 'the line in the file, past the comment and the reason\'s line break');
  const labels = parseLabels(text.replace('WP04P9', 'WP04P3'), 'labels.tsv');
  assert.deepEqual(labels.map((l) => [l.submission, l.part, l.label, l.reasons, l.unsure]), [
    ['ann', 'WP04P1', 'correct', 'fine,\tall "five" levels\r\nand the buttons', false],
    ['bob', 'WP04P2', 'partial', 'the "Orbit" button (see #3) (unsure)', true],
    ['cy', 'WP04P3', 'broken', 'no page', false]]);
});

test('overrides.tsv as a spreadsheet saves it: a BOM, CRLF, a quoted note with a tab, quotes and line breaks; a bad line named by its line in the file', () => {
  const text = BOM + crlf(['student\tpart\tverdict\tnote', '# the teacher\'s word', 'Søren Ærø\twp04p2\tcorrect\t"Culling is fine in your view.\r\nSee ""Orbit"",\tthen P3."',
    '#00012345\tWP04P1\tpass\ta comment, by its "#"', '0099\tWP04P5\tfail\tno per-fragment normalise']);
  assert.deepEqual(parseOverrides(text), [
    { student: 'Søren Ærø', part: 'WP04P2', verdict: 'pass', note: 'Culling is fine in your view.\r\nSee "Orbit",\tthen P3.', line: 3 },
    { student: '0099', part: 'WP04P5', verdict: 'fail', note: 'no per-fragment normalise', line: 6 }]);
  assert.throws(() => parseOverrides(text.replace('\tfail\t', '\tgood\t'), 'o.tsv'), /o\.tsv, line 6: verdict "good"/);
  assert.throws(() => parseOverrides(`${BOM}student\tpart\tverdict\r\nann\tWP04P1\t"pass\r\n`, 'o.tsv'), /o\.tsv, line \d+: Quote Not Closed/, 'a quote never closed: the file and the line said');
});

test('the class page\'s overrides.tsv reads back as it was set: a note with a tab, quotes, a comma and a line break; æ/ø/å', () => {
  const set = [{ student: 'Søren Ærø', part: 'WP04P2', verdict: 'pass', note: 'fine,\tsee "Orbit"\nthen P3' }, { student: 'Åse', part: 'WP04P5', verdict: 'fail', note: '' }];
  const text = overridesText(set);
  assert.equal(text.split('\n')[0], 'student\tpart\tverdict\tnote');
  assert.deepEqual(parseOverrides(text), set.map((o, k) => ({ ...o, line: [2, 4][k] })), 'lines counted in the file (the note takes two)');
});

test('what the grader writes reads back cell for cell; a cell is quoted only where it must be', () => {
  const rows = [['name', 'id', 'note'], ['Ærø, Søren', '#007', 'a "quote"'], [' lead', 'trail ', 'two\nlines'], ['cr\ronly', 'tab\tin', ''], ['plain', 0, null]];
  for (const eol of ['\n', '\r\n']) {
    const text = csvText(rows, { eol });
    assert.deepEqual(readTable(text), rows.map((r) => r.map((c) => (c === null ? '' : String(c)))).filter((r) => r.some((c) => c.trim())), JSON.stringify(eol));
    assert.equal(text, ['name,id,note', '"Ærø, Søren",#007,"a ""quote"""', '" lead","trail ","two\nlines"', '"cr\ronly",tab\tin,', 'plain,0,'].join(eol) + eol);
  }
  assert.equal(csvText([['a', 'b'], ['x', '']], { quoted: (row) => row > 0 }), 'a,b\n"x",""\n', 'quoted where the caller says, an empty cell too');
  assert.deepEqual(readRows('a,b\n"x\ny",z\nw,v\n').map((r) => r.line), [1, 2, 4]);
});
