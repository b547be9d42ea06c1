// P1/P2: normals shown as colours (c = 0.5·n + 0.5), read back and compared with a sphere's.
import { solve3, det3 } from './linear.js';

/**
 * P1/P2: do the colours decode to unit normals d = 2c − 1, and is d a rotation of the normal a
 * sphere has at that pixel (front faces) or a reflection of it (the inside of the far side)?
 */
export function normalColours(pts, thresholds) {
  if (pts.length < thresholds.minFitSamples) return null;
  let lenErr = 0;
  const mean = [0, 0, 0];
  for (const s of pts) {
    const d = s.c.map((v) => 2 * v - 1);
    s.d = d;
    lenErr += Math.abs(Math.hypot(...d) - 1);
    for (let k = 0; k < 3; k++) mean[k] += s.c[k] / pts.length;
  }
  let spread = 0;
  for (const s of pts) spread += s.c.reduce((a, v, k) => a + (v - mean[k]) ** 2, 0);
  spread = Math.sqrt(spread / pts.length);
  // least squares d ≈ M n, row by row
  const NtN = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  const Ntd = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  for (const s of pts) {
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) { NtN[i][j] += s.n[i] * s.n[j]; Ntd[i][j] += s.n[i] * s.d[j]; }
    }
  }
  const M = [0, 1, 2].map((row) => solve3(NtN, [0, 1, 2].map((i) => Ntd[i][row])));
  let res = 0;
  for (const s of pts) {
    for (let row = 0; row < 3; row++) {
      res += (s.d[row] - (M[row][0] * s.n[0] + M[row][1] * s.n[1] + M[row][2] * s.n[2])) ** 2;
    }
  }
  return { unitError: lenErr / pts.length, spread, residual: Math.sqrt(res / pts.length), det: det3(M) };
}

/** Do the colours read by normalColours (`nc`) show normals facing the viewer (a rotation, fitted well)? */
export const facesViewer = (nc, thresholds) =>
  !!nc && nc.det >= thresholds.facingDeterminant && nc.residual <= thresholds.facingResidual;
