// The surface per pixel as the grader reads it from what a WebGL page sent (grader/browser/surface.js,
// grader/core/computed/surface.js), on our own lit steps in WebGL 2 and WebGL 1: each pixel's normal
// within 1° of the exact sphere's, the camera found from the page's matrices where the scene says it
// is, and nothing of the grader's own drawing counted or recorded as the page's
// (tests/browser/surface-helpers.js). WebGPU's: surface-webgpu.spec.js.
import { ownStepSurfaceTests } from './surface-helpers.js';

// WebGL 1's steps are WebGL 2's JavaScript and GLSL 1.0 (only getContext differs): one step there
ownStepSurfaceTests([
  ...[['WP04P3', ''], ['WP04P4', '&angle=0.7'], ['WP04P5', '&angle=1.2']].map(([step, query]) => ({ api: 'webgl2', step, query })),
  { api: 'webgl', step: 'WP04P4', query: '&angle=0.7' },
]);
