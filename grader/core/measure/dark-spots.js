// P4/P5, s lowered to 0: pixels that went dark where the Phong model cannot darken (pow(0, 0) holes).
import { samples } from './samples.js';
import { RGB_MAX } from '../units.js';

/**
 * Dark spots: pixels inside the sphere that a change of s made much darker than they were, and
 * darker than the diffuse + ambient fit of the judged picture predicts there. Lowering s never
 * darkens a pixel of the Phong or Blinn-Phong model (cos^s grows as s falls for cos in [0, 1]),
 * and no specular term takes light away: such pixels are holes (pow(0, 0) or pow of a negative
 * base, undefined: NaN, black on many GPUs). `img` is the judged picture, `after` the same view
 * with s lowered, `fit` img's diffuseFit.
 */
export function darkSpots(img, an, after, fit, thresholds) {
  const margin = thresholds.darkSpotMargin;
  const { width: w } = img;
  let dark = 0, n = 0;
  for (const s of samples(img, an, thresholds)) {
    const o = 4 * (s.y * w + s.x);
    const before = (img.data[o] + img.data[o + 1] + img.data[o + 2]) / RGB_MAX;
    const now = (after.data[o] + after.data[o + 1] + after.data[o + 2]) / RGB_MAX;
    const pred =
      fit.ambient + fit.diffuse * Math.max(0, s.n[0] * fit.light[0] + s.n[1] * fit.light[1] + s.n[2] * fit.light[2]);
    n++;
    if (now < before - margin && now < pred - margin) dark++;
  }
  return n ? { share: dark / n, count: dark } : null;
}
