// Our reference at the student's size, beside theirs: evidence, not the verdict. It is the exact
// render of the scene our page shows for the query (core/reference-state.js), drawn here in Node
// with no browser; a worker keeps each query's picture for the parts that ask again (P1 and P2 ask
// the same of every student at one canvas size).
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { LRUCache } from 'lru-cache';
import { pngBytes } from './png.js';
import { hrefOf } from '../../files/layout.js';
import { referencePicture } from '../../core/reference-state.js';
import { beside } from '../../class/beside-ours.js';
import { addStep } from '../../core/grade-part.js';

// the pictures a worker keeps, in bytes of RGBA: 64 MiB holds 64 drawings at 512×512
export const KEPT_BYTES = 64 * 1024 * 1024;

const drawings = new LRUCache({ maxSize: KEPT_BYTES, sizeCalculation: (d) => (d.img ? d.img.data.length : 0) || 1 });

/** Forgets every drawing kept (for tests). */
export function forgetDrawings() {
  drawings.clear();
}

/** The step of a part's time (result.steps) that our reference takes: drawn after the part's own `seconds`, it is not in them. */
export const REFERENCE_STEP = 'drawing and comparing our reference';

/**
 * Draws (or recalls) our reference for `item`, compares it with graded.images.judged and writes
 * both pictures beside item.resultFile; the time it took goes into result.steps (REFERENCE_STEP).
 */
export async function drawReference({ item, plan, result, graded }) {
  const t0 = Date.now();
  const draw = (part, query, judged) => {
    const key = `${part}?${query}`;
    let drawing = drawings.get(key);
    if (!drawing) drawings.set(key, (drawing = referencePicture(part, query, judged)));
    return drawing;
  };
  // each picture written beside the part's result file
  const keep = (name, img) => {
    const file = path.join(path.dirname(item.resultFile), `${path.basename(item.resultFile, '.json')}-${name}.png`);
    writeFileSync(file, pngBytes(img));
    return hrefOf(plan.out, file);
  };
  const { part, referenceQuery: query } = item;
  const judged = graded.images.judged;
  beside(result, { part, judged, numbers: result.numbers, rubric: plan.rubric, query, draw }, keep);
  addStep(result.steps, REFERENCE_STEP, Date.now() - t0);
}
