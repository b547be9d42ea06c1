// An out folder as `npm run grade` leaves it, made from the RECORDED fixture class
// (tests/fixtures/artifacts/) without a browser: each part's artifact copied in and judged by
// --audit-only's own code, the parts recorded without an artifact (results.json) written as they
// were. For tests of what is made from a graded class (report, grade files, feedback).
import { cpSync, existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { auditAgain } from '../../grader/node/run/audit-only.js';
import { mergeRubric } from '../../grader/core/rubric.js';
import { PARTS } from '../../grader/files/parts.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const RECORDED = path.join(here, '../fixtures/artifacts');
const read = (f) => JSON.parse(readFileSync(f, 'utf8'));
export const testRubric = () => mergeRubric(read(path.join(here, '../../grader/core/rubric.json')), read(path.join(here, '../fixtures/test-rubric.json')));

/** Fills `out` with the recorded parts of `names` and judges them (auditAgain); returns the rubric used. */
export async function recordedOut(out, names) {
  const rubric = testRubric();
  const results = read(path.join(RECORDED, 'results.json'));
  for (const name of names) {
    for (const part of PARTS) {
      const art = path.join(RECORDED, name, part);
      const file = path.join(out, 'parts', name, `${part}.json`);
      mkdirSync(path.dirname(file), { recursive: true });
      if (existsSync(path.join(art, 'facts.json'))) {
        cpSync(art, path.join(out, 'artifacts', name, part), { recursive: true });
        writeFileSync(file, JSON.stringify({ name, part, status: 'ok', file: `${part}/index.html`, errors: [], blocked: [] }));
      } else if (results[name] && results[name][part]) {
        const r = results[name][part];
        writeFileSync(file, JSON.stringify({ name, part, status: r.verdict === 'fail' ? 'failed' : 'ok', verdict: r.verdict, reasons: r.reasons, ...(r.findings ? { findings: r.findings } : {}), api: r.api, pass: r.verdict === 'pass', errors: [], blocked: [], actions: [] }));
      }
    }
  }
  await auditAgain(out, rubric);
  return rubric;
}
