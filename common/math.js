// Vector and matrix math for the exercises, with the names students know from the textbook's
// MV.js (vec4, mat4, mult, lookAt, perspective, normalMatrix, flatten, ...) but our own code.
//
// - Every vector and matrix is a Float32Array. Matrices are COLUMN-MAJOR: element (row r,
//   column c) of a mat4 is m[4*c + r], of a mat3 m[3*c + r]. So a matrix goes to
//   gl.uniformMatrix4fv(loc, false, m) as it is: no flatten, no transpose.
// - A function that makes a vector or matrix takes an optional last argument `out`, fills it
//   and returns it; only without `out` does it allocate. `out` may be one of the inputs
//   (mult(V, M, V) is fine). With `out` given, nothing here allocates, so a draw loop can
//   call lookAt, mult and normalMatrix every frame without making garbage.
// - Mistakes throw an Error that says what was wrong (never a string, never NaNs).
//
// What is here, group by group in the file's order (MV.js's names; * marks what the pages use):
//   making vectors and matrices   vec2, vec3, vec4, mat3*, mat4*
//   component by component        add, subtract, scale (s·v), negate, dot, cross, length,
//                                 normalize, radians
//   products                      mult (matrix·matrix, matrix·vector)
//   transpose and inverse         transpose, det, inverse, normalMatrix* (N = (M^T)^-1)
//   transformations               translate, scalem, rotate, rotateX, rotateY, rotateZ
//   camera and projection         lookAt*, perspective*, ortho
//   for WebGL                     flatten, equal
// The exercise pages need five of these. The rest is here because this file stands in for MV.js
// in the students' own hand-ins, which build model matrices (translate, rotate, scalem, mult) the
// book's way. tests/unit/math.test.js checks every export against gl-matrix.

const F32 = Float32Array;

/** @typedef {Float32Array} Vec  a vec2, vec3 or vec4 */
/** @typedef {Float32Array} Mat  a mat3 (9 numbers) or mat4 (16 numbers), column-major */
/** @typedef {ArrayLike<number>} Vecish  any array-like of numbers: a Vec, a plain array, ... */

// `out` if given (and of the right size), else a new Float32Array of n numbers.
function target(out, n, who) {
  if (out === undefined || out === null) return new F32(n);
  if (out.length !== n) throw new Error(`${who}: out has ${out.length} elements, needs ${n}`);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Making vectors and matrices: vec2, vec3, vec4, mat3, mat4
// MV.js's constructors, with its argument conventions (vec4's w = 1, matrices written row by row).
// These always allocate: they are for set-up, not for the draw loop.

// The arguments of vec2/3/4 as MV.js reads them: numbers and array-likes, spread in order.
function components(n, args, who, lastDefault) {
  const v = new F32(n);
  let k = 0;
  for (const a of args) {
    if (typeof a === 'number') {
      if (k < n) v[k] = a;
      k++;
    } else if (a && typeof a === 'object' && typeof a.length === 'number') {
      for (let i = 0; i < a.length; i++, k++) {
        if (typeof a[i] !== 'number') throw new Error(`${who}: element ${i} of an argument is not a number`);
        if (k < n) v[k] = a[i];
      }
    } else {
      throw new Error(`${who}: arguments must be numbers or arrays of numbers, got ${typeof a}`);
    }
  }
  if (k < n && lastDefault !== 0) v[n - 1] = lastDefault;
  return v;
}

/**
 * A 2-vector. Missing components are 0; array arguments are spread, as in MV.js.
 * @param {...(number|Vecish)} args  e.g. vec2(), vec2(1, 2), vec2([1, 2])
 * @returns {Vec} a new Float32Array(2)
 */
export function vec2(...args) { return components(2, args, 'vec2', 0); }

/**
 * A 3-vector. Missing components are 0; array arguments are spread, as in MV.js.
 * @param {...(number|Vecish)} args  e.g. vec3(), vec3(1, 2, 3), vec3([1, 2, 3]), vec3(v4) (its xyz)
 * @returns {Vec} a new Float32Array(3)
 */
export function vec3(...args) { return components(3, args, 'vec3', 0); }

/**
 * A 4-vector, as MV.js makes it: missing x, y, z are 0 and a missing w is 1, so vec4(x, y, z)
 * is the POINT (x, y, z, 1) and vec4() is (0, 0, 0, 1). Write the w yourself for a direction:
 * vec4(x, y, z, 0). Array arguments are spread: vec4(v3, 0), vec4([x, y, z, w]).
 * Components beyond the fourth are ignored.
 * @param {...(number|Vecish)} args
 * @returns {Vec} a new Float32Array(4)
 */
export function vec4(...args) { return components(4, args, 'vec4', 1); }

// matN(): identity; matN(s): s on the diagonal; matN(n*n numbers) or matN(n rows) read row by
// row, as MV.js writes them, and stored column by column.
function matrix(n, args, who) {
  const m = new F32(n * n);
  if (args.length <= 1) {
    const s = args.length ? args[0] : 1;
    if (typeof s !== 'number') {
      throw new Error(`${who}: give no arguments, one number, ${n * n} numbers or ${n} rows, row by row ` +
        '(to copy a matrix use m.slice())');
    }
    for (let i = 0; i < n; i++) m[i * n + i] = s;
    return m;
  }
  let k = 0;
  const put = (x) => {
    if (typeof x !== 'number') throw new Error(`${who}: element ${k} is not a number`);
    if (k < n * n) m[(k % n) * n + Math.floor(k / n)] = x; // k-th number read = row k/n, column k%n
    k++;
  };
  for (const a of args) {
    if (typeof a === 'number') put(a);
    else if (a && typeof a.length === 'number') for (let i = 0; i < a.length; i++) put(a[i]);
    else put(a);
  }
  if (k !== n * n) throw new Error(`${who}: needs ${n * n} numbers (row by row), got ${k}`);
  return m;
}

/**
 * A 3×3 matrix: the identity, s·I, or nine numbers (or three rows) written ROW BY ROW as in
 * MV.js, stored column-major: mat3(a, b, c, d, e, f, g, h, i) has first row (a, b, c).
 * @param {...(number|Vecish)} args
 * @returns {Mat} a new Float32Array(9)
 */
export function mat3(...args) { return matrix(3, args, 'mat3'); }

/**
 * A 4×4 matrix: the identity, s·I, or sixteen numbers (or four rows) written ROW BY ROW as in
 * MV.js, stored column-major: in mat4(1,0,0,tx, 0,1,0,ty, 0,0,1,tz, 0,0,0,1) the translation
 * ends up in m[12], m[13], m[14].
 * @param {...(number|Vecish)} args
 * @returns {Mat} a new Float32Array(16)
 */
export function mat4(...args) { return matrix(4, args, 'mat4'); }

// ---------------------------------------------------------------------------------------------
// Component by component: add, subtract, scale, negate, dot, cross, length, normalize, radians
// Vector algebra; add, subtract, scale and negate work on matrices too.

function sameLength(a, b, who) {
  if (a.length !== b.length) throw new Error(`${who}: sizes differ (${a.length} and ${b.length})`);
}

/**
 * a + b, component by component (two vectors, or two matrices, of one size).
 * @param {Vecish} a @param {Vecish} b @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function add(a, b, out) {
  sameLength(a, b, 'add');
  const r = target(out, a.length, 'add');
  for (let i = 0; i < a.length; i++) r[i] = a[i] + b[i];
  return r;
}

/**
 * a − b, component by component (two vectors, or two matrices, of one size).
 * @param {Vecish} a @param {Vecish} b @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function subtract(a, b, out) {
  sameLength(a, b, 'subtract');
  const r = target(out, a.length, 'subtract');
  for (let i = 0; i < a.length; i++) r[i] = a[i] - b[i];
  return r;
}

/**
 * s·v, the scalar FIRST as in MV.js (works on matrices too).
 * @param {number} s @param {Vecish} v @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function scale(s, v, out) {
  if (typeof s !== 'number') throw new Error('scale: the scalar comes first, scale(s, v)');
  const r = target(out, v.length, 'scale');
  for (let i = 0; i < v.length; i++) r[i] = s * v[i];
  return r;
}

/**
 * −v.
 * @param {Vecish} v @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function negate(v, out) {
  const r = target(out, v.length, 'negate');
  for (let i = 0; i < v.length; i++) r[i] = -v[i];
  return r;
}

/**
 * The dot product a · b of two vectors of one size.
 * @param {Vecish} a @param {Vecish} b
 * @returns {number}
 */
export function dot(a, b) {
  sameLength(a, b, 'dot');
  let s = 0;
  for (let i = 0; i < a.length; i++) s += a[i] * b[i];
  return s;
}

/**
 * The cross product a × b of the xyz parts (a vec4 is read as its x, y, z).
 * @param {Vecish} a @param {Vecish} b @param {Float32Array} [out] a vec3
 * @returns {Vec} out, or a new vec3
 */
export function cross(a, b, out) {
  const ax = a[0], ay = a[1], az = a[2], bx = b[0], by = b[1], bz = b[2];
  const r = target(out, 3, 'cross');
  r[0] = ay * bz - az * by;
  r[1] = az * bx - ax * bz;
  r[2] = ax * by - ay * bx;
  return r;
}

/**
 * The Euclidean length |v| over all components.
 * @param {Vecish} v
 * @returns {number}
 */
export function length(v) {
  let s = 0;
  for (let i = 0; i < v.length; i++) s += v[i] * v[i];
  return Math.sqrt(s);
}

/**
 * v / |v| over ALL components (a vec4 is normalised with its w; for a direction in a vec4
 * use w = 0, or normalize(vec3(v))). The zero vector gives zeros, never NaN.
 * Unlike MV.js there is no `excludeLastComponent` flag: the second argument is `out`.
 * @param {Vecish} v @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function normalize(v, out) {
  if (typeof out === 'boolean') {
    throw new Error("normalize: no excludeLastComponent flag here; normalize(vec3(v)) normalises v's xyz");
  }
  const len = length(v);
  const k = len > 0 ? 1 / len : 0;
  const r = target(out, v.length, 'normalize');
  for (let i = 0; i < v.length; i++) r[i] = k * v[i];
  return r;
}

/**
 * Degrees to radians.
 * @param {number} degrees
 * @returns {number}
 */
export function radians(degrees) { return (degrees * Math.PI) / 180; }

// ---------------------------------------------------------------------------------------------
// Products: mult
// MV.js's one product for every pair: mat4·mat4 (V M), mat4·vec4 (P V p), and the mat3 cases.

// mat4 · mat4. a is read whole into locals first and each column of b just before its column
// of the result is written, so out may be a, b, or both.
function mult44(a, b, r) {
  const a00 = a[0], a10 = a[1], a20 = a[2], a30 = a[3];
  const a01 = a[4], a11 = a[5], a21 = a[6], a31 = a[7];
  const a02 = a[8], a12 = a[9], a22 = a[10], a32 = a[11];
  const a03 = a[12], a13 = a[13], a23 = a[14], a33 = a[15];
  for (let c = 0; c < 16; c += 4) {
    const x = b[c], y = b[c + 1], z = b[c + 2], w = b[c + 3]; // column c/4 of b
    r[c] = a00 * x + a01 * y + a02 * z + a03 * w;
    r[c + 1] = a10 * x + a11 * y + a12 * z + a13 * w;
    r[c + 2] = a20 * x + a21 * y + a22 * z + a23 * w;
    r[c + 3] = a30 * x + a31 * y + a32 * z + a33 * w;
  }
  return r;
}

// mat3 · mat3, the same way.
function mult33(a, b, r) {
  const a00 = a[0], a10 = a[1], a20 = a[2];
  const a01 = a[3], a11 = a[4], a21 = a[5];
  const a02 = a[6], a12 = a[7], a22 = a[8];
  for (let c = 0; c < 9; c += 3) {
    const x = b[c], y = b[c + 1], z = b[c + 2];
    r[c] = a00 * x + a01 * y + a02 * z;
    r[c + 1] = a10 * x + a11 * y + a12 * z;
    r[c + 2] = a20 * x + a21 * y + a22 * z;
  }
  return r;
}

/**
 * The product a·b, chosen by the sizes:
 * mat4·mat4 (16, 16), mat3·mat3 (9, 9), mat4·vec4 (16, 4), mat3·vec3 (9, 3);
 * two vectors of one size are multiplied component by component.
 * out may be a or b (or both); nothing is allocated when out is given.
 * @param {Mat|Vecish} a @param {Mat|Vecish} b @param {Float32Array} [out]
 * @returns {Float32Array} out, or a new array
 */
export function mult(a, b, out) {
  const na = a.length, nb = b.length;
  if (na === 16 && nb === 16) return mult44(a, b, target(out, 16, 'mult'));
  if (na === 9 && nb === 9) return mult33(a, b, target(out, 9, 'mult'));
  if (na === 16 && nb === 4) {
    const x = b[0], y = b[1], z = b[2], w = b[3];
    const r = target(out, 4, 'mult');
    r[0] = a[0] * x + a[4] * y + a[8] * z + a[12] * w;
    r[1] = a[1] * x + a[5] * y + a[9] * z + a[13] * w;
    r[2] = a[2] * x + a[6] * y + a[10] * z + a[14] * w;
    r[3] = a[3] * x + a[7] * y + a[11] * z + a[15] * w;
    return r;
  }
  if (na === 9 && nb === 3) {
    const x = b[0], y = b[1], z = b[2];
    const r = target(out, 3, 'mult');
    r[0] = a[0] * x + a[3] * y + a[6] * z;
    r[1] = a[1] * x + a[4] * y + a[7] * z;
    r[2] = a[2] * x + a[5] * y + a[8] * z;
    return r;
  }
  if (na === nb && na <= 4) {
    const r = target(out, na, 'mult');
    for (let i = 0; i < na; i++) r[i] = a[i] * b[i];
    return r;
  }
  throw new Error(`mult: cannot multiply sizes ${na} and ${nb} ` +
    '(mat4·mat4, mat3·mat3, mat4·vec4, mat3·vec3, or two vectors of one size)');
}

// ---------------------------------------------------------------------------------------------
// Transpose and inverse: transpose, det, inverse, normalMatrix
// normalMatrix is what the lighting steps need: N = (M^T)^-1 turns normals into view space.

function order(m, who) {
  if (m.length === 16) return 4;
  if (m.length === 9) return 3;
  throw new Error(`${who}: expects a mat3 (9 numbers) or mat4 (16), got ${m.length} numbers`);
}

/**
 * The transpose of a mat3 or mat4 (out === m transposes in place).
 * @param {Mat} m @param {Mat} [out]
 * @returns {Mat} out, or a new matrix
 */
export function transpose(m, out) {
  const n = order(m, 'transpose');
  const r = target(out, n * n, 'transpose');
  for (let c = 0; c < n; c++) {
    for (let row = c; row < n; row++) { // each pair (row, c), (c, row) once: read both, then write
      const below = m[c * n + row], above = m[row * n + c];
      r[c * n + row] = above;
      r[row * n + c] = below;
    }
  }
  return r;
}

// The inverse of the 3×3 with columns p, q, t: its rows are q×t, t×p, p×q divided by
// det = p·(q×t). With `rows` false they are written as columns instead, which gives the
// transposed inverse (M^-1)^T = (M^T)^-1, the normal matrix.
function invert3(px, py, pz, qx, qy, qz, tx, ty, tz, r, rows, who) {
  const ax = qy * tz - qz * ty, ay = qz * tx - qx * tz, az = qx * ty - qy * tx; // q × t
  const bx = ty * pz - tz * py, by = tz * px - tx * pz, bz = tx * py - ty * px; // t × p
  const cx = py * qz - pz * qy, cy = pz * qx - px * qz, cz = px * qy - py * qx; // p × q
  const det = px * ax + py * ay + pz * az;
  if (!det) throw new Error(`${who}: singular matrix`);
  const k = 1 / det;
  if (rows) {
    r[0] = ax * k; r[3] = ay * k; r[6] = az * k;
    r[1] = bx * k; r[4] = by * k; r[7] = bz * k;
    r[2] = cx * k; r[5] = cy * k; r[8] = cz * k;
  } else {
    r[0] = ax * k; r[1] = ay * k; r[2] = az * k;
    r[3] = bx * k; r[4] = by * k; r[5] = bz * k;
    r[6] = cx * k; r[7] = cy * k; r[8] = cz * k;
  }
  return r;
}

// The inverse of a mat4 by 3-vector algebra (E. Lengyel, Foundations of Game Engine Development,
// vol. 1, §1.7.5). Columns of m: (a, x), (b, y), (c, z), (d, w) with a..d their upper 3-vectors
// and x..w the bottom row. With s = a×b, t = c×d, u = y a − x b, v = w c − z d:
// det = s·v + t·u, and the rows of m^-1 are
// (b×v + y t, −b·t), (v×a − x t, a·t), (d×u + w s, −d·s), (u×c − z s, c·s), all over det.
function invert4(m, r) {
  const ax = m[0], ay = m[1], az = m[2], x = m[3];
  const bx = m[4], by = m[5], bz = m[6], y = m[7];
  const cx = m[8], cy = m[9], cz = m[10], z = m[11];
  const dx = m[12], dy = m[13], dz = m[14], w = m[15];
  let sx = ay * bz - az * by, sy = az * bx - ax * bz, sz = ax * by - ay * bx; // a × b
  let tx = cy * dz - cz * dy, ty = cz * dx - cx * dz, tz = cx * dy - cy * dx; // c × d
  let ux = y * ax - x * bx, uy = y * ay - x * by, uz = y * az - x * bz;
  let vx = w * cx - z * dx, vy = w * cy - z * dy, vz = w * cz - z * dz;
  const det = sx * vx + sy * vy + sz * vz + tx * ux + ty * uy + tz * uz;
  if (!det) throw new Error('inverse: singular matrix');
  const k = 1 / det;
  sx *= k; sy *= k; sz *= k; tx *= k; ty *= k; tz *= k;
  ux *= k; uy *= k; uz *= k; vx *= k; vy *= k; vz *= k;
  // row i of the inverse goes to r[i], r[4 + i], r[8 + i], r[12 + i]
  r[0] = by * vz - bz * vy + y * tx; r[4] = bz * vx - bx * vz + y * ty; r[8] = bx * vy - by * vx + y * tz;
  r[12] = -(bx * tx + by * ty + bz * tz);
  r[1] = vy * az - vz * ay - x * tx; r[5] = vz * ax - vx * az - x * ty; r[9] = vx * ay - vy * ax - x * tz;
  r[13] = ax * tx + ay * ty + az * tz;
  r[2] = dy * uz - dz * uy + w * sx; r[6] = dz * ux - dx * uz + w * sy; r[10] = dx * uy - dy * ux + w * sz;
  r[14] = -(dx * sx + dy * sy + dz * sz);
  r[3] = uy * cz - uz * cy - z * sx; r[7] = uz * cx - ux * cz - z * sy; r[11] = ux * cy - uy * cx - z * sz;
  r[15] = cx * sx + cy * sy + cz * sz;
  return r;
}

/**
 * The determinant of a mat3 or mat4.
 * @param {Mat} m
 * @returns {number}
 */
export function det(m) {
  if (order(m, 'det') === 3) {
    // p · (q × t) for the columns p, q, t
    return m[0] * (m[4] * m[8] - m[5] * m[7]) + m[1] * (m[5] * m[6] - m[3] * m[8]) +
      m[2] * (m[3] * m[7] - m[4] * m[6]);
  }
  const ax = m[0], ay = m[1], az = m[2], x = m[3], bx = m[4], by = m[5], bz = m[6], y = m[7];
  const cx = m[8], cy = m[9], cz = m[10], z = m[11], dx = m[12], dy = m[13], dz = m[14], w = m[15];
  // s·v + t·u as in invert4
  return (ay * bz - az * by) * (w * cx - z * dx) + (az * bx - ax * bz) * (w * cy - z * dy) +
    (ax * by - ay * bx) * (w * cz - z * dz) + (cy * dz - cz * dy) * (y * ax - x * bx) +
    (cz * dx - cx * dz) * (y * ay - x * by) + (cx * dy - cy * dx) * (y * az - x * bz);
}

/**
 * The inverse of a mat3 or mat4 (out === m inverts in place).
 * @param {Mat} m @param {Mat} [out]
 * @returns {Mat} out, or a new matrix
 * @throws {Error} 'inverse: singular matrix' when the determinant is 0
 */
export function inverse(m, out) {
  if (order(m, 'inverse') === 4) return invert4(m, target(out, 16, 'inverse'));
  return invert3(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], target(out, 9, 'inverse'), true, 'inverse');
}

/**
 * The normal matrix of a model-view matrix M (slides: N = (M^T)^-1): the transposed inverse of
 * M's upper-left 3×3, a mat3 ready for gl.uniformMatrix3fv(loc, false, N). It keeps normals
 * perpendicular to surfaces under non-uniform scaling.
 * @param {Mat} m a mat4
 * @param {Mat} [out] a mat3
 * @returns {Mat} out, or a new mat3
 * @throws {Error} 'normalMatrix: singular matrix' when the upper 3×3 has no inverse
 */
export function normalMatrix(m, out) {
  if (m.length !== 16) throw new Error(`normalMatrix: expects a mat4, got ${m.length} numbers`);
  return invert3(m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10], target(out, 9, 'normalMatrix'), false, 'normalMatrix');
}

// ---------------------------------------------------------------------------------------------
// Transformations: translate, scalem, rotate, rotateX, rotateY, rotateZ
// The model matrix M's building blocks, all mat4, angles in degrees as in MV.js.

/**
 * The translation by (x, y, z): m[12], m[13], m[14] = x, y, z.
 * @param {number} x @param {number} y @param {number} z @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function translate(x, y, z, out) {
  const m = target(out, 16, 'translate');
  m.fill(0);
  m[0] = m[5] = m[10] = m[15] = 1;
  m[12] = x; m[13] = y; m[14] = z;
  return m;
}

/**
 * The scaling by (x, y, z) (MV.js's name: `scale` is s·v).
 * @param {number} x @param {number} y @param {number} z @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function scalem(x, y, z, out) {
  const m = target(out, 16, 'scalem');
  m.fill(0);
  m[0] = x; m[5] = y; m[10] = z; m[15] = 1;
  return m;
}

/**
 * The rotation by `angle` DEGREES about `axis` through the origin, counter-clockwise when the
 * axis points at the viewer (right-handed). The axis need not be unit length.
 * @param {number} angle degrees
 * @param {Vecish} axis its x, y, z are used
 * @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 * @throws {Error} when the axis has zero length
 */
export function rotate(angle, axis, out) {
  let x = axis[0], y = axis[1], z = axis[2];
  const len = Math.sqrt(x * x + y * y + z * z);
  if (!len) throw new Error('rotate: the axis has zero length');
  x /= len; y /= len; z /= len;
  const c = Math.cos(radians(angle)), s = Math.sin(radians(angle)), t = 1 - c;
  // Rodrigues: R = c I + s [n]x + (1 − c) n n^T
  const m = target(out, 16, 'rotate');
  m[0] = t * x * x + c; m[4] = t * x * y - s * z; m[8] = t * x * z + s * y; m[12] = 0;
  m[1] = t * x * y + s * z; m[5] = t * y * y + c; m[9] = t * y * z - s * x; m[13] = 0;
  m[2] = t * x * z - s * y; m[6] = t * y * z + s * x; m[10] = t * z * z + c; m[14] = 0;
  m[3] = 0; m[7] = 0; m[11] = 0; m[15] = 1;
  return m;
}

// A rotation about one coordinate axis: i, j are the two axes that turn (i towards j).
function axisRotation(angle, i, j, out, who) {
  const c = Math.cos(radians(angle)), s = Math.sin(radians(angle));
  const m = target(out, 16, who);
  m.fill(0);
  m[0] = m[5] = m[10] = m[15] = 1;
  m[i * 4 + i] = c; m[j * 4 + i] = -s;
  m[i * 4 + j] = s; m[j * 4 + j] = c;
  return m;
}

/**
 * The rotation by `angle` degrees about the x axis (y turns towards z).
 * @param {number} angle degrees @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function rotateX(angle, out) { return axisRotation(angle, 1, 2, out, 'rotateX'); }

/**
 * The rotation by `angle` degrees about the y axis (z turns towards x).
 * @param {number} angle degrees @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function rotateY(angle, out) { return axisRotation(angle, 2, 0, out, 'rotateY'); }

/**
 * The rotation by `angle` degrees about the z axis (x turns towards y).
 * @param {number} angle degrees @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function rotateZ(angle, out) { return axisRotation(angle, 0, 1, out, 'rotateZ'); }

// ---------------------------------------------------------------------------------------------
// Camera and projection: lookAt, perspective, ortho
// The view matrix V (the camera) and the projection P of gl_Position = P * V * M * p.

/**
 * The view matrix V of a camera at `eye` looking at `at`, with `up` roughly up (OpenGL: the
 * camera looks down its own −z axis, x to the right, y up). The same matrix as gl-matrix's
 * mat4.lookAt, except that impossible cameras throw instead of giving the identity.
 * @param {Vecish} eye @param {Vecish} at @param {Vecish} up  their x, y, z are used
 * @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 * @throws {Error} when eye = at, or up is parallel to the view direction (or zero)
 */
export function lookAt(eye, at, up, out) {
  const ex = eye[0], ey = eye[1], ez = eye[2];
  // n: from at to eye, the camera's +z
  let nx = ex - at[0], ny = ey - at[1], nz = ez - at[2];
  let len = Math.sqrt(nx * nx + ny * ny + nz * nz);
  if (!len) throw new Error('lookAt: eye and at are the same point, so there is no view direction');
  nx /= len; ny /= len; nz /= len;
  // u = up × n: the camera's +x
  const upx = up[0], upy = up[1], upz = up[2];
  let ux = upy * nz - upz * ny, uy = upz * nx - upx * nz, uz = upx * ny - upy * nx;
  len = Math.sqrt(ux * ux + uy * uy + uz * uz);
  if (!len) throw new Error('lookAt: up is zero or parallel to the view direction (eye − at)');
  ux /= len; uy /= len; uz /= len;
  // v = n × u: the camera's +y
  const vx = ny * uz - nz * uy, vy = nz * ux - nx * uz, vz = nx * uy - ny * ux;
  // rows u, v, n; then move the eye to the origin
  const m = target(out, 16, 'lookAt');
  m[0] = ux; m[4] = uy; m[8] = uz; m[12] = -(ux * ex + uy * ey + uz * ez);
  m[1] = vx; m[5] = vy; m[9] = vz; m[13] = -(vx * ex + vy * ey + vz * ez);
  m[2] = nx; m[6] = ny; m[10] = nz; m[14] = -(nx * ex + ny * ey + nz * ez);
  m[3] = 0; m[7] = 0; m[11] = 0; m[15] = 1;
  return m;
}

/**
 * The perspective projection P (OpenGL: the view volume maps to the cube [−1, 1]^3), as MV.js:
 * vertical field of view `fovy` in DEGREES. far = Infinity gives the limit matrix.
 * Same as gl-matrix's mat4.perspective with fovy in radians.
 * @param {number} fovy degrees @param {number} aspect width / height
 * @param {number} near > 0 @param {number} far > near
 * @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function perspective(fovy, aspect, near, far, out) {
  const f = 1 / Math.tan(radians(fovy) / 2);
  const m = target(out, 16, 'perspective');
  m.fill(0);
  m[0] = f / aspect;
  m[5] = f;
  m[11] = -1;
  if (far === Infinity) {
    m[10] = -1;
    m[14] = -2 * near;
  } else {
    m[10] = (far + near) / (near - far);
    m[14] = (2 * far * near) / (near - far);
  }
  return m;
}

/**
 * The perspective projection for WebGPU, whose clip space keeps z in [0, 1] (WebGL's: [−1, 1]):
 * the same view volume as `perspective`, its near plane mapped to z = 0 and its far plane to 1.
 * Same as gl-matrix's mat4.perspectiveZO with fovy in radians.
 * @param {number} fovy degrees @param {number} aspect width / height
 * @param {number} near > 0 @param {number} far > near, or Infinity
 * @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function perspectiveZO(fovy, aspect, near, far, out) {
  const m = perspective(fovy, aspect, near, far, target(out, 16, 'perspectiveZO'));
  if (far === Infinity) {
    m[10] = -1;
    m[14] = -near;
  } else {
    m[10] = far / (near - far);
    m[14] = (far * near) / (near - far);
  }
  return m;
}

/**
 * The orthographic projection of the box x in [left, right], y in [bottom, top],
 * z in [−near, −far] (camera space) onto the cube [−1, 1]^3.
 * @param {number} left @param {number} right @param {number} bottom @param {number} top
 * @param {number} near @param {number} far
 * @param {Mat} [out]
 * @returns {Mat} out, or a new mat4
 */
export function ortho(left, right, bottom, top, near, far, out) {
  const m = target(out, 16, 'ortho');
  m.fill(0);
  m[0] = 2 / (right - left);
  m[5] = 2 / (top - bottom);
  m[10] = -2 / (far - near);
  m[12] = -(right + left) / (right - left);
  m[13] = -(top + bottom) / (top - bottom);
  m[14] = -(far + near) / (far - near);
  m[15] = 1;
  return m;
}

// ---------------------------------------------------------------------------------------------
// For WebGL: flatten, equal
// flatten hands data to gl.bufferData and gl.uniform*; equal compares with a tolerance.

/**
 * One Float32Array for gl.bufferData or gl.uniform*: a Float32Array is returned AS IT IS (no
 * copy); another typed array or a plain array of numbers is converted; an array of vectors (or
 * matrices) is concatenated into one new Float32Array. Matrices are already column-major, so
 * nothing is transposed.
 * @param {Float32Array|ArrayLike<number>|ArrayLike<ArrayLike<number>>} x
 * @returns {Float32Array}
 */
export function flatten(x) {
  if (x instanceof F32) return x;
  if (!x || typeof x !== 'object' || typeof x.length !== 'number') {
    throw new Error('flatten: expects an array of numbers or an array of vectors');
  }
  if (ArrayBuffer.isView(x)) return F32.from(x);
  let n = 0;
  let numbers = 0;
  for (let i = 0; i < x.length; i++) {
    const e = x[i];
    if (typeof e === 'number') { n++; numbers++; } else if (e && typeof e === 'object' && typeof e.length === 'number') n += e.length;
    else throw new Error(`flatten: element ${i} is neither a number nor a vector`);
  }
  if (numbers > 0 && numbers < x.length) throw new Error('flatten: mixes numbers and vectors');
  if (numbers === x.length) return F32.from(x);
  const r = new F32(n);
  let at = 0;
  for (let i = 0; i < x.length; i++) {
    r.set(x[i], at);
    at += x[i].length;
  }
  return r;
}

/**
 * True when a and b have one length and no component differs by more than eps.
 * @param {ArrayLike<number>} a @param {ArrayLike<number>} b @param {number} [eps=1e-6]
 * @returns {boolean}
 */
export function equal(a, b, eps = 1e-6) {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (!(Math.abs(a[i] - b[i]) <= eps)) return false;
  return true;
}
