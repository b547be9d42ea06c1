// Our five steps as the slides build them: the URL parameters each page reads besides api, size and
// msaa (common/params.js), the shading its window.scene names and the shading errors its level is
// chosen by (common/sphere.js chooseLevel). Each step's main.js and webgpu.js open with their own
// entry (common/step.js openStep), and the grader draws our reference from the same entry
// (grader/core/reference-state.js), so the page and the reference cannot read a query differently.

/** The lit steps' parameters: the canvas's height, the camera's near and far, the level, the orbit, the light and the diffuse material. */
const LIT = ['height', 'near', 'far', 'level', 'orbit', 'angle', 'light', 'lx', 'ly', 'lz', 'kd', 'Le'];
/** The Phong reflection model's besides: ks, s, La and the specular term's form. */
const PHONG_MODEL = [...LIT, 'ks', 's', 'La', 'model'];

/**
 * @type {Record<string, {exercise: string, params: string[], shading: 'normals'|'gouraud'|'phong', rmse: null|'diffuse'|'gouraud'|'phong', inOrder?: true}>}
 * shading: as window.scene says it; rmse: the shading errors chooseLevel weighs (null: the
 * silhouette alone sets the level); inOrder: the page draws with neither the depth test nor
 * culling (the slides' WP04P1), so the face that shows is the last one drawn and its reference is
 * its mesh drawn in order (common/mesh-render.js), not the exact sphere.
 */
export const STEPS = {
  WP04P1: { exercise: 'WP04P1', params: ['level'], shading: 'normals', rmse: null, inOrder: true },
  WP04P2: { exercise: 'WP04P2', params: ['level', 'depth', 'cull', 'cw'], shading: 'normals', rmse: null },
  WP04P3: { exercise: 'WP04P3', params: LIT, shading: 'gouraud', rmse: 'diffuse' },
  WP04P4: { exercise: 'WP04P4', params: PHONG_MODEL, shading: 'gouraud', rmse: 'gouraud' },
  WP04P5: { exercise: 'WP04P5', params: PHONG_MODEL, shading: 'phong', rmse: 'phong' },
};

/** Every parameter a step's page reads: the canvas's api, size and msaa, then the step's own. */
export function paramNames(step) {
  return ['api', 'size', 'msaa', ...step.params];
}
