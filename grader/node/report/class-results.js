// A graded class as the report reads it: every part's result in OUT/parts/<student>/<part>.json
// (all shards, once their out folders are copied together), a student a row, each with all five
// parts (one not graded in this run says so).
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { PARTS } from '../../files/parts.js';
import { withFindings } from '../../core/part-result.js';

/** The students graded under `partsDir` (OUT/parts): [{ name, parts: [result, ...] }], parts in order. */
export function readClass(partsDir) {
  const byName = new Map();
  for (const dir of readdirSync(partsDir).sort()) {
    for (const part of PARTS) {
      const f = path.join(partsDir, dir, `${part}.json`);
      if (!existsSync(f)) continue;
      const r = JSON.parse(readFileSync(f, 'utf8'));
      if (!byName.has(r.name)) byName.set(r.name, { name: r.name, parts: [] });
      byName.get(r.name).parts.push(r);
    }
  }
  for (const s of byName.values()) {
    for (const part of PARTS) {
      if (!s.parts.some((p) => p.part === part)) {
        const notGraded = { id: 'not-graded-in-run', level: 'fail', reason: 'not graded in this run' };
        s.parts.push({ ...withFindings({ name: s.name, part, status: 'not graded here', verdict: 'fail' }, [notGraded]),
          api: null, actions: [], mismatch: null, rmse: null, pass: false, errors: [], blocked: [] });
      }
    }
    s.parts.sort((a, b) => a.part.localeCompare(b.part));
  }
  return [...byName.values()];
}
