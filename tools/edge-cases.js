// Where the methods are weakest: the cases that tests/browser/edge-cases.spec.js holds and that
// npm run bench measures for the lab page's table. Each case is a set of URL parameters for
// WP04P4 (Gouraud) and WP04P5 (Phong shading), on top of a still default view.
export const EDGE_CASES = [
  { name: 'shininess s = 0', params: { s: 0 } },
  { name: 's = 0.5', params: { s: 0.5 } },
  { name: 's = 1', params: { s: 1 } },
  { name: 's = 1000', params: { s: 1000 } },
  { name: 's = 10000', params: { s: 10000 } },
  { name: 'ks = 0', params: { ks: 0 } },
  { name: 'kd = 0 (so ka = 0)', params: { kd: 0 } },
  { name: 'Le = 0', params: { Le: 0 } },
  { name: 'La = 0', params: { La: 0 } },
  { name: 'all at their maximum', params: { kd: 1, ks: 1, Le: 5, La: 1 } },
  { name: 'light grazing (from the side)', params: { lx: -1, ly: 0, lz: 0 } },
  { name: 'light behind the sphere', params: { lx: 0, ly: 0, lz: 1 } },
  { name: 'w_i = −w_o, Blinn-Phong', params: { lx: 0, ly: 0, lz: 1, model: 'blinn-phong' } },
  { name: 'point light on the surface', params: { light: 'point', lx: 0, ly: 0, lz: 1 } },
  { name: 'point light inside the sphere', params: { light: 'point', lx: 0, ly: 0, lz: 0.5 } },
  { name: 'point light far away (= directional)', params: { light: 'point', lx: 0, ly: 0, lz: 1000, Le: 1e6 } },
  { name: 'level 0', params: { level: 0 } },
  { name: 'level 8 (the maximum)', params: { level: 8 } },
  { name: 'a non-square canvas', params: { height: 72 } },
  { name: 'the near plane cuts the sphere', params: { near: 2.3 } },
  // at far = 3.5 the plane cuts only the back half, which culling hides anyway; at 2.5 it cuts the
  // side the camera sees (the visible front spans view depths 2 to 2⅔ from the eye at 3)
  { name: 'the far plane cuts the sphere', params: { far: 3.5 } },
  { name: 'the far plane cuts the visible side', params: { far: 2.5 } },
];

/** An 8-bit step: errors are reported in these. */
export const STEP = 1 / 255;
