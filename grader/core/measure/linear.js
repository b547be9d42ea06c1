// The small solvers the fits share: a 3×3 determinant and a 3×3 linear system (Cramer's rule), and
// the straight line through n points from their sums.

/** The determinant of a 3×3 matrix (rows). */
export const det3 = (m) =>
  m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
  m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);

/** Guards against dividing by (nearly) zero: a singular matrix, a pivot, a line fit's spread. */
const SINGULAR = 1e-12, GUARD = 1e-9;
/** Jacobi's method: its sweeps, and an off-diagonal entry taken as zero (the mechanics of a fit). */
const SWEEPS = 12, OFF_DIAGONAL_ZERO = 1e-15;

/** x with A x = b (A 3×3, rows), by Cramer's rule; [0, 0, 0] where A is singular. */
export function solve3(A, b) {
  const d = det3(A);
  if (Math.abs(d) < SINGULAR) return [0, 0, 0];
  return [0, 1, 2].map((k) => det3(A.map((row, i) => row.map((v, j) => (j === k ? b[i] : v)))) / d);
}

/** x minimising Σ (x·row − y)² over `rows` (each of length k), by the normal equations; null where singular. */
export function leastSquares(rows, ys) {
  const k = rows[0].length;
  const N = new Float64Array(k * k), v = new Float64Array(k);
  for (let i = 0; i < rows.length; i++) {
    const r = rows[i];
    for (let a = 0; a < k; a++) {
      for (let b = 0; b < k; b++) N[a * k + b] += r[a] * r[b];
      v[a] += r[a] * ys[i];
    }
  }
  return solveNormal(N, v, k);
}

/** x with N x = v (N k×k, row-major), by Gaussian elimination with pivoting; null where singular. */
export function solveNormal(N, v, k) {
  const A = Array.from({ length: k }, (_, a) => [...N.slice(a * k, a * k + k), v[a]]);
  for (let c = 0; c < k; c++) {
    let p = c;
    for (let r = c + 1; r < k; r++) if (Math.abs(A[r][c]) > Math.abs(A[p][c])) p = r;
    if (Math.abs(A[p][c]) < SINGULAR) return null;
    [A[c], A[p]] = [A[p], A[c]];
    for (let r = 0; r < k; r++) {
      if (r === c) continue;
      const f = A[r][c] / A[c][c];
      for (let j = c; j <= k; j++) A[r][j] -= f * A[c][j];
    }
  }
  return Array.from({ length: k }, (_, c) => A[c][k] / A[c][c]);
}

/** The eigenvalues of a symmetric 3×3 matrix (rows), largest first (Jacobi rotations). */
export function symmetricEigenvalues3(M) {
  const a = M.map((r) => [...r]);
  for (let sweep = 0; sweep < SWEEPS; sweep++) {
    for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
      if (Math.abs(a[p][q]) < OFF_DIAGONAL_ZERO) continue;
      const th = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(th || 1) / (Math.abs(th) + Math.sqrt(th * th + 1));
      const c = 1 / Math.sqrt(t * t + 1), s = t * c;
      for (let k = 0; k < 3; k++) { // columns p, q
        const kp = a[k][p], kq = a[k][q];
        a[k][p] = c * kp - s * kq; a[k][q] = s * kp + c * kq;
      }
      for (let k = 0; k < 3; k++) { // rows p, q
        const pk = a[p][k], qk = a[q][k];
        a[p][k] = c * pk - s * qk; a[q][k] = s * pk + c * qk;
      }
    }
  }
  return [a[0][0], a[1][1], a[2][2]].sort((x, y) => y - x);
}

/** The least-squares (a, b) of y ≈ a + b x over n points from the sums, and the residual Σy² − a Σy − b Σxy. */
export function lineFit(n, sy, syy, sx, sxx, sxy) {
  const den = n * sxx - sx * sx;
  const b = den > GUARD ? (n * sxy - sx * sy) / den : 0;
  const a = (sy - b * sx) / n;
  return { a, b, sse: Math.max(0, syy - a * sy - b * sxy) };
}
