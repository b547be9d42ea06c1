// The exact reference renderer. For a page's `window.scene` it casts one ray per pixel centre at the
// unit sphere (centre 0, model matrix identity), in double precision, and evaluates the slides'
// reflection model at the hit point, so that L_o = L_r,d + L_r,s + L_r,a with no mesh, no
// interpolation and no float32 anywhere. Plain JavaScript; its one import is the course's clear
// colour. The error measures and PNG files (tools/reference/), the command (tools/reference.js),
// the tests, the bench and the grader's reference picture (grader/core/reference-state.js) build on it.
import { BACKGROUND as CLEAR } from './course.js';

/** The course's clear colour, RGB (common/course.js). */
export const BACKGROUND = CLEAR.slice(0, 3);

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
