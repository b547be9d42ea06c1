// A built picture for the shading fits' tests: a unit sphere seen by an orthographic camera, each
// pixel coloured by shade(n) for its view-space normal n, on a light grey background.

/** A w×w picture ({ width, height, data }) of a sphere r pixels in radius, shaded by shade(n) → [r, g, b] in 0..1. */
export function spherePicture(shade, w = 160, r = 64) {
  const data = new Uint8Array(w * w * 4);
  for (let y = 0; y < w; y++) for (let x = 0; x < w; x++) {
    const nx = (x + 0.5 - w / 2) / r, ny = -(y + 0.5 - w / 2) / r, q = nx * nx + ny * ny;
    const col = q <= 1 ? shade([nx, ny, Math.sqrt(1 - q)]) : [0.95, 0.95, 0.95];
    data.set([...col.map((v) => Math.round(255 * Math.min(1, Math.max(0, v)))), 255], 4 * (y * w + x));
  }
  return { width: w, height: w, data };
}
