// --audit-only: a graded class judged again from its saved artifacts, with no browser (Lighthouse's
// -A). Each part's result (parts/<submission>/<part>.json) gets the verdict, reasons, numbers and
// pictures its artifact now gives under `rubric`; what was only seen live (the page's errors, what
// was blocked, our reference beside it, the time it took) stays as it was.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { auditDirs } from './audit-pool.js';
import { applyAudit } from '../core/part-result.js';
import { PARTS } from './parts.js';
import { hrefOf } from './layout.js';

/** Re-judges every part under `out` that has an artifact; `progress(done, total)`. Returns { audited, without }. */
export async function auditAgain(out, rubric, progress = () => {}) {
  const partsDir = path.join(out, 'parts');
  const files = existsSync(partsDir) ? readdirSync(partsDir).sort().flatMap((dir) => PARTS.map((part) => ({ dir, part, file: path.join(partsDir, dir, `${part}.json`) })))
    .filter((x) => existsSync(x.file)) : [];
  const artifactDir = ({ dir, part }) => path.join(out, 'artifacts', dir, part);
  const judged = await auditDirs(files.map(artifactDir), rubric, { progress });
  let audited = 0;
  const without = [];
  for (const x of files) {
    const result = JSON.parse(readFileSync(x.file, 'utf8'));
    const j = judged.get(artifactDir(x));
    if (!j) {
      if (result.status !== 'missing') without.push(`${result.name} ${x.part}`);
      continue;
    }
    applyAudit(result, j, Object.fromEntries(Object.entries(j.files).map(([name, f]) => [name, hrefOf(out, path.join(artifactDir(x), f))])));
    writeFileSync(x.file, JSON.stringify(result, null, 1));
    audited++;
  }
  return { audited, without };
}
