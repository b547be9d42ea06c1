// The audits as declared units (grader/core/audits/unit.js, list.js): each reads only the facts it
// names and says only the ids it declares (audits/strict.js, on recorded parts); a unit
// runs after those whose results it uses; and an audit added in a test (a META and a unit, nothing
// else touched) runs, is said in grades.csv and is listed in the README's table.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { auditPart } from '../../grader/core/audit.js';
import { AUDIT_LIST, orderedUnits } from '../../grader/core/audits/list.js';
import { AUDITS } from '../../grader/core/audits/index.js';
import { unit } from '../../grader/core/audits/unit.js';
import { strictly } from '../../grader/core/audits/strict.js';
import { judgement } from '../../grader/core/part-result.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { PARTS } from '../../grader/core/part-names.js';
import { readArtifact, listArtifacts } from '../../grader/node/run/artifacts.js';
import { gradesCsv } from '../../grader/class/grades-csv.js';
import { readTable } from '../../grader/files/csv.js';
import { auditTable, withTable, README } from '../../tools/audit-table.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
const rubric = mergeRubric(read(path.join(here, '../../grader/core/rubric.json')), read(path.join(here, '../fixtures/test-rubric.json')));

// students whose parts give reviews and fails of many kinds (labels.json); grader-class.test.js
// judges the whole recorded class strictly
const STUDENTS = ['cy', 'dee', 'eve', 'dmitri', 'mona', 'finn', 'ada'];

test('every audit unit reads only the facts it names and says only the ids it declares, and judges as it does unwatched', () => {
  const parts = listArtifacts(RECORDED).filter((p) => STUDENTS.includes(p.submission));
  assert.ok(parts.length >= 30, `${parts.length} recorded parts`);
  const strict = strictly(AUDIT_LIST);
  const wrong = new Set();
  for (const { dir } of parts) {
    const artifact = readArtifact(dir);
    try {
      assert.deepEqual(auditPart(artifact, rubric, { audits: strict }), auditPart(artifact, rubric), dir);
    } catch (err) {
      if (err instanceof assert.AssertionError) throw err;
      wrong.add(err.message);
    }
  }
  assert.deepEqual([...wrong], []);
});

test('the strict run catches a unit that reads a fact it does not name', () => {
  const artifact = readArtifact(path.join(RECORDED, 'ada', 'WP04P1'));
  const sneaky = AUDIT_LIST.map((u) => (u.id !== 'closed' ? u : { ...u, run: (C, results) => (C.facts.sliders, u.run(C, results)) }));
  assert.throws(() => auditPart(artifact, rubric, { audits: strictly(sneaky) }), /the audit unit closed reads facts\.sliders/);
});

test('the list runs each unit after the units whose results it uses, and lists every unit once', () => {
  const ids = AUDIT_LIST.map((u) => u.id);
  assert.equal(new Set(ids).size, ids.length);
  for (const [k, u] of AUDIT_LIST.entries()) for (const x of u.uses) assert.ok(ids.indexOf(x) >= 0 && ids.indexOf(x) < k, `${u.id} uses ${x}`);
  const a = { id: 'a', meta: {}, uses: ['b'], reads: [], run: () => null }, b = { id: 'b', meta: {}, uses: [], reads: [], run: () => null };
  assert.throws(() => orderedUnits([a, b], ['a', 'b']), /a uses b, which run after it/);
  assert.throws(() => orderedUnits([a, b], ['b']), /not in the list: a/);
  assert.deepEqual(orderedUnits([a, b], ['b', 'a']).map((u) => u.id), ['b', 'a']);
});

test('an audit added in a test, a META and a unit, runs, is said in grades.csv and is listed in the README\'s table', () => {
  const META = { 'made-up': { title: 'A made-up audit', failureTitle: 'A made-up miss', description: 'Reads the canvas\'s width.', slide: null, reads: ['facts.canvas'] } };
  const madeUp = unit(META, 'made-up', ({ facts, sayAs }) => sayAs('made-up')('review', `a made-up review of a ${facts.canvas.width}-pixel canvas`));
  const audits = [...AUDIT_LIST, madeUp];
  const artifact = readArtifact(path.join(RECORDED, 'ada', 'WP04P1'));
  const judged = auditPart(artifact, rubric, { audits: strictly(audits) });
  assert.deepEqual(judged.checks.filter((c) => c.id === 'made-up'), [{ id: 'made-up', level: 'review', reason: `a made-up review of a ${artifact.facts.canvas.width}-pixel canvas` }]);
  const parts = PARTS.map((part) => ({ part, ...(part === 'WP04P1' ? judgement(judged) : { verdict: 'pass', reasons: [], findings: [] }) }));
  const [head, row] = readTable(gradesCsv([{ name: 'ada', passes: 4, parts }], PARTS));
  assert.equal(row[head.indexOf('WP04P1')], 'review');
  assert.match(row[head.indexOf('WP04P1_audits')], /(^| )made-up( |$)/);
  assert.match(auditTable(audits), /\| `made-up` \| `made-up`: A made-up audit \| `canvas` \| — \|$/m);
  assert.match(auditTable(audits), /^- `made-up`: \*\*A made-up audit\*\*; missed: \*A made-up miss\*\. Reads the canvas's width\.$/m);
  // without it, the README's table is the list's as it stands
  const readme = readFileSync(README, 'utf8');
  assert.equal(withTable(readme, AUDIT_LIST), readme, 'the README\'s table of audit units is out of date: run node tools/audit-table.js');
  assert.doesNotMatch(readme, /made-up/);
});

test('every audit has the title a part that misses it gets and what it checks, in words; a unit without them is refused', () => {
  for (const a of Object.values(AUDITS)) {
    assert.ok(a.failureTitle && a.description, `${a.id} has no failureTitle or description`);
    assert.notEqual(a.failureTitle, a.title, a.id);
    assert.match(a.description, /^[A-Z].*\.$/, `${a.id}: a sentence`);
  }
  assert.throws(() => unit({ x: { title: 'X', slide: null, reads: [] } }, 'x', () => null), /the audit x declares no failureTitle or description/);
});
