// Written by `npm run calibrate` (tools/calibrate.js) on 2026-11-23, measured in
// Chromium 156.0.8078.79 at 128, 256, 512 px in 57 s. Do not edit: run the command again.
// tests/browser/calibration.spec.js re-measures every entry.

/**
 * How far the mesh at each level falls inside the unit sphere at worst: 1 − the least distance
 * from the origin to a triangle's plane (tools/reference/measure.js meshDeviation).
 */
export const MAX_DEVIATION = [6.6667e-1, 4.2265e-1, 1.8350e-1, 5.7191e-2, 1.5268e-2, 3.8835e-3, 9.7513e-4, 2.4408e-4, 6.1035e-5];

/** The shininess values of SHADING_TABLE's rows. */
export const SHININESS = [0, 1, 2, 5, 10, 20, 40, 80, 160, 320, 500];

/**
 * How far each lighting step's shading is off at each level, in 8-bit steps (1 = 1/255): the
 * interior RMSE against the exact render with the silhouette left out (shadingError), for the
 * exercises' default view (eye (0, 0, 3), light along the view, kd 0.8, ks 0.5, Le 1, La 0.2),
 * the largest over the canvas sizes above. 0.29 is what rounding to 8 bits alone costs.
 *  - diffuse[level]: WP04P3 (Gouraud, diffuse light only: no shininess)
 *  - gouraud[k][level]: WP04P4 (Gouraud, the Phong reflection model) with s = SHININESS[k]
 *  - phong[k][level]: WP04P5 (Phong shading) with s = SHININESS[k]
 */
export const SHADING_TABLE = {
  diffuse: [122.89, 69.67, 27.11, 8.34, 2.25, 0.64, 0.32, 0.29, 0.29],
  gouraud: [
    [143.72, 94.02, 16.06, 13.95, 9.91, 6.11, 6.12, 4.86, 3.55], // s = 0
    [142.02, 88.26, 37.04, 8.19, 2.55, 0.88, 0.37, 0.23, 0.22], // s = 1
    [139.54, 82.84, 38.76, 6.55, 1.91, 0.54, 0.27, 0.24, 0.24], // s = 2
    [134.22, 76.46, 33.74, 8.03, 2.01, 0.6, 0.29, 0.26, 0.26], // s = 5
    [129.4, 73.35, 30.95, 10.98, 2.86, 0.82, 0.34, 0.28, 0.27], // s = 10
    [126.18, 71.53, 29.28, 10.25, 2.46, 0.84, 0.39, 0.29, 0.28], // s = 20
    [124.45, 70.56, 28.35, 9.36, 3.17, 1.35, 0.48, 0.3, 0.29], // s = 40
    [123.57, 70.06, 27.86, 8.87, 3.01, 1.29, 0.5, 0.32, 0.29], // s = 80
    [123.13, 69.81, 27.6, 8.6, 2.66, 1.1, 0.66, 0.34, 0.29], // s = 160
    [122.91, 69.69, 27.48, 8.46, 2.47, 1.07, 0.72, 0.36, 0.3], // s = 320
    [122.83, 69.64, 27.43, 8.41, 2.39, 0.94, 0.49, 0.37, 0.3], // s = 500
  ],
  phong: [
    [82.46, 53.02, 22.66, 10.33, 4.99, 2.6, 1.57, 1.11, 0.8], // s = 0
    [80.66, 46.81, 17.69, 5.95, 1.68, 0.47, 0.24, 0.22, 0.22], // s = 1
    [77.82, 41.84, 15.67, 5.28, 1.49, 0.44, 0.25, 0.24, 0.24], // s = 2
    [71.42, 36.86, 13.87, 4.77, 1.37, 0.43, 0.27, 0.26, 0.26], // s = 5
    [66.5, 34.9, 13.22, 4.62, 1.34, 0.43, 0.28, 0.27, 0.27], // s = 10
    [63.92, 34.06, 12.93, 4.55, 1.33, 0.43, 0.29, 0.28, 0.28], // s = 20
    [62.92, 33.75, 12.8, 4.53, 1.32, 0.43, 0.29, 0.29, 0.29], // s = 40
    [62.58, 33.65, 12.75, 4.52, 1.32, 0.43, 0.3, 0.29, 0.29], // s = 80
    [62.47, 33.61, 12.74, 4.51, 1.32, 0.43, 0.3, 0.29, 0.29], // s = 160
    [62.44, 33.6, 12.73, 4.51, 1.32, 0.43, 0.3, 0.29, 0.29], // s = 320
    [62.43, 33.6, 12.72, 4.51, 1.32, 0.43, 0.3, 0.29, 0.29], // s = 500
  ],
};
