// The numerical edge cases of tools/edge-cases.js, each for Gouraud (WP04P4) and Phong shading
// (WP04P5), against the exact reference: never a NaN-black or saturated pixel where the reference
// is not; Phong shading stays within its bound wherever the mesh is fine enough. The errors are
// printed.
import { test, expect, open, scene, canvasPixels, errorAgainstReference } from './fixtures.js';
import { EDGE_CASES, STEP } from '../../tools/edge-cases.js';

// Phong shading's interior RMSE bound, in 8-bit steps, and no saturated pixel where the reference
// has none. Where it breaks, and why: level 0 is a tetrahedron, whose interpolated normals are far
// from the sphere's; s = 0 puts a step in the picture where w_r · w_o = 0; a point light ON the
// surface lights none of the true sphere ((p_l − p) · p = p_l · p − 1 ≤ 0), but the flat triangles
// lie inside it, so the mesh near the light faces it and 1/r² makes them glow.
const PHONG_BOUND = { default: 1.5, 'level 0': null, 'shininess s = 0': 4, 'point light on the surface': null };
// Pixels saturated (a channel at 255) where the exact render's is not, per method: none, but where
// the method breaks. Gouraud with s = 0 interpolates across the step that max(w_r · w_o, 0)^0 makes
// at w_r · w_o = 0 (34 px measured at 96 px); the far plane cuts the mesh's interpolated highlight
// differently from the true sphere's (2 px); Phong shading with a point light on the surface: the
// glowing flat triangles above (48 px). A point light without 1/r² saturates thousands.
const SATURATED_BOUND = {
  WP04P4: { default: 0, 'shininess s = 0': 50, 'the far plane cuts the sphere': 4 },
  WP04P5: { default: 0, 'point light on the surface': 64 },
};

for (const c of EDGE_CASES) {
  test(`edge case: ${c.name}`, async ({ page }, testInfo) => {
    const lines = [];
    const errors = {};
    const all = {};
    for (const step of ['WP04P4', 'WP04P5']) {
      await open(page, `/${step}/`, { orbit: 0, angle: 0, size: 96, ...c.params });
      const stats = await errorAgainstReference(page);
      errors[step] = stats.rmse / STEP;
      lines.push(`${step}: RMSE ${(stats.rmse / STEP).toFixed(2)}/255, max ${(stats.maxError / STEP).toFixed(1)}/255, ` +
        `silhouette ${stats.silhouetteMismatch} px, NaN-black ${stats.nanLike}, saturated ${stats.saturated}`);
      all[step] = stats;
    }
    testInfo.annotations.push({ type: 'error', description: lines.join('; ') });
    console.log(`[${testInfo.project.name}] ${c.name}: ${lines.join('; ')}`);
    for (const [step, stats] of Object.entries(all)) {
      expect(stats.nanLike, `${step}: NaN-black pixels`).toBe(0);
      expect(stats.spherePixels).toBeGreaterThan(0);
      const saturated = SATURATED_BOUND[step][c.name] ?? SATURATED_BOUND[step].default;
      expect(stats.saturated, `${step}: saturated pixels where the reference is not`).toBeLessThanOrEqual(saturated);
    }
    const bound = c.name in PHONG_BOUND ? PHONG_BOUND[c.name] : PHONG_BOUND.default;
    if (bound !== null) expect(errors.WP04P5, 'Phong shading RMSE in 8-bit steps').toBeLessThanOrEqual(bound);
  });
}

test('a far point light agrees with the directional light', async ({ page }) => {
  await open(page, '/WP04P5/', { orbit: 0, angle: 0.7, size: 96, light: 'point', lx: 0, ly: 0, lz: 1000, Le: 1e6 });
  const far = await canvasPixels(page);
  const s = await open(page, '/WP04P5/', { orbit: 0, angle: 0.7, size: 96 });
  expect(s.light.position).toEqual([0, 0, -1, 0]);
  const directional = await canvasPixels(page);
  let worst = 0;
  for (let i = 0; i < far.data.length; i++) worst = Math.max(worst, Math.abs(far.data[i] - directional.data[i]));
  expect(worst).toBeLessThanOrEqual(2);
  expect((await scene(page)).exercise).toBe('WP04P5');
  // and both are the right picture, not only the same one
  expect((await errorAgainstReference(page)).rmse / STEP, 'RMSE against the exact render, 8-bit steps').toBeLessThanOrEqual(1);
});
