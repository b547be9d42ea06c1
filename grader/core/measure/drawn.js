// What a picture shows off its background before thin lines are opened away (measure/silhouette.js
// opens them): how many pixels, and whether they are one colour. A picture that is blank to the
// silhouette but not one colour shows lines, points or text, not a solid object.

/**
 * The pixels off the background `bg` by more than `tol` (summed over channels): { pixels, spread }.
 * spread is how far apart their colours are, each taken as its direction away from the background
 * (c − bg over the sum of its channels' sizes), so that a line's edges, blended with the background
 * by antialiasing, count as the line's colour: the widest channel's range, 0 (one colour) to 2.
 */
export function drawnPixels(img, bg, tol) {
  const { data } = img;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  let pixels = 0;
  for (let o = 0; o < data.length; o += 4) {
    const d = [data[o] - bg[0], data[o + 1] - bg[1], data[o + 2] - bg[2]];
    const size = Math.abs(d[0]) + Math.abs(d[1]) + Math.abs(d[2]);
    if (size <= tol) continue;
    pixels++;
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], d[k] / size);
      hi[k] = Math.max(hi[k], d[k] / size);
    }
  }
  return { pixels, spread: pixels ? Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) : 0 };
}
