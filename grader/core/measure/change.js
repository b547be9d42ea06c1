// What changed between two pictures: the silhouette (a level), the outline's pixels (a level at
// a fine mesh), the shading inside (a material or light), or anything (the orbit).
import { RGB_MAX } from '../units.js';

/**
 * How much the silhouette changed between two pictures: the relative change of its area, or of
 * its roundness, whichever is more (pixel flips along the edge alone do not count).
 */
export function silhouetteChange(a, b) {
  if (!a || !b || a.width !== b.width || a.height !== b.height || a.blank || b.blank) {
    return a && b && a.blank && b.blank ? 0 : 1;
  }
  return Math.max(Math.abs(a.area - b.area) / Math.max(a.area, b.area), Math.abs(a.roundness - b.roundness) / 3);
}

/**
 * The pixels where two pictures' objects differ (one mask has it, the other not), and how many of
 * them lie at the outline (farther than outlineRadius of the radius from the centre): a finer or coarser
 * mesh at a high level moves only a few outline pixels, too few to change the area or roundness.
 */
export function outlineFlips(a, b, thresholds) {
  if (!a || !b || a.blank || b.blank || a.width !== b.width || a.height !== b.height) return null;
  let flips = 0, atOutline = 0;
  const w = a.width, r = thresholds.outlineRadius * Math.min(a.radius, b.radius);
  for (let p = 0; p < a.mask.length; p++) {
    if (a.mask[p] === b.mask[p]) continue;
    flips++;
    const x = p % w, y = (p - x) / w;
    if (Math.hypot(x + 0.5 - a.cx, y + 0.5 - a.cy) >= r) atOutline++;
  }
  return { flips, atOutline, area: b.area - a.area };
}

/** RMS difference of brightness between two pictures over the pixels inside both objects, within the rubric's coarseSampleRadius of B's radius. */
export function shadingChange(imgA, anA, imgB, anB, thresholds) {
  const maxRho = thresholds.coarseSampleRadius;
  let sum = 0, n = 0;
  const w = imgA.width;
  for (let p = 0; p < anA.mask.length; p++) {
    if (!anA.mask[p] || !anB.mask[p]) continue;
    const x = p % w, y = (p - x) / w;
    if (Math.hypot(x + 0.5 - anB.cx, y + 0.5 - anB.cy) > maxRho * anB.radius) continue;
    const o = 4 * p;
    const ya = (imgA.data[o] + imgA.data[o + 1] + imgA.data[o + 2]) / RGB_MAX,
      yb = (imgB.data[o] + imgB.data[o + 1] + imgB.data[o + 2]) / RGB_MAX;
    sum += (ya - yb) ** 2;
    n++;
  }
  return n ? Math.sqrt(sum / n) : null;
}

/** The share of pixels where two pictures differ by more than rounding (pixelChange, summed over the channels of 0–255). */
export function pictureChange(a, b, thresholds) {
  if (!a || !b || a.width !== b.width || a.height !== b.height) return 1;
  // (read once: the gathering's thresholds are a recorder, gather/reads.js, too slow to ask per pixel)
  const { pixelChange } = thresholds;
  let diff = 0;
  for (let o = 0; o < a.data.length; o += 4) {
    if (
      Math.abs(a.data[o] - b.data[o]) +
        Math.abs(a.data[o + 1] - b.data[o + 1]) +
        Math.abs(a.data[o + 2] - b.data[o + 2]) >
      pixelChange
    ) {
      diff++;
    }
  }
  return diff / (a.width * a.height);
}
