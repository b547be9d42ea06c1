// common/math.js checked against gl-matrix as an oracle on seeded random inputs: every export,
// `out` returned as given, `out` aliasing an input, and the MV.js conventions (row-major
// arguments, vec4's w, scalar-first scale, degrees) that gl-matrix does not share.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mat3 as gm3, mat4 as gm4, vec3 as gv3, vec4 as gv4 } from 'gl-matrix';
import * as M from '../../common/math.js';

// mulberry32: a small seeded generator, so a failure replays exactly
function mulberry32(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const random = mulberry32(2561);
const num = (s = 10) => (random() * 2 - 1) * s;
const arr = (n, s) => Float32Array.from({ length: n }, () => num(s));
const copy = (a) => Float32Array.from(a);
const deg = (r) => (r * 180) / Math.PI;
const CASES = 200;

// |actual − expected| <= tol · max(1, |expected|) in every component: absolute near 0, relative above 1
function close(actual, expected, what, tol = 1e-5) {
  assert.equal(actual.length, expected.length, `${what}: length`);
  for (let i = 0; i < actual.length; i++) {
    const bound = tol * Math.max(1, Math.abs(expected[i]));
    assert.ok(Math.abs(actual[i] - expected[i]) <= bound, `${what}[${i}]: ${actual[i]} vs ${expected[i]}`);
  }
}
const closeNum = (a, e, what, tol) => close([a], [e], what, tol);

// A random mat4 that is comfortably invertible: I·k plus noise, so the oracle comparison is
// about our formula, not about float32 cancellation in a near-singular matrix.
function invertible(n) {
  const m = arr(n * n, 1);
  for (let i = 0; i < n; i++) m[i * n + i] += (random() < 0.5 ? -1 : 1) * (2 + random() * 3);
  return m;
}

test('vec2, vec3, vec4: defaults, spread arguments, and vec4 w = 1 as in MV.js', () => {
  assert.ok(M.vec3() instanceof Float32Array);
  assert.deepEqual([...M.vec2()], [0, 0]);
  assert.deepEqual([...M.vec3()], [0, 0, 0]);
  assert.deepEqual([...M.vec4()], [0, 0, 0, 1], 'MV.js: vec4() is the origin point');
  assert.deepEqual([...M.vec4(1, 2, 3)], [1, 2, 3, 1], 'MV.js: vec4(x, y, z) is a point, w = 1');
  assert.deepEqual([...M.vec4(1, 2, 3, 0)], [1, 2, 3, 0]);
  assert.deepEqual([...M.vec4(7)], [7, 0, 0, 1]);
  assert.deepEqual([...M.vec2(1)], [1, 0]);
  assert.deepEqual([...M.vec3([1, 2, 3])], [1, 2, 3]);
  assert.deepEqual([...M.vec2([5, 6, 7])], [5, 6], 'extra components are dropped');
  assert.deepEqual([...M.vec3(M.vec4(1, 2, 3, 4))], [1, 2, 3], "vec3(v4) is v4's xyz");
  assert.deepEqual([...M.vec4(M.vec3(1, 2, 3), 0)], [1, 2, 3, 0], 'vec4(v3, w)');
  assert.deepEqual([...M.vec4([1, 2])], [1, 2, 0, 1]);
  const src = M.vec3(1, 2, 3), c = M.vec3(src);
  c[0] = 9;
  assert.equal(src[0], 1, 'vec3(v) copies');
  assert.throws(() => M.vec3('1'), /vec3: arguments must be numbers/);
  assert.throws(() => M.vec4([1, 'x']), /vec4: element 1/);
});

test('mat3, mat4: identity, s·I, and arguments written row by row stored column-major', () => {
  close(M.mat4(), gm4.create(), 'mat4()');
  close(M.mat3(), gm3.create(), 'mat3()');
  close(M.mat4(2), gm4.fromScaling(gm4.create(), [2, 2, 2]).map((x, i) => (i === 15 ? 2 : x)), 'mat4(2)');
  // written as rows, the translation is the last column: elements 12, 13, 14
  const t = M.mat4(1, 0, 0, 7, 0, 1, 0, 8, 0, 0, 1, 9, 0, 0, 0, 1);
  close(t, gm4.fromTranslation(gm4.create(), [7, 8, 9]), 'mat4(rows)');
  for (let k = 0; k < CASES; k++) {
    const rows = Array.from({ length: 16 }, () => num());
    // gl-matrix fromValues takes column-major order; ours takes rows: one is the other's transpose
    close(M.mat4(...rows), gm4.transpose(gm4.create(), gm4.fromValues(...rows)), 'mat4 layout');
    const r3 = Array.from({ length: 9 }, () => num());
    close(M.mat3(...r3), gm3.transpose(gm3.create(), gm3.fromValues(...r3)), 'mat3 layout');
    close(M.mat3(r3.slice(0, 3), r3.slice(3, 6), r3.slice(6)), M.mat3(...r3), 'mat3(row, row, row)');
  }
  assert.deepEqual([...M.mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)], [1, 4, 7, 2, 5, 8, 3, 6, 9]);
  assert.throws(() => M.mat3(1, 2, 3), /mat3: needs 9 numbers/);
  assert.throws(() => M.mat4(M.mat4()), /m\.slice\(\)/, 'one matrix argument is refused, not silently transposed');
});

test('add, subtract, scale, negate (vectors and matrices), with out and aliasing', () => {
  for (let k = 0; k < CASES; k++) {
    const a = arr(3), b = arr(3), s = num();
    close(M.add(a, b), gv3.add(gv3.create(), a, b), 'add');
    close(M.subtract(a, b), gv3.subtract(gv3.create(), a, b), 'subtract');
    close(M.scale(s, a), gv3.scale(gv3.create(), a, s), 'scale');
    close(M.negate(a), gv3.negate(gv3.create(), a), 'negate');
    const A = arr(16), B = arr(16);
    close(M.add(A, B), gm4.add(gm4.create(), A, B), 'add mat4');
    close(M.subtract(A, B), gm4.subtract(gm4.create(), A, B), 'subtract mat4');
    close(M.scale(s, A), gm4.multiplyScalar(gm4.create(), A, s), 'scale mat4');
    // out returned as given; out === a; out === b
    const out = new Float32Array(3);
    assert.equal(M.add(a, b, out), out);
    const a1 = copy(a), b1 = copy(b), a2 = copy(a), v = copy(a);
    close(M.subtract(a1, b, a1), gv3.subtract(gv3.create(), a, b), 'subtract out === a');
    close(M.subtract(a, b1, b1), gv3.subtract(gv3.create(), a, b), 'subtract out === b');
    assert.equal(M.scale(s, a2, a2), a2);
    close(a2, gv3.scale(gv3.create(), a, s), 'scale in place');
    assert.equal(M.negate(v, v), v);
    close(v, gv3.negate(gv3.create(), a), 'negate in place');
    assert.notEqual(M.add(a, b), a, 'without out, a new array');
  }
  assert.throws(() => M.add(M.vec3(), M.vec4()), /add: sizes differ/);
  assert.throws(() => M.scale(M.vec3(), 2), /scalar comes first/);
  assert.throws(() => M.add(M.vec3(), M.vec3(), new Float32Array(4)), /out has 4 elements, needs 3/);
});

test('dot, cross, length, normalize agree with gl-matrix; normalize(0) gives zeros', () => {
  for (let k = 0; k < CASES; k++) {
    const a = arr(3), b = arr(3), a4 = arr(4), b4 = arr(4);
    closeNum(M.dot(a, b), gv3.dot(a, b), 'dot');
    closeNum(M.dot(a4, b4), gv4.dot(a4, b4), 'dot vec4');
    close(M.cross(a, b), gv3.cross(gv3.create(), a, b), 'cross');
    close(M.cross(a4, b4), gv3.cross(gv3.create(), a4.subarray(0, 3), b4.subarray(0, 3)), 'cross of vec4 xyz');
    closeNum(M.length(a), gv3.length(a), 'length');
    closeNum(M.length(a4), gv4.length(a4), 'length vec4');
    close(M.normalize(a), gv3.normalize(gv3.create(), a), 'normalize');
    close(M.normalize(a4), gv4.normalize(gv4.create(), a4), 'normalize vec4 (all four)');
    const c1 = copy(a), c2 = copy(b), n = copy(a), out = new Float32Array(3);
    assert.equal(M.cross(a, b, out), out);
    assert.equal(M.cross(c1, b, c1), c1);
    close(c1, gv3.cross(gv3.create(), a, b), 'cross out === a');
    close(M.cross(a, c2, c2), gv3.cross(gv3.create(), a, b), 'cross out === b');
    assert.equal(M.normalize(n, n), n);
    close(n, gv3.normalize(gv3.create(), a), 'normalize in place');
  }
  assert.deepEqual([...M.normalize(M.vec3())], [0, 0, 0], 'zero stays zero, not NaN');
  assert.deepEqual([...M.normalize(new Float32Array(4))], [0, 0, 0, 0]);
  assert.throws(() => M.normalize(M.vec4(1, 2, 3, 1), true), /excludeLastComponent/);
  assert.throws(() => M.dot(M.vec3(), M.vec4()), /dot: sizes differ/);
});

test('mult: mat4·mat4, mat3·mat3, mat4·vec4, mat3·vec3, vector·vector, with out and aliasing', () => {
  for (let k = 0; k < CASES; k++) {
    const a = arr(16), b = arr(16), v = arr(4);
    const ab = gm4.multiply(gm4.create(), a, b);
    close(M.mult(a, b), ab, 'mat4·mat4');
    const out = new Float32Array(16);
    assert.equal(M.mult(a, b, out), out, 'returns out');
    close(out, ab, 'mat4·mat4 into out');
    const a1 = copy(a), b1 = copy(b), sq = copy(a);
    assert.equal(M.mult(a1, b, a1), a1);
    close(a1, ab, 'mat4·mat4 out === a');
    close(M.mult(a, b1, b1), ab, 'mat4·mat4 out === b');
    close(M.mult(sq, sq, sq), gm4.multiply(gm4.create(), a, a), 'mat4 a·a into a');

    const m = arr(9), n = arr(9);
    const mn = gm3.multiply(gm3.create(), m, n);
    close(M.mult(m, n), mn, 'mat3·mat3');
    const m1 = copy(m), n1 = copy(n), sq3 = copy(m);
    close(M.mult(m1, n, m1), mn, 'mat3·mat3 out === a');
    close(M.mult(m, n1, n1), mn, 'mat3·mat3 out === b');
    close(M.mult(sq3, sq3, sq3), gm3.multiply(gm3.create(), m, m), 'mat3 a·a into a');

    const av = gv4.transformMat4(gv4.create(), v, a);
    close(M.mult(a, v), av, 'mat4·vec4');
    const v1 = copy(v);
    assert.equal(M.mult(a, v1, v1), v1);
    close(v1, av, 'mat4·vec4 out === v');
    const w = arr(3), w1 = copy(w);
    const mw = gv3.transformMat3(gv3.create(), w, m);
    close(M.mult(m, w), mw, 'mat3·vec3');
    close(M.mult(m, w1, w1), mw, 'mat3·vec3 out === v');

    const p = arr(3), q = arr(3);
    close(M.mult(p, q), gv3.multiply(gv3.create(), p, q), 'vec3 ⊙ vec3');
    close(M.mult(v, v), gv4.multiply(gv4.create(), v, v), 'vec4 ⊙ vec4');
  }
  assert.throws(() => M.mult(new Float32Array(16), new Float32Array(3)), /mult: cannot multiply sizes 16 and 3/);
  assert.throws(() => M.mult(M.mat4(), M.mat4(), M.mat3()), /out has 9 elements, needs 16/);
  // column-major meaning: T·p moves the point p
  assert.deepEqual([...M.mult(M.translate(1, 2, 3), M.vec4(0, 0, 0, 1))], [1, 2, 3, 1]);
});

test('transpose, det, inverse of mat3 and mat4, in place too; a singular matrix throws', () => {
  for (let k = 0; k < CASES; k++) {
    const a = arr(16), m = arr(9);
    close(M.transpose(a), gm4.transpose(gm4.create(), a), 'transpose4');
    close(M.transpose(m), gm3.transpose(gm3.create(), m), 'transpose3');
    const t4 = copy(a), t3 = copy(m), out = new Float32Array(16);
    assert.equal(M.transpose(t4, t4), t4);
    close(t4, gm4.transpose(gm4.create(), a), 'transpose4 in place');
    close(M.transpose(t3, t3), gm3.transpose(gm3.create(), m), 'transpose3 in place');
    assert.equal(M.transpose(a, out), out);

    closeNum(M.det(a), gm4.determinant(a), 'det4', 1e-4);
    closeNum(M.det(m), gm3.determinant(m), 'det3', 1e-4);

    const g = invertible(4), h = invertible(3);
    const gi = gm4.invert(gm4.create(), g), hi = gm3.invert(gm3.create(), h);
    close(M.inverse(g), gi, 'inverse4', 1e-5);
    close(M.inverse(h), hi, 'inverse3', 1e-5);
    const g1 = copy(g), h1 = copy(h);
    assert.equal(M.inverse(g1, g1), g1);
    close(g1, gi, 'inverse4 in place', 1e-5);
    assert.equal(M.inverse(h1, h1), h1);
    close(h1, hi, 'inverse3 in place', 1e-5);
    assert.equal(M.inverse(g, out), out);
    close(M.mult(g, M.inverse(g)), M.mat4(), 'g·g⁻¹ = I', 1e-5);
    // and on plain random matrices (any conditioning), still the same as gl-matrix
    if (gm4.determinant(a) !== 0) close(M.inverse(a), gm4.invert(gm4.create(), a), 'inverse4 random', 1e-3);
  }
  assert.throws(() => M.inverse(new Float32Array(16)), /^Error: inverse: singular matrix$/);
  assert.throws(() => M.inverse(new Float32Array(9)), /inverse: singular matrix/);
  // rank 2: the third row is the sum of the first two
  assert.throws(() => M.inverse(M.mat3(1, 2, 3, 4, 5, 6, 5, 7, 9)), /singular/);
  assert.throws(() => M.inverse(M.scalem(1, 0, 1)), /singular/);
  assert.throws(() => M.transpose(new Float32Array(4)), /transpose: expects a mat3/);
});

test('translate, scalem, rotate (degrees, any axis), rotateX/Y/Z, radians', () => {
  for (let k = 0; k < CASES; k++) {
    const [x, y, z] = arr(3);
    close(M.translate(x, y, z), gm4.fromTranslation(gm4.create(), [x, y, z]), 'translate');
    close(M.scalem(x, y, z), gm4.fromScaling(gm4.create(), [x, y, z]), 'scalem');
    const angle = num(360), axis = arr(3), rad = M.radians(angle);
    const unit = gv3.normalize(gv3.create(), axis);
    close(M.rotate(angle, axis), gm4.fromRotation(gm4.create(), rad, unit), 'rotate');
    close(M.rotate(angle, [...axis]), gm4.fromRotation(gm4.create(), rad, unit), 'rotate, plain-array axis');
    close(M.rotateX(angle), gm4.fromXRotation(gm4.create(), rad), 'rotateX');
    close(M.rotateY(angle), gm4.fromYRotation(gm4.create(), rad), 'rotateY');
    close(M.rotateZ(angle), gm4.fromZRotation(gm4.create(), rad), 'rotateZ');
    // out is overwritten whatever it held
    const out = arr(16);
    assert.equal(M.translate(x, y, z, out), out);
    close(out, gm4.fromTranslation(gm4.create(), [x, y, z]), 'translate into used out');
    assert.equal(M.scalem(x, y, z, arr(16)).length, 16);
    const o2 = arr(16), o3 = arr(16);
    close(M.rotate(angle, axis, o2), gm4.fromRotation(gm4.create(), rad, unit), 'rotate into used out');
    close(M.rotateY(angle, o3), gm4.fromYRotation(gm4.create(), rad), 'rotateY into used out');
  }
  assert.equal(M.radians(180), Math.PI);
  closeNum(M.radians(deg(1.234)), 1.234, 'radians');
  close(M.mult(M.rotateZ(90), M.vec4(1, 0, 0, 0)), [0, 1, 0, 0], 'rotateZ(90) turns x to y');
  assert.throws(() => M.rotate(10, [0, 0, 0]), /rotate: the axis has zero length/);
});

test('lookAt, perspective, ortho agree with gl-matrix; impossible cameras throw', () => {
  for (let k = 0; k < CASES; k++) {
    const eye = arr(3), at = arr(3), up = arr(3);
    const want = gm4.lookAt(gm4.create(), eye, at, up);
    close(M.lookAt(eye, at, up), want, 'lookAt', 1e-4);
    close(M.lookAt([...eye], M.vec4(at, 1), up), want, 'lookAt, plain array and vec4 inputs', 1e-4);
    const out = arr(16);
    assert.equal(M.lookAt(eye, at, up, out), out);
    close(out, want, 'lookAt into used out', 1e-4);
    // the eye goes to the origin, at onto the −z axis
    close(M.mult(out, M.vec4(eye, 1)), [0, 0, 0, 1], 'V·eye = 0', 1e-4);
    const seen = M.mult(out, M.vec4(at, 1));
    close([seen[0], seen[1]], [0, 0], 'V·at on the z axis', 1e-4);
    assert.ok(seen[2] < 0, 'at is in front of the camera (−z)');

    const fovy = 10 + random() * 150, aspect = 0.2 + random() * 4;
    const near = 0.01 + random(), far = near + 1 + random() * 100;
    const P = gm4.perspective(gm4.create(), (fovy * Math.PI) / 180, aspect, near, far);
    close(M.perspective(fovy, aspect, near, far), P, 'perspective');
    const o2 = arr(16);
    assert.equal(M.perspective(fovy, aspect, near, far, o2), o2);
    close(o2, P, 'perspective into used out');
    close(M.perspective(fovy, aspect, near, Infinity),
      gm4.perspective(gm4.create(), (fovy * Math.PI) / 180, aspect, near, Infinity), 'perspective, far = ∞');

    const l = num(), r = l + 1 + random() * 5, b = num(), t = b + 1 + random() * 5;
    const O = gm4.ortho(gm4.create(), l, r, b, t, near, far);
    close(M.ortho(l, r, b, t, near, far), O, 'ortho');
    const o3 = arr(16);
    assert.equal(M.ortho(l, r, b, t, near, far, o3), o3);
    close(o3, O, 'ortho into used out');
  }
  assert.throws(() => M.lookAt([1, 2, 3], [1, 2, 3], [0, 1, 0]), /lookAt: eye and at are the same point/);
  assert.throws(() => M.lookAt([0, 0, 3], [0, 0, 0], [0, 0, 1]), /lookAt: up is zero or parallel/);
  assert.throws(() => M.lookAt([0, 0, 3], [0, 0, 0], [0, 0, 0]), /up is zero or parallel/);
});

test('normalMatrix is N = (M^T)^-1 of the upper 3×3, as gl-matrix mat3.normalFromMat4', () => {
  for (let k = 0; k < CASES; k++) {
    // a model-view as the exercises make it: V · R · S, with non-uniform scaling
    const V = M.lookAt(arr(3), arr(3), arr(3));
    const m = M.mult(V, M.mult(M.rotate(num(180), arr(3)), M.scalem(0.2 + random(), 1 + random() * 3, 0.5 + random())));
    const want = gm3.normalFromMat4(gm3.create(), m);
    close(M.normalMatrix(m), want, 'normalMatrix', 1e-4);
    const out = arr(9);
    assert.equal(M.normalMatrix(m, out), out);
    close(out, want, 'normalMatrix into used out', 1e-4);
    // any affine mat4 (bottom row 0 0 0 1: gl-matrix inverts the whole 4×4, which for an
    // affine matrix has the same upper 3×3), and the slides' definition written out
    const g = invertible(4);
    g[3] = g[7] = g[11] = 0; g[15] = 1;
    close(M.normalMatrix(g), gm3.normalFromMat4(gm3.create(), g), 'normalMatrix of an affine mat4', 1e-4);
    const upper = M.mat3(g[0], g[4], g[8], g[1], g[5], g[9], g[2], g[6], g[10]);
    close(M.normalMatrix(g), M.inverse(M.transpose(upper)), 'N = (M^T)^-1', 1e-4);
    const h = invertible(4); // not affine: still only its upper 3×3 counts
    const hUpper = M.mat3(h[0], h[4], h[8], h[1], h[5], h[9], h[2], h[6], h[10]);
    close(M.normalMatrix(h), M.transpose(M.inverse(hUpper)), 'N = (M^-1)^T of the upper 3×3', 1e-4);
    // it keeps normals perpendicular to tangents: (M t) · (N n) = t · n = 0
    const n = M.normalize(arr(3)), t = M.normalize(M.cross(n, arr(3)));
    closeNum(M.dot(M.mult(upper, t), M.mult(M.normalMatrix(g), n)), 0, 'Mt ⟂ Nn', 1e-4);
  }
  assert.throws(() => M.normalMatrix(M.scalem(1, 1, 0)), /normalMatrix: singular matrix/);
  assert.throws(() => M.normalMatrix(M.mat3()), /normalMatrix: expects a mat4/);
});

test('flatten: a Float32Array as it is, other arrays converted, arrays of vectors concatenated', () => {
  const f = new Float32Array([1, 2]);
  assert.equal(M.flatten(f), f, 'a Float32Array is returned as it is, not copied');
  const fromPlain = M.flatten([1, 2, 3]);
  assert.ok(fromPlain instanceof Float32Array);
  assert.deepEqual([...fromPlain], [1, 2, 3]);
  const fromF64 = M.flatten(new Float64Array([0.5, 1.5]));
  assert.ok(fromF64 instanceof Float32Array);
  assert.deepEqual([...fromF64], [0.5, 1.5]);
  assert.deepEqual([...M.flatten(new Uint16Array([1, 2]))], [1, 2]);
  const joined = M.flatten([M.vec4(1, 2, 3, 4), [5, 6, 7, 8], M.vec2(9, 10)]);
  assert.ok(joined instanceof Float32Array);
  assert.deepEqual([...joined], [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
  const T = M.translate(1, 2, 3);
  assert.equal(M.flatten(T), T);
  assert.deepEqual([...M.flatten([T]).slice(12, 15)], [1, 2, 3], 'matrices stay column-major');
  const parts = [M.vec3(1, 2, 3)];
  const flat = M.flatten(parts);
  flat[0] = 9;
  assert.equal(parts[0][0], 1, 'concatenation copies');
  assert.equal(M.flatten([]).length, 0);
  assert.throws(() => M.flatten([1, [2, 3]]), /flatten: mixes numbers and vectors/);
  assert.throws(() => M.flatten(['a']), /flatten: element 0/);
  assert.throws(() => M.flatten(3), /flatten: expects/);
});

test('equal compares with a tolerance and a length', () => {
  assert.ok(M.equal(M.vec3(1, 2, 3), [1, 2, 3.0000001]));
  assert.ok(!M.equal(M.vec3(1, 2, 3), [1, 2, 3.001]));
  assert.ok(M.equal(M.vec3(1, 2, 3), [1, 2, 3.001], 0.01));
  assert.ok(!M.equal(M.vec3(1, 2, 3), [1, 2]));
  assert.ok(!M.equal([NaN], [NaN]), 'NaN is never equal');
  assert.ok(M.equal(M.mult(M.rotate(30, [1, 1, 0]), M.rotate(-30, [1, 1, 0])), M.mat4()));
});

test('perspectiveZO (WebGPU, z in [0, 1]) agrees with gl-matrix, maps near to 0 and far to 1', () => {
  for (const [fovy, aspect, near, far] of [[45, 1, 0.1, 10], [60, 16 / 9, 0.5, 100], [30, 0.5, 2.3, 3.5]]) {
    const P = gm4.perspectiveZO(gm4.create(), (fovy * Math.PI) / 180, aspect, near, far);
    close(M.perspectiveZO(fovy, aspect, near, far), P, 'perspectiveZO');
    const o = new Float32Array(16).fill(7);
    assert.equal(M.perspectiveZO(fovy, aspect, near, far, o), o);
    close(o, P, 'perspectiveZO into a used out');
    const z = (d) => { const m = M.perspectiveZO(fovy, aspect, near, far); return (m[10] * -d + m[14]) / d; };
    assert.ok(Math.abs(z(near)) < 1e-6 && Math.abs(z(far) - 1) < 1e-6, 'near -> 0, far -> 1');
  }
  close(M.perspectiveZO(45, 1, 0.1, Infinity), gm4.perspectiveZO(gm4.create(), Math.PI / 4, 1, 0.1, Infinity), 'perspectiveZO, far = ∞');
});

test('every export is tested here', () => {
  const tested = ['vec2', 'vec3', 'vec4', 'mat3', 'mat4', 'add', 'subtract', 'scale', 'negate', 'dot', 'cross',
    'length', 'normalize', 'radians', 'mult', 'transpose', 'det', 'inverse', 'normalMatrix', 'translate',
    'scalem', 'rotate', 'rotateX', 'rotateY', 'rotateZ', 'lookAt', 'perspective', 'perspectiveZO', 'ortho', 'flatten', 'equal'];
  assert.deepEqual(Object.keys(M).sort(), tested.sort());
});
