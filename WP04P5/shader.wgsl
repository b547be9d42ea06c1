// WP04P5 in WebGPU: Phong shading. The vertex shader only moves the point and its normal to eye
// space; the Phong reflection model is evaluated per fragment, where interpolation has shortened
// the direction vectors, so every one is normalised again.
struct Uniforms {
  P: mat4x4f,         // projection (WebGPU: clip-space z in [0, 1])
  V: mat4x4f,         // view, recomputed by lookAt as the camera orbits
  N: mat3x3f,         // normal matrix of V M (M = identity): N = ((V M)^T)^-1
  lightPos: vec4f,    // world space: w = 0 a directional light (direction xyz), w = 1 a point light
  kd: vec3f,          // diffuse reflection coefficient (k_a = k_d)
  ks: vec3f,          // specular reflection coefficient
  s: f32,             // shininess
  Le: vec3f,          // light emission (a point light: its intensity)
  La: vec3f,          // ambient light
  blinnPhong: u32,    // the specular term: Phong (0) or Blinn-Phong (1)
};
@group(0) @binding(0) var<uniform> u: Uniforms;

struct VertexOut {
  @builtin(position) position: vec4f,
  @location(0) x: vec3f,    // the surface point in eye space
  @location(1) n: vec3f,    // its normal in eye space (shortened by interpolation)
};

@vertex
fn main_vs(@location(0) aPosition: vec4f) -> VertexOut {  // a vertex of the unit sphere (w = 1)
  var out: VertexOut;
  let pos = aPosition;                  // pos = M * aPosition with M = identity
  out.x = (u.V * pos).xyz;
  out.n = u.N * pos.xyz;                // unit sphere: n = p
  out.position = u.P * u.V * pos;
  return out;
}

@fragment
fn main_fs(in: VertexOut) -> @location(0) vec4f {
  let x = in.x;                         // the surface point in eye space
  let n = normalize(in.n);              // re-normalised for every fragment
  let l = u.V * u.lightPos;             // the light in eye space
  let directional = l.w == 0.0;
  let toLight = l.xyz - x;
  // w_i = normalize(-l_e) (directional) or normalize(p_l - x) (point); w_o = -normalize(V pos)
  let w_i = select(normalize(toLight), normalize(-l.xyz), directional);
  let w_o = -normalize(x);
  // L_i = L_e, or I / ||p_l - x||^2 for a point light
  let L_i = select(u.Le / dot(toLight, toLight), u.Le, directional);
  let cosTheta = dot(n, w_i);
  // L_r,d = k_d L_i max(n . w_i, 0)
  let L_rd = u.kd * L_i * max(cosTheta, 0.0);
  // Phong: w_r = 2 (w_i . n) n - w_i, cos(phi) = w_r . w_o
  // Blinn-Phong: w_h = normalize(w_i + w_o), cos(psi) = n . w_h (no halfway vector when w_i = -w_o)
  let w_r = 2.0 * cosTheta * n - w_i;
  let h = w_i + w_o;
  let cosPsi = select(0.0, dot(n, h * inverseSqrt(max(dot(h, h), 1e-30))), dot(h, h) > 0.0);
  let cosPhi = select(dot(w_r, w_o), cosPsi, u.blinnPhong == 1u);
  // L_r,s = k_s L_i max(cos, 0)^s; none on the side facing away from the light
  let highlight = select(0.0, pow(max(cosPhi, 1e-30), u.s), cosTheta > 0.0 && cosPhi > 0.0);
  let L_rs = u.ks * L_i * highlight;
  // L_r,a = k_a L_a with k_a = k_d
  let L_ra = u.kd * u.La;
  return vec4f(L_rd + L_rs + L_ra, 1.0);
}
