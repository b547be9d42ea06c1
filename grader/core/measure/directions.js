// The light directions a fit tries first: 500 nearly even directions on the unit sphere.

/** √5, in the golden angle π·(3 − √5) between one fibonacci direction and the next. */
const ROOT5 = Math.sqrt(5);

function fibonacciDirections(n) {
  const out = [];
  for (let k = 0; k < n; k++) {
    const z = 1 - (2 * (k + 0.5)) / n, r = Math.sqrt(1 - z * z), a = k * Math.PI * (3 - ROOT5);
    out.push([r * Math.cos(a), r * Math.sin(a), z]);
  }
  return out;
}
export const DIRS = fibonacciDirections(500);
