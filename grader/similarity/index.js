// The similarity check of a class, as the grader's command runs it: the code's pairs (compare.js)
// and the pictures' (pictures.js), in one list, highest first. A pointer for a person, never a verdict.
import { compareClass, DEFAULTS } from './compare.js';
import { samePictures } from './pictures.js';
import { PARTS, findParts } from '../files/parts.js';

export { DEFAULTS };

/**
 * `submissions` [{ name, root }]; `out` a grading out folder whose pictures are read (or null);
 * `options` as compare.js DEFAULTS. Every pair is { a, b, score, overall, parts, fragments,
 * samePictures: [part], listed }.
 */
export async function similarity(submissions, out, options = {}, progress) {
  const r = await compareClass(submissions, findParts, options, progress);
  const byKey = new Map(r.pairs.map((p) => [[p.a, p.b].sort().join('\u0000'), p]));
  for (const [key, parts] of samePictures(out, submissions.map((s) => s.name), PARTS)) {
    if (!byKey.has(key)) {
      const [a, b] = key.split('\u0000');
      const p = { a, b, score: 0, overall: 0, parts: {}, fragments: [], fragmentCount: 0 };
      byKey.set(key, p);
      r.pairs.push(p);
    }
    Object.assign(byKey.get(key), { samePictures: parts, listed: true });
  }
  r.pairs.sort((p, q) => q.score - p.score || (q.samePictures?.length || 0) - (p.samePictures?.length || 0));
  return r;
}
