// window.scene, the page contract's picture of a step (DESIGN.md): its camera and the fields its
// parameters give it. Pure: common/step.js publishes it after every frame, and the grader builds
// the same scene from a query to render our reference exactly (grader/core/reference-state.js).
import { AT, EYE_DISTANCE, FOVY, UP } from './course.js';

/**
 * The camera at angle 0: it looks at the centre from e = (0, 0, r); a step that orbits moves e to
 * (r sin α, 0, r cos α) in each frame. `aspect`: the canvas's width / height.
 */
export function cameraOf(state, aspect) {
  return { eye: [0, 0, EYE_DISTANCE], at: [...AT], up: [...UP], fovy: FOVY, aspect, near: state.near ?? 0.1, far: state.far ?? 10 };
}

/** window.scene's fields from the step's parameters, in place; a step without one leaves it out. */
export function describeScene(scene, state) {
  scene.level = state.level;
  if ('depth' in state) {
    scene.depthTest = state.depth;
    scene.cullFace = state.cull;
    scene.frontFace = state.cw ? 'cw' : 'ccw';
  }
  if ('orbit' in state) {
    // the lit steps test depth and cull back faces, as WP04P2 taught
    scene.depthTest = true;
    scene.cullFace = true;
    scene.frontFace = 'ccw';
    scene.orbit = state.orbit;
    scene.angle = state.angle;
  }
  if ('light' in state) {
    scene.light ??= { position: [0, 0, 0, 0] };
    const p = scene.light.position;
    p[0] = state.lx;
    p[1] = state.ly;
    p[2] = state.lz;
    p[3] = state.light === 'point' ? 1 : 0; // homogeneous: w = 1 a point, w = 0 a direction
    scene.light.Le = state.Le;
    if ('La' in state) scene.light.La = state.La;
  }
  if ('kd' in state) {
    scene.material ??= {};
    scene.material.kd = state.kd;
    if ('La' in state) scene.material.ka = state.kd; // k_a = k_d
    if ('ks' in state) {
      scene.material.ks = state.ks;
      scene.material.s = state.s;
    }
  }
  if ('model' in state) scene.model = state.model;
  return scene;
}
