// Comparing a submission's canvas with the reference's (pictures { width, height, data: RGBA } of
// one size): pixelmatch over the whole picture, and over the object only (each picture's
// background estimated from its corners and masked out), since students pick their own clear
// colours. No Node: the command (node/run/reference.js) and the class page (grade/) compare alike.
import pixelmatch from 'pixelmatch';

// The most common colour among the four corners' 3×3 patches.
function background(img) {
  const counts = new Map();
  const { width: w, height: h, data } = img;
  for (const [cx, cy] of [[1, 1], [w - 2, 1], [1, h - 2], [w - 2, h - 2]]) {
    for (let dy = -1; dy <= 1; dy++) {
      for (let dx = -1; dx <= 1; dx++) {
        const x = Math.min(w - 1, Math.max(0, cx + dx)), y = Math.min(h - 1, Math.max(0, cy + dy));
        const o = 4 * (y * w + x);
        const key = `${data[o]},${data[o + 1]},${data[o + 2]}`;
        counts.set(key, (counts.get(key) || 0) + 1);
      }
    }
  }
  return [...counts.entries()].sort((a, b) => b[1] - a[1])[0][0].split(',').map(Number);
}

const near = (data, o, c, tol) =>
  Math.abs(data[o] - c[0]) + Math.abs(data[o + 1] - c[1]) + Math.abs(data[o + 2] - c[2]) <= tol;

/**
 * @returns {{mismatch, mismatchFull, mismatchObject, rmse, comparison: 'full'|'object-only', notes: string[],
 *   reference, submission, diff}} mismatch is a fraction 0..1 of the pixels compared; the pictures
 *   are { width, height, data }
 */
export function compareImages(reference, submission) {
  const { width, height } = reference;
  if (submission.width !== width || submission.height !== height) throw new Error('compareImages: the pictures must have one size');
  const n = width * height;
  const notes = [];
  const diff = { width, height, data: new Uint8Array(4 * n) };
  const mismatchFull = pixelmatch(reference.data, submission.data, diff.data, width, height, { threshold: 0.1 }) / n;

  const bgRef = background(reference), bgSub = background(submission);
  // the object: pixels away from their own picture's background; compared with both backgrounds
  // painted black, counted over the union of the two objects
  const a = Uint8Array.from(reference.data), b = Uint8Array.from(submission.data);
  const union = new Uint8Array(n);
  let unionCount = 0;
  for (let p = 0; p < n; p++) {
    const o = 4 * p;
    const inRef = !near(reference.data, o, bgRef, 12), inSub = !near(submission.data, o, bgSub, 12);
    if (!inRef) a[o] = a[o + 1] = a[o + 2] = 0;
    if (!inSub) b[o] = b[o + 1] = b[o + 2] = 0;
    if (inRef || inSub) { union[p] = 1; unionCount++; }
  }
  const mask = new Uint8Array(4 * n);
  pixelmatch(a, b, mask, width, height, { threshold: 0.1, diffMask: true });
  let objectDiff = 0, sum = 0;
  for (let p = 0; p < n; p++) {
    if (!union[p]) continue;
    if (mask[4 * p + 3] > 0) objectDiff++;
    for (let c = 0; c < 3; c++) {
      const e = (a[4 * p + c] - b[4 * p + c]) / 255;
      sum += e * e;
    }
  }
  const mismatchObject = unionCount ? objectDiff / unionCount : (mismatchFull > 0 ? 1 : 0);
  const rmse = unionCount ? Math.sqrt(sum / (3 * unionCount)) : 0;
  const sameBackground =
    Math.abs(bgRef[0] - bgSub[0]) + Math.abs(bgRef[1] - bgSub[1]) + Math.abs(bgRef[2] - bgSub[2]) <= 12;
  if (!sameBackground) notes.push(`backgrounds differ (reference rgb(${bgRef}), submission rgb(${bgSub})): the object alone is compared`);
  if (unionCount === 0) notes.push('no object in either picture: only backgrounds');
  const comparison = sameBackground ? 'full' : 'object-only';
  const mismatch = comparison === 'full' ? mismatchFull : mismatchObject;
  return { mismatch, mismatchFull, mismatchObject, rmse, comparison, notes,
    reference, submission, diff };
}
