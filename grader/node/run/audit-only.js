// --audit-only: a graded class judged again from its saved artifacts, with no browser (Lighthouse's
// -A). Each part's result (parts/<submission>/<part>.json) gets the verdict, reasons, numbers and
// pictures its artifact now gives under `rubric`; what was only seen live (the page's errors, what
// was blocked, our reference beside it, the time it took) stays as it was. A part whose gathering
// read a key of the rubric that `rubric` gives another value (a slider's change bound, how many
// controls to try) was gathered as the old rubric would: its result says so (`regather`: the keys),
// and --regather-changed gathers those parts again.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { auditDirs } from './audit-pool.js';
import { applyAudit } from '../../core/part-result.js';
import { PARTS } from '../../files/parts.js';
import { hrefOf } from '../../files/layout.js';

/**
 * Re-judges every part under `out` that has an artifact; `progress(done, total)`. Returns {
 * audited, without, stale: [{ name, part, keys }], unknown: ['name part'] } (the parts to gather
 * again for `rubric`; those gathered before artifacts kept the keys they read, which cannot tell).
 */
export async function auditAgain(out, rubric, progress = () => {}) {
  const partsDir = path.join(out, 'parts');
  const partFiles = (dir) => PARTS.map((part) => ({ dir, part, file: path.join(partsDir, dir, `${part}.json`) }));
  const files = existsSync(partsDir) ? readdirSync(partsDir).sort().flatMap(partFiles)
    .filter((x) => existsSync(x.file)) : [];
  const artifactDir = ({ dir, part }) => path.join(out, 'artifacts', dir, part);
  const judged = await auditDirs(files.map(artifactDir), rubric, { progress });
  let audited = 0;
  const without = [], stale = [], unknown = [];
  for (const x of files) {
    const result = JSON.parse(readFileSync(x.file, 'utf8'));
    const j = judged.get(artifactDir(x));
    if (!j) {
      if (result.status !== 'missing') without.push(`${result.name} ${x.part}`);
      continue;
    }
    applyAudit(
      result,
      j,
      Object.fromEntries(Object.entries(j.files).map(([name, f]) => [name, hrefOf(out, path.join(artifactDir(x), f))])),
    );
    delete result.regather;
    if (j.stale === null) unknown.push(`${result.name} ${x.part}`);
    else if (j.stale.length) {
      result.regather = j.stale;
      stale.push({ name: result.name, part: x.part, keys: j.stale });
    }
    writeFileSync(x.file, JSON.stringify(result, null, 1));
    audited++;
  }
  return { audited, without, stale, unknown };
}

/** What --audit-only says of the parts to gather again (`stale`: auditAgain's), one line a key: "re-gather these 2 parts for `sliderChange`: ada WP04P4, bo WP04P4". */
export function regatherLines(stale) {
  const byKey = new Map();
  for (const s of stale) for (const k of s.keys) byKey.set(k, [...(byKey.get(k) || []), `${s.name} ${s.part}`]);
  return [...byKey].map(([k, parts]) => {
    const one = parts.length === 1;
    return `re-gather ${one ? 'this part' : `these ${parts.length} parts`} for \`${k}\` (${one ? 'its' : 'their'} gathering read it, under another value): ${parts.join(', ')}`;
  });
}
