// The error measures: how far a picture (a canvas screenshot, RGBA, row 0 at the top) is from the
// exact reference of render.js, as coverage (the silhouette) and as shading error on the interior.
import { BACKGROUND } from '../../common/exact-render.js';

/** A pixel counts as sphere when it is more than this far from the background in some channel. */
const COVERAGE_TOLERANCE = 3 / 255;

/** Whether the RGBA pixel at byte offset o differs from the background by more than the tolerance. */
function showsSphere(data, o, background8, tolerance8) {
  return Math.abs(data[o] - background8[0]) > tolerance8 ||
    Math.abs(data[o + 1] - background8[1]) > tolerance8 ||
    Math.abs(data[o + 2] - background8[2]) > tolerance8;
}

function checkImage(image, ref, who) {
  if (!image || !image.data) throw new Error(`${who}: the picture needs width, height and RGBA data`);
  if (image.width !== ref.width || image.height !== ref.height) {
    throw new Error(`${who}: the picture is ${image.width}×${image.height} but the reference is ${ref.width}×${ref.height}; render the reference at the picture's size`);
  }
  if (image.data.length < 4 * ref.width * ref.height) {
    throw new Error(`${who}: the picture's data holds ${image.data.length} bytes, not ${4 * ref.width * ref.height} (RGBA)`);
  }
}

/**
 * Compares a picture with the reference.
 *  - Silhouette, as coverage: a picture pixel shows the sphere where it is more than 3/255 from
 *    the background in some channel; silhouetteMismatch counts the pixels where that differs from
 *    the reference's coverage, silhouetteMismatchRatio divides it by spherePixels.
 *  - Shading, on interior pixels only (the reference covers the pixel and its 8 neighbours), so
 *    the silhouette's antialiasing-free staircase does not count as shading error: rmse over
 *    all 3 channels and maxError (at maxErrorAt = [i, j]), in units of 0..1 (1/255 is one 8-bit
 *    step). A mesh sphere whose silhouette strays more than a pixel inside the true one shows
 *    background on interior pixels, and that does count, unless options.interior is "both":
 *    then the picture must show sphere on the 3×3 too, and a coarse mesh's silhouette counts
 *    once, as mismatch, not again as shading error.
 *  - nanLike: interior pixels that are pure black where the reference is at least 2/255 in some
 *    channel (what a NaN turns into); saturated: interior pixels at 255 in all channels where the
 *    reference is below 250/255 in some channel.
 * @param {{width: number, height: number, data: ArrayLike<number>}} image RGBA, row 0 at the top
 * @param {{width: number, height: number, rgb: Float64Array, coverage: Uint8Array}} ref
 * @param {{background?: number[], tolerance?: number, interior?: 'reference' | 'both'}} [options]
 *   the background colour (0..1), the coverage tolerance (default 3/255), and whose coverage
 *   makes a pixel interior (default "reference")
 */
export function compareToReference(image, ref, options = {}) {
  checkImage(image, ref, 'compareToReference');
  const { width, height, rgb, coverage } = ref;
  const data = image.data;
  const background8 = (options.background ?? BACKGROUND).map((v) => Math.round(v * 255));
  const tolerance8 = (options.tolerance ?? COVERAGE_TOLERANCE) * 255;
  const interiorRule = options.interior ?? 'reference';
  if (interiorRule !== 'reference' && interiorRule !== 'both') {
    throw new Error(`compareToReference: options.interior must be "reference" or "both", not ${JSON.stringify(interiorRule)}`);
  }
  // image coverage, once per pixel: the 3×3 test below reads it up to nine times
  const shows = new Uint8Array(width * height);
  for (let p = 0; p < width * height; p++) shows[p] = showsSphere(data, 4 * p, background8, tolerance8) ? 1 : 0;
  const mask = interiorRule === 'both' ? shows.map((v, p) => v & coverage[p]) : coverage;
  let spherePixels = 0, interiorPixels = 0, silhouetteMismatch = 0, nanLike = 0, saturated = 0;
  let sum = 0, maxError = 0, maxErrorAt = null;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const p = j * width + i;
      const inRef = coverage[p] === 1;
      if (inRef) spherePixels++;
      if ((shows[p] === 1) !== inRef) silhouetteMismatch++;
      if (!mask[p] || i === 0 || j === 0 || i === width - 1 || j === height - 1) continue;
      if (!(mask[p - width - 1] && mask[p - width] && mask[p - width + 1] && mask[p - 1] && mask[p + 1] &&
        mask[p + width - 1] && mask[p + width] && mask[p + width + 1])) continue;
      interiorPixels++;
      let black = true, white = true, refLit = false, refBelowWhite = false;
      for (let c = 0; c < 3; c++) {
        const v = data[4 * p + c], want = rgb[3 * p + c];
        const e = Math.abs(v / 255 - want);
        sum += e * e;
        if (e > maxError) { maxError = e; maxErrorAt = [i, j]; }
        if (v !== 0) black = false;
        if (v !== 255) white = false;
        if (want >= 2 / 255) refLit = true;
        if (want < 250 / 255) refBelowWhite = true;
      }
      if (black && refLit) nanLike++;
      if (white && refBelowWhite) saturated++;
    }
  }
  return {
    spherePixels,
    interiorPixels,
    rmse: interiorPixels > 0 ? Math.sqrt(sum / (3 * interiorPixels)) : 0,
    maxError,
    maxErrorAt,
    silhouetteMismatch,
    silhouetteMismatchRatio: spherePixels > 0 ? silhouetteMismatch / spherePixels : 0,
    nanLike,
    saturated,
  };
}

/**
 * The shading error of a picture, the measure of SHADING_RMSE (common/shading-table.js), the
 * lab and the tests alike: interior RMSE in 8-bit steps (1 = 1/255) with the silhouette left out
 * (interior "both": a pixel counts where picture and reference both show the sphere on its 3×3).
 */
export function shadingError(image, ref) {
  return compareToReference(image, ref, { interior: 'both' }).rmse * 255;
}

/**
 * How far a mesh of the unit sphere falls inside it at worst (MAX_DEVIATION): 1 − the least
 * distance from the origin to one of its triangles' planes.
 * @param {Float32Array} p x,y,z per vertex, three vertices per triangle
 */
export function meshDeviation(p) {
  let least = 1;
  for (let i = 0; i < p.length; i += 9) {
    const ux = p[i + 3] - p[i], uy = p[i + 4] - p[i + 1], uz = p[i + 5] - p[i + 2];
    const vx = p[i + 6] - p[i], vy = p[i + 7] - p[i + 1], vz = p[i + 8] - p[i + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    least = Math.min(least, (nx * p[i] + ny * p[i + 1] + nz * p[i + 2]) / Math.hypot(nx, ny, nz));
  }
  return 1 - least;
}

/**
 * How far, in pixels, a picture's silhouette strays at worst from the true one, for a camera that
 * looks at the sphere's centre (camera.at = 0): the true silhouette is then the circle of radius
 * R = (height / 2) tan(asin(1 / ‖eye‖)) / tan(fovy / 2) about the picture's centre, and the answer
 * is the largest |r − R| over the pixel centres whose coverage differs from the reference's.
 * @returns {number} pixels (0 when the coverages agree everywhere)
 */
export function silhouetteErrorPx(image, ref, scene) {
  checkImage(image, ref, 'silhouetteErrorPx');
  const { width, height } = ref;
  const cam = scene.camera;
  const background8 = BACKGROUND.map((v) => Math.round(v * 255));
  const R = ((height / 2) * Math.tan(Math.asin(1 / Math.hypot(...cam.eye)))) / Math.tan((cam.fovy * Math.PI) / 360);
  let worst = 0;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const p = j * width + i;
      if (showsSphere(image.data, 4 * p, background8, COVERAGE_TOLERANCE * 255) === (ref.coverage[p] === 1)) continue;
      worst = Math.max(worst, Math.abs(Math.hypot(i + 0.5 - width / 2, j + 0.5 - height / 2) - R));
    }
  }
  return worst;
}
