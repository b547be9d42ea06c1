// The small solvers the fits share: a 3×3 determinant and a 3×3 linear system (Cramer's rule).

/** The determinant of a 3×3 matrix (rows). */
export const det3 = (m) => m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);

/** x with A x = b (A 3×3, rows), by Cramer's rule; [0, 0, 0] where A is singular. */
export function solve3(A, b) {
  const d = det3(A);
  if (Math.abs(d) < 1e-12) return [0, 0, 0];
  return [0, 1, 2].map((k) => det3(A.map((row, i) => row.map((v, j) => (j === k ? b[i] : v)))) / d);
}
