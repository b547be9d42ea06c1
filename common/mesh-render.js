// Our WP04P1 as the browser draws it, drawn in JavaScript: the slides' first step has neither the
// depth test nor back-face culling, so which face shows at a pixel is not geometry but the order
// of the draw: the last triangle that covers the pixel's centre, in the order the mesh was sent.
// No ray–sphere intersection can give that picture (common/exact-render.js assumes the depth test);
// this rasteriser can. The reference the grader puts beside a student's WP04P1 (grader/core/
// reference-state.js) is this picture; tests/unit/self-grade.test.js holds it to our own page.
import { lookAt, mult, perspective } from './math.js';
import { BACKGROUND } from './course.js';

/** Where the GPU puts a vertex: its window position snapped to 1/SUBPIXEL of a pixel (8 bits of sub-pixel precision, as SwiftShader's). */
const SUBPIXEL = 256;

/** clip = P·V·[x, y, z, 1] for every vertex of `positions` (xyz a vertex): [x, y, z, w] a vertex. */
function toClip(camera, aspect, positions) {
  const PV = mult(perspective(camera.fovy, aspect, camera.near, camera.far), lookAt(camera.eye, camera.at, camera.up));
  const n = positions.length / 3;
  const clip = new Float64Array(4 * n);
  for (let v = 0; v < n; v++) {
    const x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
    for (let r = 0; r < 4; r++) clip[4 * v + r] = PV[r] * x + PV[4 + r] * y + PV[8 + r] * z + PV[12 + r];
  }
  return clip;
}

/**
 * The scene's mesh (`positions`: three floats a vertex, three vertices a triangle, as the page sends
 * them) drawn in order with no depth test and no culling, each vertex coloured 0.5·p + 0.5 (the
 * slides' WP04P1) and the colour interpolated perspective-correct, sampled at pixel centres.
 * A triangle with a vertex behind the eye's plane (w ≤ 0) is left out: our WP04P1's camera never
 * sees one. Returns what renderReference returns: { width, height, rgb (3 a pixel, [0, 1], row 0
 * at the top), coverage }.
 * @param {object} scene a page's window.scene (its camera)
 * @param {Float32Array|number[]} positions
 * @param {number} width pixels
 * @param {number} height pixels
 */
export function renderMeshInOrder(scene, positions, width, height) {
  if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
    throw new Error(`renderMeshInOrder: width and height must be positive integers, not ${width}×${height}`);
  }
  const cam = scene.camera;
  const clip = toClip(cam, cam.aspect ?? width / height, positions);
  const rgb = new Float64Array(width * height * 3);
  const coverage = new Uint8Array(width * height);
  const background = BACKGROUND.slice(0, 3);
  for (let p = 0; p < width * height; p++) rgb.set(background, 3 * p);
  // each vertex in the window (row 0 at the top), snapped as the GPU snaps it, with 1/w
  const n = clip.length / 4;
  const sx = new Float64Array(n), sy = new Float64Array(n), iw = new Float64Array(n);
  for (let v = 0; v < n; v++) {
    const w = clip[4 * v + 3];
    iw[v] = w > 0 ? 1 / w : 0;
    sx[v] = Math.round(((clip[4 * v] * iw[v] + 1) * width) / 2 * SUBPIXEL) / SUBPIXEL;
    sy[v] = Math.round(((1 - clip[4 * v + 1] * iw[v]) * height) / 2 * SUBPIXEL) / SUBPIXEL;
  }
  for (let t = 0; t + 2 < n; t += 3) {
    if (!(iw[t] > 0 && iw[t + 1] > 0 && iw[t + 2] > 0)) continue;
    drawTriangle([t, t + 1, t + 2], { sx, sy, iw, positions, rgb, coverage, width, height });
  }
  return { width, height, rgb, coverage };
}

/** One triangle (`tri`: its three vertices' indices) over the pixels whose centres it covers, either winding. */
function drawTriangle(tri, { sx, sy, iw, positions, rgb, coverage, width, height }) {
  const [a, b, c] = tri;
  const area = (sx[b] - sx[a]) * (sy[c] - sy[a]) - (sx[c] - sx[a]) * (sy[b] - sy[a]);
  if (area === 0) return;
  const x0 = Math.max(0, Math.floor(Math.min(sx[a], sx[b], sx[c]) - 0.5));
  const x1 = Math.min(width - 1, Math.ceil(Math.max(sx[a], sx[b], sx[c]) - 0.5));
  const y0 = Math.max(0, Math.floor(Math.min(sy[a], sy[b], sy[c]) - 0.5));
  const y1 = Math.min(height - 1, Math.ceil(Math.max(sy[a], sy[b], sy[c]) - 0.5));
  // the edge functions E = A·x + B·y + C, signed so that the inside is positive whichever way the
  // triangle winds: E_a is 0 on the edge b–c and grows toward a (the screen's barycentric weight of a)
  const s = area > 0 ? 1 : -1;
  const coef = (i, j) => [s * (sy[i] - sy[j]), s * (sx[j] - sx[i]), s * (sx[i] * sy[j] - sx[j] * sy[i])];
  const [Aa, Ba, Ca] = coef(b, c), [Ab, Bb, Cb] = coef(c, a), [Ac, Bc, Cc] = coef(a, b);
  const ia = iw[a], ib = iw[b], ic = iw[c];
  for (let y = y0; y <= y1; y++) {
    const py = y + 0.5;
    for (let x = x0; x <= x1; x++) {
      const px = x + 0.5;
      const ea = Aa * px + Ba * py + Ca, eb = Ab * px + Bb * py + Cb, ec = Ac * px + Bc * py + Cc;
      if (ea < 0 || eb < 0 || ec < 0) continue;
      // perspective-correct weights: the screen's barycentric weights over w, normalised
      const wa = ea * ia, wb = eb * ib, wc = ec * ic, sum = wa + wb + wc;
      const pix = y * width + x;
      for (let k = 0; k < 3; k++) {
        const p = (wa * positions[3 * a + k] + wb * positions[3 * b + k] + wc * positions[3 * c + k]) / sum;
        rgb[3 * pix + k] = 0.5 * p + 0.5; // the slides' WP04P1: c = 0.5·p + 0.5
      }
      coverage[pix] = 1;
    }
  }
}
