// The unlit steps' screenshot views: foundation.spec.js holds them to their WebGL 2 baselines, and
// webgpu.spec.js holds WebGPU's pictures equal to WebGL 2's in the same views (so the screenshots
// run under WebGL 2 only). Each view: its baseline's name and the URL parameters.

/** WP04P1 at these levels. */
export const P1_VIEWS = [0, 2, 5].map((level) => ({ name: `WP04P1-level${level}`, params: { level } }));

/** WP04P2 at level 4, with each toggle as the slides try it. */
export const P2_VIEWS = Object.entries({
  default: {},
  'no-depth-no-cull': { depth: 0, cull: 0 },
  'depth-only': { depth: 1, cull: 0 },
  'cull-only': { depth: 0, cull: 1 },
  clockwise: { cw: 1 },
}).map(([name, params]) => ({ name: `WP04P2-${name}`, label: name, params: { level: 4, ...params } }));
