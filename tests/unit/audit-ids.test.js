// Every reason carries the id of the audit that said it (grader/core/audits/index.js), and what is
// keyed on a reason (the slide the check page and the feedback page quote, the columns of
// grades.csv) goes by that id, never by the words: reword every reason of a recorded class and the
// slides and the CSV's verdicts and audit ids stay as they were.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { auditDirs } from '../../grader/node/run/audit-pool.js';
import { judgement } from '../../grader/core/part-result.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { AUDITS } from '../../grader/core/audits/index.js';
import { missedSlides } from '../../check/slides.js';
import { gradesCsv } from '../../grader/class/grades-csv.js';
import { PARTS } from '../../grader/core/part-names.js';
import { readTable } from '../../grader/files/csv.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.join(here, '../..');
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
const rubric = mergeRubric(read(path.join(root, 'grader/core/rubric.json')), read(path.join(here, '../fixtures/test-rubric.json')));
// students whose parts give reviews and fails of many kinds (labels.json)
const STUDENTS = ['cy', 'dee', 'eve', 'dmitri', 'mona', 'finn', 'ada'];

/** The recorded students' rows as report.js has them ({ name, passes, parts: [result] }), each part's result as part-result.js makes it; judged once, for both tests below. */
let rows = null;
const recordedRows = async () => rows || (rows = await judgeRows());

async function judgeRows() {
  const dirs = STUDENTS.flatMap((name) => PARTS.map((part) => path.join(RECORDED, name, part))).filter((d) => existsSync(path.join(d, 'facts.json')));
  const judged = await auditDirs(dirs, rubric);
  return STUDENTS.map((name) => {
    const parts = PARTS.map((part) => {
      const j = judged.get(path.join(RECORDED, name, part));
      return { part, ...(j ? judgement(j, j.errors) : { verdict: 'fail', reasons: [], findings: [] }) };
    });
    return { name, passes: parts.filter((p) => p.verdict === 'pass').length, parts };
  });
}

/** What the check page keys on a part's reasons: the slides its cards quote, with the audit that asks each. */
const checkPage = (rows) => rows.map((s) => s.parts.map((r) => missedSlides(r.findings).map(({ slide, note, id }) => ({ slide, note, id }))));
/** grades.csv without its reasons' words: the names, passes, verdicts and audit ids. */
const csvIds = (rows) => readTable(gradesCsv(rows, PARTS)).map((cells) => [...cells.slice(0, 2 + PARTS.length), ...cells.slice(-PARTS.length)]);

test('every reason of a recorded class carries a declared audit id, and the reviews and fails name their slides', async () => {
  const rows = await recordedRows();
  const findings = rows.flatMap((s) => s.parts.flatMap((r) => r.findings));
  assert.ok(findings.length > 100, `${findings.length} findings`);
  for (const f of findings) assert.ok(AUDITS[f.id], `${f.id}: ${f.reason}`);
  for (const s of rows) for (const r of s.parts) assert.deepEqual(r.findings.map((f) => f.reason), r.reasons);
  // reviews and fails of many audits, most naming a sentence
  const asking = findings.filter((f) => f.level === 'review' || f.level === 'fail');
  assert.ok(new Set(asking.map((f) => f.id)).size >= 8, [...new Set(asking.map((f) => f.id))].join(' '));
  assert.ok(checkPage(rows).flat(2).length >= 15, `${checkPage(rows).flat(2).length} slides`);
});

test('reworded reasons leave the check page\'s slides and grades.csv\'s verdicts and audit ids as they were', async () => {
  const rows = await recordedRows();
  const reworded = rows.map((s) => ({ ...s, parts: s.parts.map((r) => {
    const findings = r.findings.map((f, k) => ({ ...f, reason: `${f.level === 'pass' ? '' : `${f.level.toUpperCase()}: `}reworded ${k}` }));
    return { ...r, findings, reasons: findings.map((f) => f.reason) };
  }) }));
  assert.deepEqual(checkPage(reworded), checkPage(rows));
  assert.deepEqual(csvIds(reworded), csvIds(rows));
  // (the CSV's reasons are the words, and change with them)
  assert.notEqual(gradesCsv(reworded, PARTS), gradesCsv(rows, PARTS));
  assert.match(gradesCsv(rows, PARTS).split('\n')[0], /WP04P5_reasons,WP04P1_audits,.*WP04P5_audits$/);
});

test('each audit id said in the code is declared, and each declared one is said somewhere', () => {
  const files = (dir) => readdirSync(path.join(root, dir), { recursive: true }).filter((f) => f.endsWith('.js')).map((f) => path.join(root, dir, f));
  const code = [...files('grader'), ...files('check')].map((f) => readFileSync(f, 'utf8')).join('\n');
  const said = new Set([...code.matchAll(/sayAs\('([a-z-]+)'\)/g)].map((m) => m[1]));
  for (const id of said) assert.ok(AUDITS[id], `sayAs('${id}') has no audit`);
  const declaredOnly = Object.keys(AUDITS).filter((id) => !new RegExp(`'${id}'`).test(code.replace(/^\s+'?[a-z-]+'?: \{ title:.*$/gm, '')));
  assert.deepEqual(declaredOnly, []);
});

test('the grader README\'s sentence table names audits by their ids, every audit that checks a sentence among them', () => {
  const readme = readFileSync(path.join(root, 'grader/README.md'), 'utf8');
  const rows = readme.split('\n').filter((l) => /^\| WP04P\d/.test(l) && l.split(' | ').length >= 4 && readme.indexOf(l) > readme.indexOf('| slide | sentence | audits |'));
  assert.ok(rows.length >= 30, `${rows.length} rows`);
  const named = new Set(rows.flatMap((l) => [...l.split(' | ')[2].matchAll(/`([a-z-]+)`/g)].map((m) => m[1])));
  for (const id of named) assert.ok(AUDITS[id], `the README names ${id}, which no audit declares`);
  const missing = Object.values(AUDITS).filter((a) => a.slide && !named.has(a.id)).map((a) => a.id);
  assert.deepEqual(missing, []);
});
