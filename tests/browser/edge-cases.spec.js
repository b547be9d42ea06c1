// The numerical edge cases of tools/edge-cases.js, each for Gouraud (WP04P4) and Phong shading
// (WP04P5), in WebGL 2 and, where the languages can part, in WebGPU (WebGL 1 runs the same GLSL),
// against the exact reference: each step's interior RMSE and silhouette within a bound per case,
// wherever the case allows one; never a NaN-black or saturated pixel where the reference is not.
// The errors are printed.
import { test, expect, open, errorAgainstReference } from './fixtures.js';
import { EDGE_CASES, STEP } from '../../tools/edge-cases.js';

// Interior RMSE bounds, in 8-bit steps, per step; null where no bound can apply, and why:
// - level 0 is a tetrahedron: its silhouette and its interpolated normals are far from the sphere's;
// - Phong shading with a point light ON the surface: it lights none of the true sphere
//   ((p_l − p) · p = p_l · p − 1 ≤ 0), but the flat triangles lie inside it, so the mesh near the
//   light faces it and 1/r² makes them glow. Gouraud evaluates at the vertices, which lie on the
//   sphere, and so agrees with the reference there;
// - s = 0 puts a step in the picture where w_r · w_o = 0, which the mesh's normals move;
// - kd = 0 leaves Gouraud only its interpolated highlight (no diffuse term to hide its error).
// The near and far planes that cut the sphere are held to the default bound: there WebGPU's clip
// space (z in [0, 1]) and WebGL's ([−1, 1]) really differ, and the projection must clip where the
// exact render does.
const RMSE_BOUND = {
  WP04P4: { default: 1.5, 'level 0': null, 'shininess s = 0': 4, 'kd = 0 (so ka = 0)': 2.5 },
  WP04P5: { default: 1.5, 'level 0': null, 'shininess s = 0': 4, 'point light on the surface': null },
};
// Silhouette: pixels where the picture's coverage differs from the exact render's, as a share of
// the render's sphere pixels; null for level 0 (a tetrahedron's outline is not a circle's). Where
// the near plane cuts the sphere only a thin ring is left (1,216 px at 96 px, against 5,276), and
// both its edges, the silhouette and the cut, count: 24 px measured, a projection that clips
// elsewhere misses the ring whole.
const SILHOUETTE_BOUND = { default: 0.005, 'level 0': null, 'the near plane cuts the sphere': 0.03 };
// Pixels saturated (a channel at 255) where the exact render's is not, per method: none, but where
// the method breaks. Gouraud with s = 0 interpolates across the step that max(w_r · w_o, 0)^0 makes
// at w_r · w_o = 0 (34 px measured at 96 px); with a far plane at 3.5 or 2.5 two pixels of the
// interpolated highlight saturate (2 px in either); Phong shading with a point light on the surface: the
// glowing flat triangles above (48 px). A point light without 1/r² saturates thousands.
const SATURATED_BOUND = {
  WP04P4: { default: 0, 'shininess s = 0': 50, 'the far plane cuts the sphere': 4, 'the far plane cuts the visible side': 4 },
  WP04P5: { default: 0, 'point light on the surface': 64 },
};
const boundOf = (table, name) => (name in table ? table[name] : table.default);
// Cases that only scale a term of the same arithmetic (a shininess far from 0, a coefficient at 0
// or at its greatest, a grazing light) run under WebGL 2 alone: the WGSL twins do the GLSL's
// arithmetic step for step, which webgpu.spec.js holds pixel for pixel in six views a step. Under
// every API run the cases where the two languages or their pipelines can part: pow at 0 and below
// 1, a negative base behind the sphere, normalize(0), a far light's large numbers, the mesh's ends,
// the canvas's aspect and the clip planes (WebGPU's clip z is [0, 1], WebGL's [−1, 1]).
const SCALES_A_TERM = new Set(['s = 1', 's = 1000', 's = 10000', 'ks = 0', 'kd = 0 (so ka = 0)', 'Le = 0', 'La = 0', 'all at their maximum', 'light grazing (from the side)']);

for (const c of EDGE_CASES) {
  test(`edge case: ${c.name}`, SCALES_A_TERM.has(c.name) ? { tag: '@any-api' } : {}, async ({ page }, testInfo) => {
    const lines = [];
    const all = {};
    for (const step of ['WP04P4', 'WP04P5']) {
      await open(page, `/${step}/`, { orbit: 0, angle: 0, size: 96, ...c.params });
      const stats = await errorAgainstReference(page);
      lines.push(`${step}: RMSE ${(stats.rmse / STEP).toFixed(2)}/255, max ${(stats.maxError / STEP).toFixed(1)}/255, ` +
        `silhouette ${stats.silhouetteMismatch} of ${stats.spherePixels} px, NaN-black ${stats.nanLike}, saturated ${stats.saturated}`);
      all[step] = stats;
    }
    testInfo.annotations.push({ type: 'error', description: lines.join('; ') });
    console.log(`[${testInfo.project.name}] ${c.name}: ${lines.join('; ')}`);
    for (const [step, stats] of Object.entries(all)) {
      expect(stats.nanLike, `${step}: NaN-black pixels`).toBe(0);
      expect(stats.spherePixels).toBeGreaterThan(0);
      expect(stats.saturated, `${step}: saturated pixels where the reference is not`).toBeLessThanOrEqual(boundOf(SATURATED_BOUND[step], c.name));
      const rmse = boundOf(RMSE_BOUND[step], c.name);
      if (rmse !== null) expect(stats.rmse / STEP, `${step}: interior RMSE in 8-bit steps`).toBeLessThanOrEqual(rmse);
      const silhouette = boundOf(SILHOUETTE_BOUND, c.name);
      if (silhouette !== null) expect(stats.silhouetteMismatchRatio, `${step}: silhouette mismatch`).toBeLessThanOrEqual(silhouette);
    }
  });
}

test('a far point light, seen from an orbit angle: within 1/255 of the exact render, as the directional light is', async ({ page }) => {
  // far away (p_l = (0, 0, 1000), L_e = 10⁶) a point light is the directional light (0, 0, −1): the
  // exact render of either is the same picture within rounding, and the page must draw it
  for (const params of [{ light: 'point', lx: 0, ly: 0, lz: 1000, Le: 1e6 }, {}]) {
    const s = await open(page, '/WP04P5/', { orbit: 0, angle: 0.7, size: 96, ...params });
    expect(s.light.position).toEqual(params.light ? [0, 0, 1000, 1] : [0, 0, -1, 0]);
    const stats = await errorAgainstReference(page);
    expect(stats.rmse / STEP, `${s.light.position}: RMSE against the exact render, 8-bit steps`).toBeLessThanOrEqual(1);
    expect(stats.silhouetteMismatchRatio).toBeLessThanOrEqual(0.005);
  }
});
