import { readArtifact, listArtifacts } from './grader/node/artifacts.js';
import { auditPart } from './grader/core/audit.js';
import { readFileSync } from 'node:fs';
const rubric = JSON.parse(readFileSync('grader/core/rubric.json', 'utf8'));
let tr = 0, ta = 0;
const slow = [];
for (const { submission, part, dir } of listArtifacts('tests/fixtures/artifacts')) {
  let t0 = Date.now(); const a = readArtifact(dir); const t1 = Date.now(); auditPart(a, rubric); const t2 = Date.now();
  tr += t1 - t0; ta += t2 - t1; slow.push([t2 - t1, submission, part, Object.keys(a.images).length]);
}
console.log('read', tr, 'audit', ta); slow.sort((a, b) => b[0] - a[0]); console.log(slow.slice(0, 8));
