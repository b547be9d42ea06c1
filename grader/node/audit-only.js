// --audit-only: a graded class judged again from its saved artifacts, with no browser (Lighthouse's
// -A). Each part's result (parts/<submission>/<part>.json) gets the verdict, reasons, numbers and
// pictures its artifact now gives under `rubric`; what was only seen live (the page's errors, what
// was blocked, our reference beside it, the time it took) stays as it was.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { readArtifact } from './artifacts.js';
import { applyAudit } from './part-result.js';
import { judged } from '../core/grade-part.js';
import { PARTS } from './parts.js';

/** Re-judges every part under `out` that has an artifact; `progress(done, total)`. Returns { audited, without }. */
export function auditAgain(out, rubric, progress = () => {}) {
  const partsDir = path.join(out, 'parts');
  const files = existsSync(partsDir) ? readdirSync(partsDir).sort().flatMap((dir) => PARTS.map((part) => ({ dir, part, file: path.join(partsDir, dir, `${part}.json`) })))
    .filter((x) => existsSync(x.file)) : [];
  let audited = 0;
  const without = [];
  for (const [k, { dir, part, file }] of files.entries()) {
    progress(k, files.length);
    const result = JSON.parse(readFileSync(file, 'utf8'));
    const artifactDir = path.join(out, 'artifacts', dir, part);
    const artifact = readArtifact(artifactDir);
    if (!artifact) {
      if (result.status !== 'missing') without.push(`${result.name} ${part}`);
      continue;
    }
    const rel = path.relative(out, artifactDir).split(path.sep).join('/');
    const byName = Object.fromEntries(Object.entries(artifact.files).map(([name, f]) => [name, `${rel}/${f}`]));
    applyAudit(result, judged(artifact, rubric), byName);
    writeFileSync(file, JSON.stringify(result, null, 1));
    audited++;
  }
  return { audited, without };
}
