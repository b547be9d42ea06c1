// Our reference at the student's size, beside theirs: evidence, not the verdict. Our page draws
// the same pixels for the same query (the page contract: time frozen, orbit 0, everything else in
// the URL), so a worker draws each query once and keeps the picture for the parts that ask again
// (P1 and P2 ask the same of every student at one canvas size).
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { LRUCache } from 'lru-cache';
import { compareImages } from './compare.js';
import { pngBytes } from './png.js';
import { hrefOf } from '../../files/layout.js';
import { referenceQuery, referenceStateOf, referencePicture, untilDrawn } from '../../core/reference-state.js';
import { addStep } from '../../core/grade-part.js';

// the pictures a worker keeps, in bytes of RGBA: 64 MiB holds 64 drawings at 512×512
export const KEPT_BYTES = 64 * 1024 * 1024;

const drawings = new LRUCache({ maxSize: KEPT_BYTES, sizeCalculation: (drawing) => drawing.img.data.length || 1 });

/** Forgets every drawing kept (for tests). */
export function forgetDrawings() {
  drawings.clear();
}

/**
 * Our page for `query` drawn in a page that openers.reference opens: { opened, img, why, scene,
 * complete }. img is null where it drew nothing; complete says nothing failed (a failure after the
 * picture was taken keeps the picture, but the drawing is not kept for other parts).
 */
async function drawOurs({ item, plan, openers, query, judged, notes }) {
  const refLog = { errors: [], blocked: [], notes: [] };
  const drawing = { opened: false, img: null, why: null, scene: null };
  try {
    const rel = `${item.part}/index.html`;
    const { loadSeconds } = plan.rubric;
    const r = await openers.reference.open({ root: plan.repo, rel, query: query.toString(), loadSeconds, log: refLog });
    if (!r.why) {
      // (our pages publish window.scene after each frame drawn: the picture waits for one)
      const shows = () => r.page.evaluate(() => !!(window.scene && window.scene.frame >= 1)).catch(() => false);
      const drawn = await referencePicture(r.driver, judged, () =>
        untilDrawn(shows, r.driver, plan.rubric.firstFrameSeconds),
      );
      Object.assign(drawing, { img: drawn.img, why: drawn.why });
      drawing.scene = await r.page.evaluate(() => window.scene || null).catch(() => null);
      drawing.opened = true;
    }
    await openers.reference.done(true);
    return { ...drawing, complete: true };
  } catch (err) {
    await openers.reference.done(false);
    notes.push(`our reference could not be drawn: ${err.message.split('\n')[0]}`);
    return drawing;
  }
}

/** The step of a part's time (result.steps) that our reference takes: drawn after the part's own `seconds`, it is not in them. */
export const REFERENCE_STEP = 'drawing and comparing our reference';

/**
 * Draws (or recalls) our reference for `item`, compares it with graded.images.judged and writes
 * both pictures beside item.resultFile; the time it took goes into result.steps (REFERENCE_STEP).
 */
export async function drawReference(args) {
  const t0 = Date.now();
  try {
    await compareWithOurs(args);
  } finally {
    addStep(args.result.steps, REFERENCE_STEP, Date.now() - t0);
  }
}

async function compareWithOurs({ item, plan, openers, result, graded }) {
  const judged = graded.images.judged;
  const query = referenceQuery(judged, result.numbers, plan.rubric.thresholds, item.referenceQuery);
  const key = `${plan.browser || 'chromium'}|${plan.repo}|${item.part}?${query}`;
  let drawing = drawings.get(key);
  if (!drawing) {
    drawing = await drawOurs({ item, plan, openers, query, judged, notes: result.notes });
    if (drawing.complete && drawing.img) drawings.set(key, drawing);
  }
  if (drawing.why) result.notes.push(drawing.why);
  if (drawing.opened) result.referenceState = referenceStateOf(query, drawing.scene);
  if (!drawing.img) return;
  const cmp = compareImages(drawing.img, judged);
  const { mismatch, rmse, comparison, mismatchFull, mismatchObject } = cmp;
  Object.assign(result, { mismatch, rmse, comparison, mismatchFull, mismatchObject });
  result.notes.push(...cmp.notes, `the reference is our page at the same canvas size${result.referenceState && result.referenceState.light ? ', lit from the fitted light' : ''}; the difference is evidence, the verdict comes from the checks`);
  const dir = path.dirname(item.resultFile);
  const stem = path.basename(item.resultFile, '.json');
  const reference = path.join(dir, `${stem}-reference.png`), diff = path.join(dir, `${stem}-diff.png`);
  writeFileSync(reference, pngBytes(cmp.reference));
  writeFileSync(diff, pngBytes(cmp.diff));
  Object.assign(result.images, { reference: hrefOf(plan.out, reference), diff: hrefOf(plan.out, diff) });
}
