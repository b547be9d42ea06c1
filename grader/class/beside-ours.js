// Our reference beside a student's judged picture, as the report shows it: the scene our page shows
// for the part's query (reference-state.js) drawn at the student's size, compared pixel by pixel
// (compare-images.js), and what the report says of it. No Node and no files: the command
// (node/run/reference.js) writes the pictures, the class page (grade/) keeps them in the browser.
import { compareImages } from './compare-images.js';
import { referenceQuery, referenceStateOf, referencePicture } from '../core/reference-state.js';

/**
 * `judged` (the student's judged picture, { width, height, data }) beside our `part`: { notes,
 * referenceState, compared: { mismatch, rmse, comparison, mismatchFull, mismatchObject }, reference,
 * diff } (reference and diff: pictures; left out where ours could not be drawn, `notes` says why).
 * `numbers`: the part's; `query`: the rubric's referenceQuery for the part; `draw(part, query,
 * judged)`: referencePicture, or a caller's that keeps its drawings.
 */
export function besideOurs({ part, judged, numbers, rubric, query = {}, draw = referencePicture }) {
  const q = referenceQuery(judged, numbers, rubric.thresholds, query, part);
  const drawing = draw(part, q, judged);
  const notes = drawing.why ? [drawing.why] : [];
  const referenceState = drawing.scene ? referenceStateOf(q, drawing.scene) : null;
  if (!drawing.img) return { notes, referenceState };
  const cmp = compareImages(drawing.img, judged);
  const { mismatch, rmse, comparison, mismatchFull, mismatchObject } = cmp;
  const ours = referenceState && referenceState.level !== null
    ? `our ${part} as it draws (its mesh at level ${referenceState.level}, in order, no depth test)` : 'the exact sphere our page shows';
  const lit = referenceState && referenceState.light ? ', lit from the fitted light' : '';
  notes.push(...cmp.notes, `the reference is ${ours} at the same canvas size${lit}; the difference is evidence, the verdict comes from the checks`);
  const compared = { mismatch, rmse, comparison, mismatchFull, mismatchObject };
  return { notes, referenceState, compared, reference: cmp.reference, diff: cmp.diff };
}

/**
 * Our step beside a graded part's `row` (report.json's, its `images` an object): besideOurs(`args`)
 * said in its notes, its referenceState and its comparison's numbers set, and each of our two
 * pictures (reference, diff) kept by the caller's `keep(name, picture)`, which gives its href.
 * Where ours could not be drawn, the row's notes say why and the grading goes on.
 */
export function beside(row, args, keep) {
  try {
    const ours = besideOurs(args);
    row.notes.push(...ours.notes);
    if (ours.referenceState) row.referenceState = ours.referenceState;
    if (!ours.reference) return;
    Object.assign(row, ours.compared);
    const reference = keep('reference', ours.reference), diff = keep('diff', ours.diff);
    Object.assign(row.images, { reference, diff });
  } catch (err) {
    row.notes.push(`our reference could not be drawn: ${String(err && err.message).split('\n')[0]}`);
  }
}
