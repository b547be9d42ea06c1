#!/usr/bin/env node
// The exact reference renderer. For a page's `window.scene` it casts one ray per pixel centre at the
// unit sphere (centre 0, model matrix identity), in double precision, and evaluates the slides'
// reflection model at the hit point, so that L_o = L_r,d + L_r,s + L_r,a with no mesh, no
// interpolation and no float32 anywhere. Tests, the bench and the grader compare canvases with it.
// Also a small command: node tools/reference.js --help.
import { readFileSync, writeFileSync, realpathSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';

/** The course's clear colour, cornflower blue (gl.clearColor(0.3921, 0.5843, 0.9294, 1)). */
export const BACKGROUND = [0.3921, 0.5843, 0.9294];

/** A pixel counts as sphere when it is more than this far from the background in some channel. */
const COVERAGE_TOLERANCE = 3 / 255;

// ---------------------------------------------------------------------------------------------
// Reading the scene
// ---------------------------------------------------------------------------------------------

/** A scene colour (Le, La, kd, ka, ks): a number (grey) or [r, g, b]; `fallback` when missing. */
function colourOf(value, fallback, name) {
  if (value === undefined || value === null) {
    if (fallback === undefined) throw new Error(`scene.${name} is missing`);
    return [fallback, fallback, fallback];
  }
  if (typeof value === 'number' && Number.isFinite(value)) return [value, value, value];
  if (Array.isArray(value) && value.length === 3 && value.every((v) => typeof v === 'number' && Number.isFinite(v))) {
    return [value[0], value[1], value[2]];
  }
  throw new Error(`scene.${name} must be a number or [r, g, b], not ${JSON.stringify(value)}`);
}

/** A vector of `n` finite numbers. */
function vectorOf(value, n, name) {
  if (!Array.isArray(value) || value.length !== n || !value.every((v) => typeof v === 'number' && Number.isFinite(v))) {
    throw new Error(`scene.${name} must be ${n} numbers, not ${JSON.stringify(value)}`);
  }
  return value;
}

const clamp01 = (x) => (x < 0 ? 0 : x > 1 ? 1 : x);

/**
 * Builds the shading function of a scene once, so that the per-pixel work allocates nothing.
 * The returned function writes the colour of the surface point (x, y, z) into out[o..o+2].
 */
function makeShader(scene) {
  if (scene === null || typeof scene !== 'object') throw new Error('the scene must be an object');
  const shading = scene.shading ?? 'phong';
  if (shading === 'normals') {
    // c = 0.5 n + 0.5 (WP04P1, WP04P2); n = p on the unit sphere
    return (x, y, z, out, o) => {
      const l = Math.hypot(x, y, z);
      out[o] = clamp01(0.5 * (x / l) + 0.5);
      out[o + 1] = clamp01(0.5 * (y / l) + 0.5);
      out[o + 2] = clamp01(0.5 * (z / l) + 0.5);
    };
  }
  if (shading !== 'gouraud' && shading !== 'phong') {
    throw new Error(`scene.shading must be "normals", "gouraud" or "phong", not ${JSON.stringify(shading)}`);
  }
  // Gouraud or Phong shading: the reference evaluates the model exactly at every point either way.
  const model = scene.model ?? 'phong';
  if (model !== 'phong' && model !== 'blinn-phong') {
    throw new Error(`scene.model must be "phong" or "blinn-phong", not ${JSON.stringify(model)}`);
  }
  const blinn = model === 'blinn-phong';
  const [ex, ey, ez] = vectorOf(scene.camera?.eye, 3, 'camera.eye');
  const light = scene.light ?? {};
  const [lx, ly, lz, lw] = vectorOf(light.position, 4, 'light.position');
  const material = scene.material ?? {};
  const Le = colourOf(light.Le, 1, 'light.Le');
  const La = colourOf(light.La, 0, 'light.La'); // WP04P3 has no ambient light
  const kd = colourOf(material.kd, undefined, 'material.kd');
  const ka = material.ka === undefined || material.ka === null ? kd : colourOf(material.ka, undefined, 'material.ka');
  const ks = colourOf(material.ks, 0, 'material.ks'); // WP04P3 has no highlight
  const hasSpecular = ks.some((v) => v !== 0);
  const s = material.s ?? (hasSpecular ? undefined : 1);
  if (typeof s !== 'number' || !Number.isFinite(s) || s < 0) {
    throw new Error(`scene.material.s must be a number ≥ 0 when ks is not 0, not ${JSON.stringify(material.s)}`);
  }
  // L_r,a = k_a L_a, the same at every point
  const ambient = [ka[0] * La[0], ka[1] * La[1], ka[2] * La[2]];

  const directional = lw === 0;
  // directional light: w_i = normalize(−l) everywhere; point light at p_l = l.xyz / l.w
  let dirX = 0, dirY = 0, dirZ = 0;
  if (directional) {
    const l = Math.hypot(lx, ly, lz);
    if (l === 0) throw new Error('scene.light.position: a directional light (w = 0) needs a direction, not (0, 0, 0)');
    dirX = -lx / l; dirY = -ly / l; dirZ = -lz / l;
  }
  const plX = directional ? 0 : lx / lw, plY = directional ? 0 : ly / lw, plZ = directional ? 0 : lz / lw;

  return (x, y, z, out, o) => {
    const nl = Math.hypot(x, y, z);
    const nx = x / nl, ny = y / nl, nz = z / nl; // n = p on the unit sphere

    let wiX = dirX, wiY = dirY, wiZ = dirZ, falloff = 1;
    if (!directional) {
      // w_i = normalize(p_l − p), L_i = L_e / ‖p_l − p‖²
      const tx = plX - x, ty = plY - y, tz = plZ - z;
      const r2 = tx * tx + ty * ty + tz * tz;
      if (r2 > 0) {
        const r = Math.sqrt(r2);
        wiX = tx / r; wiY = ty / r; wiZ = tz / r;
        falloff = 1 / r2;
      } else {
        // The light sits on the point itself: it has no direction there. Every nearby surface
        // point sees it at n · w_i ≤ 0, so, continuously, it lights nothing here.
        wiX = 0; wiY = 0; wiZ = 0; falloff = 0;
      }
    }
    const cosTheta = nx * wiX + ny * wiY + nz * wiZ; // n · w_i

    let diffuse = 0, highlight = 0;
    if (cosTheta > 0) {
      diffuse = cosTheta; // max(n · w_i, 0)
      if (hasSpecular) {
        // w_o = normalize(eye − p)
        let woX = ex - x, woY = ey - y, woZ = ez - z;
        const wol = Math.hypot(woX, woY, woZ);
        if (wol > 0) { woX /= wol; woY /= wol; woZ /= wol; }
        let cosSpec;
        if (blinn) {
          // w_h = normalize(w_i + w_o), cos ψ = n · w_h; no halfway vector when w_i = −w_o
          const hX = wiX + woX, hY = wiY + woY, hZ = wiZ + woZ;
          const hl = Math.hypot(hX, hY, hZ);
          cosSpec = hl > 0 ? (nx * hX + ny * hY + nz * hZ) / hl : 0;
        } else {
          // w_r = 2 (w_i · n) n − w_i, cos φ = w_r · w_o
          const rX = 2 * cosTheta * nx - wiX, rY = 2 * cosTheta * ny - wiY, rZ = 2 * cosTheta * nz - wiZ;
          cosSpec = rX * woX + rY * woY + rZ * woZ;
        }
        // max(cos, 0)^s. A base of 0 gives 0, also for s = 0 (where Math.pow(0, 0) would be 1):
        // the pages' shaders do the same, as GLSL leaves pow(0, 0) undefined. The min() only
        // trims rounding above 1, which a large s would otherwise amplify.
        highlight = cosSpec > 0 ? Math.pow(Math.min(cosSpec, 1), s) : 0;
      }
    }
    // L_o = L_i (k_d max(n·w_i, 0) + k_s max(cos, 0)^s) + k_a L_a, clamped to [0, 1]
    for (let c = 0; c < 3; c++) {
      const Li = Le[c] * falloff;
      const direct = diffuse > 0 || highlight > 0 ? Li * (kd[c] * diffuse + ks[c] * highlight) : 0;
      out[o + c] = clamp01(direct + ambient[c]);
    }
  };
}

/**
 * The exact colour of the unit sphere's surface point p seen from scene.camera.eye.
 *
 * shading "normals": c = 0.5 n + 0.5. Otherwise ("gouraud" or "phong": the exact model either way)
 * the reflection model of the slides, with n = p:
 *   w_i = normalize(−l.xyz) for a directional light (l.w = 0), else normalize(l.xyz / l.w − p);
 *   L_i = L_e, or L_e / ‖l.xyz / l.w − p‖² for a point light;  w_o = normalize(eye − p);
 *   L_r,d = k_d L_i max(n · w_i, 0);
 *   L_r,s = k_s L_i max(w_r · w_o, 0)^s, w_r = 2 (w_i · n) n − w_i          (model "phong"), or
 *   L_r,s = k_s L_i max(n · w_h, 0)^s,  w_h = normalize(w_i + w_o)          (model "blinn-phong",
 *           0 where w_i + w_o = 0);
 *   L_r,a = k_a L_a;  L_o = clamp(L_r,d + L_r,s + L_r,a, 0, 1) per channel.
 * Choices: L_r,s = 0 wherever n · w_i ≤ 0 (no highlight on the side facing away from the light,
 * which Phong's w_r · w_o can otherwise give near the terminator when the light is behind); a
 * cosine of 0 or less gives L_r,s = 0 even for s = 0 (Math.pow(0, 0) is 1, but we take 0^0 = 0
 * there, as the pages do); a point light exactly at p lights nothing.
 * Missing fields: ks and La count as 0, ka as kd, Le as 1; kd and light.position are required
 * for a lit scene, and s when ks is not 0.
 * Le, La, kd, ka, ks may each be a number (grey) or [r, g, b].
 * @param {object} scene a page's window.scene
 * @param {number[]} p a point of the unit sphere, [x, y, z]
 * @returns {number[]} [r, g, b], each in [0, 1]
 */
export function shadePoint(scene, p) {
  const out = [0, 0, 0];
  makeShader(scene)(p[0], p[1], p[2], out, 0);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Rendering
// ---------------------------------------------------------------------------------------------

/**
 * Ray-casts the scene's unit sphere through every pixel centre.
 *
 * Pixel (i, j), row 0 at the TOP, has its centre at NDC x = 2(i + 0.5)/width − 1,
 * y = 1 − 2(j + 0.5)/height; its ray leaves camera.eye along f + x tan(fovy/2) aspect r +
 * y tan(fovy/2) u, with f = normalize(at − eye), r = normalize(f × up), u = r × f (OpenGL's
 * lookAt and perspective). aspect is camera.aspect, else width / height.
 * A hit whose view depth (p − eye) · f is below camera.near or beyond camera.far is clipped.
 * With cullFace (the default) only front faces count: the near root, or with frontFace "cw" the
 * far one (the inside of the back half, as WP04P2 shows); a clipped one leaves the background, so
 * a near plane cutting the sphere shows the background. Without culling the far root shows where
 * the near one is clipped (the inside, still shaded with n = p). The depth test is assumed on:
 * without it, which triangle wins depends on the mesh's draw order, not on geometry.
 *
 * @param {object} scene a page's window.scene
 * @param {number} width pixels
 * @param {number} height pixels
 * @returns {{width: number, height: number, rgb: Float64Array, coverage: Uint8Array}} rgb in
 *   [0, 1], 3 per pixel; coverage 1 where the sphere covers the pixel centre
 */
export function renderReference(scene, width, height) {
  if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
    throw new Error(`renderReference: width and height must be positive integers, not ${width}×${height}`);
  }
  const shade = makeShader(scene);
  const cam = scene.camera;
  const [ex, ey, ez] = vectorOf(cam.eye, 3, 'camera.eye');
  const at = vectorOf(cam.at, 3, 'camera.at');
  const up = vectorOf(cam.up, 3, 'camera.up');
  if (!(cam.fovy > 0 && cam.fovy < 180)) throw new Error(`scene.camera.fovy must be in (0, 180) degrees, not ${cam.fovy}`);
  const aspect = cam.aspect ?? width / height;
  if (!(aspect > 0)) throw new Error(`scene.camera.aspect must be positive, not ${cam.aspect}`);
  const near = cam.near ?? 0, far = cam.far ?? Infinity;

  // the camera basis: f = normalize(at − eye), r = normalize(f × up), u = r × f
  let fx = at[0] - ex, fy = at[1] - ey, fz = at[2] - ez;
  const fl = Math.hypot(fx, fy, fz);
  if (fl === 0) throw new Error('scene.camera: eye and at are the same point');
  fx /= fl; fy /= fl; fz /= fl;
  let rx = fy * up[2] - fz * up[1], ry = fz * up[0] - fx * up[2], rz = fx * up[1] - fy * up[0];
  const rl = Math.hypot(rx, ry, rz);
  if (rl === 0) throw new Error('scene.camera: up is parallel to the view direction');
  rx /= rl; ry /= rl; rz /= rl;
  const ux = ry * fz - rz * fy, uy = rz * fx - rx * fz, uz = rx * fy - ry * fx;

  const tanY = Math.tan((cam.fovy * Math.PI) / 360);
  const tanX = tanY * aspect;
  const cull = scene.cullFace !== false;
  const frontIsInside = scene.frontFace === 'cw'; // our faces wind counter-clockwise seen from outside
  const c = ex * ex + ey * ey + ez * ez - 1; // |eye|² − 1

  const rgb = new Float64Array(width * height * 3);
  const coverage = new Uint8Array(width * height);
  for (let j = 0; j < height; j++) {
    const y = (1 - (2 * (j + 0.5)) / height) * tanY;
    for (let i = 0; i < width; i++) {
      const x = ((2 * (i + 0.5)) / width - 1) * tanX;
      let dx = fx + x * rx + y * ux, dy = fy + x * ry + y * uy, dz = fz + x * rz + y * uz;
      const dl = Math.hypot(dx, dy, dz);
      dx /= dl; dy /= dl; dz /= dl;
      const pix = j * width + i;
      let t = NaN;
      // |eye + t d|² = 1  ⇔  t² + 2 b t + c = 0, b = eye · d. The discriminant b² − c is computed
      // as 1 − ‖h‖², h = eye − b d (the ray's nearest point to the centre): no cancellation near
      // the silhouette. The roots are q and c / q with q = −b − sign(b) √disc: no cancellation either.
      const b = ex * dx + ey * dy + ez * dz;
      const hx = ex - b * dx, hy = ey - b * dy, hz = ez - b * dz;
      const disc = 1 - (hx * hx + hy * hy + hz * hz);
      if (disc >= 0) {
        const q = -b - (b < 0 ? -1 : 1) * Math.sqrt(disc);
        const t1 = q, t2 = q !== 0 ? c / q : 0;
        const tNear = Math.min(t1, t2), tFar = Math.max(t1, t2);
        const cosF = dx * fx + dy * fy + dz * fz; // view depth = t (d · f)
        const visible = (tt) => tt * cosF >= near && tt * cosF <= far;
        if (cull) {
          const front = frontIsInside ? tFar : tNear;
          if (visible(front)) t = front;
        } else if (visible(tNear)) {
          t = tNear;
        } else if (visible(tFar)) {
          t = tFar;
        }
      }
      const o = 3 * pix;
      if (t === t) { // a visible hit (t is not NaN)
        coverage[pix] = 1;
        shade(ex + t * dx, ey + t * dy, ez + t * dz, rgb, o);
      } else {
        rgb[o] = BACKGROUND[0]; rgb[o + 1] = BACKGROUND[1]; rgb[o + 2] = BACKGROUND[2];
      }
    }
  }
  return { width, height, rgb, coverage };
}

// ---------------------------------------------------------------------------------------------
// Pictures
// ---------------------------------------------------------------------------------------------

/**
 * The reference as 8-bit RGBA, row 0 at the top, as a canvas stores it: round(v · 255), alpha 255.
 * @returns {Uint8ClampedArray}
 */
export function toRGBA8(ref) {
  const n = ref.width * ref.height;
  const out = new Uint8ClampedArray(4 * n);
  for (let p = 0; p < n; p++) {
    out[4 * p] = Math.round(ref.rgb[3 * p] * 255);
    out[4 * p + 1] = Math.round(ref.rgb[3 * p + 1] * 255);
    out[4 * p + 2] = Math.round(ref.rgb[3 * p + 2] * 255);
    out[4 * p + 3] = 255;
  }
  return out;
}

/** Writes the reference to `path` as an 8-bit RGBA PNG. */
export function writePNG(path, ref) {
  const png = new PNG({ width: ref.width, height: ref.height });
  png.data = Buffer.from(toRGBA8(ref).buffer);
  writeFileSync(path, PNG.sync.write(png));
}

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

// ---------------------------------------------------------------------------------------------
// The command
// ---------------------------------------------------------------------------------------------

const HELP = `usage: node tools/reference.js --scene scene.json [--width N --height N] --out ref.png [--compare shot.png]

Renders the exact picture of a page's window.scene (saved as JSON): the unit sphere ray-cast per
pixel centre in double precision, shaded with the slides' reflection model, written as a PNG.

  --scene FILE       the scene, as JSON (copy(JSON.stringify(window.scene)) in the page's console)
  --width N          the picture's width in pixels (default: scene.canvas.width)
  --height N         the picture's height in pixels (default: scene.canvas.height)
  --out FILE         where to write the PNG (may be left out when --compare is given)
  --compare FILE     a PNG screenshot of the canvas, same size: prints the comparison as JSON
                     (rmse and maxError in units of 0..1, so 1/255 is one 8-bit step)
  --help             this text

exit codes: 0 done, 1 it failed (the message says why), 2 bad usage`;

class UsageError extends Error {}

function parseArgs(argv) {
  const known = ['scene', 'width', 'height', 'out', 'compare'];
  const opt = {};
  for (let k = 0; k < argv.length; k++) {
    const arg = argv[k];
    if (arg === '--help' || arg === '-h') return { help: true };
    const m = /^--([a-z]+)(?:=(.*))?$/.exec(arg);
    if (!m || !known.includes(m[1])) throw new UsageError(`unknown argument ${JSON.stringify(arg)}`);
    const value = m[2] ?? argv[++k];
    if (value === undefined || value === '') throw new UsageError(`--${m[1]} needs a value`);
    opt[m[1]] = value;
  }
  if (!opt.scene) throw new UsageError('--scene is required');
  if (!opt.out && !opt.compare) throw new UsageError('give --out, --compare or both');
  for (const name of ['width', 'height']) {
    if (opt[name] !== undefined) {
      const n = Number(opt[name]);
      if (!Number.isInteger(n) || n < 1 || n > 16384) throw new UsageError(`--${name} must be a whole number from 1 to 16384, not ${JSON.stringify(opt[name])}`);
      opt[name] = n;
    }
  }
  return opt;
}

function readScene(path) {
  let text;
  try {
    text = readFileSync(path, 'utf8');
  } catch (err) {
    throw new Error(`cannot read the scene ${path}: ${err.code === 'ENOENT' ? 'no such file' : err.message}`, { cause: err });
  }
  try {
    return JSON.parse(text);
  } catch (err) {
    throw new Error(`the scene ${path} is not JSON: ${err.message}`, { cause: err });
  }
}

function readPNG(path) {
  let bytes;
  try {
    bytes = readFileSync(path);
  } catch (err) {
    throw new Error(`cannot read the screenshot ${path}: ${err.code === 'ENOENT' ? 'no such file' : err.message}`, { cause: err });
  }
  try {
    return PNG.sync.read(bytes);
  } catch (err) {
    throw new Error(`the screenshot ${path} is not a PNG: ${err.message}`, { cause: err });
  }
}

/** Runs the command; returns its exit code. */
function main(argv) {
  let opt;
  try {
    opt = parseArgs(argv);
  } catch (err) {
    if (!(err instanceof UsageError)) throw err;
    console.error(`reference: ${err.message}\n\n${HELP}`);
    return 2;
  }
  if (opt.help) {
    console.log(HELP);
    return 0;
  }
  try {
    const scene = readScene(opt.scene);
    const shot = opt.compare ? readPNG(opt.compare) : null;
    const width = opt.width ?? scene?.canvas?.width ?? shot?.width;
    const height = opt.height ?? scene?.canvas?.height ?? shot?.height;
    if (width === undefined || height === undefined) {
      console.error('reference: the scene has no canvas size: give --width and --height');
      return 2;
    }
    const ref = renderReference(scene, width, height);
    if (opt.out) {
      writePNG(opt.out, ref);
      const covered = ref.coverage.reduce((a, v) => a + v, 0);
      console.error(`reference: wrote ${opt.out} (${width}×${height}, the sphere covers ${covered} pixels)`);
    }
    if (shot) console.log(JSON.stringify(compareToReference(shot, ref), null, 2));
    return 0;
  } catch (err) {
    console.error(`reference: ${err.message}`);
    return 1;
  }
}

/** Whether this module is the script node was started with (importing it runs nothing). */
function isMainScript() {
  if (!process.argv[1]) return false;
  try {
    return realpathSync(process.argv[1]) === realpathSync(fileURLToPath(import.meta.url));
  } catch {
    return false;
  }
}

if (isMainScript()) process.exitCode = main(process.argv.slice(2));
