// Bench only: flat shading in WebGPU, the twin of lab/flat.vert. The Phong reflection model of
// WP04P4, evaluated once per triangle: all three vertices light the triangle's centroid with the
// centroid's normal, so they agree and the interpolated colour is the triangle's one colour.
struct Uniforms {
  P: mat4x4f,         // projection (WebGPU: clip-space z in [0, 1])
  V: mat4x4f,         // view
  N: mat3x3f,         // normal matrix of V M (M = identity)
  lightPos: vec4f,    // world space: w = 0 a directional light, w = 1 a point light
  kd: vec3f,          // diffuse reflection coefficient (k_a = k_d)
  ks: vec3f,          // specular reflection coefficient
  s: f32,             // shininess
  Le: vec3f,          // light emission
  La: vec3f,          // ambient light
  blinnPhong: u32,    // the specular term: Phong (0) or Blinn-Phong (1)
};
@group(0) @binding(0) var<uniform> u: Uniforms;

struct VertexOut {
  @builtin(position) position: vec4f,
  @location(0) color: vec4f,
};

@vertex
fn main_vs(@location(0) aPosition: vec4f,   // a vertex of the unit sphere (w = 1)
           @location(1) aFace: vec3f) -> VertexOut {  // the centroid of its triangle
  var out: VertexOut;
  let x = (u.V * vec4f(aFace, 1.0)).xyz;
  let n = normalize(u.N * aFace);
  let l = u.V * u.lightPos;
  let directional = l.w == 0.0;
  let toLight = l.xyz - x;
  let w_i = select(normalize(toLight), normalize(-l.xyz), directional);
  let w_o = -normalize(x);
  let L_i = select(u.Le / dot(toLight, toLight), u.Le, directional);
  let cosTheta = dot(n, w_i);
  // L_r,d = k_d L_i max(n . w_i, 0); Phong: w_r = 2 (w_i . n) n - w_i; Blinn-Phong: w_h
  let w_r = 2.0 * cosTheta * n - w_i;
  let h = w_i + w_o;
  let cosPsi = select(0.0, dot(n, h * inverseSqrt(max(dot(h, h), 1e-30))), dot(h, h) > 0.0);
  let cosPhi = select(dot(w_r, w_o), cosPsi, u.blinnPhong == 1u);
  // L_r,s = k_s L_i max(cos, 0)^s; L_r,a = k_a L_a
  let highlight = select(0.0, pow(max(cosPhi, 1e-30), u.s), cosTheta > 0.0 && cosPhi > 0.0);
  out.color = vec4f(u.kd * L_i * max(cosTheta, 0.0) + u.ks * L_i * highlight + u.kd * u.La, 1.0);
  out.position = u.P * u.V * aPosition;
  return out;
}

@fragment
fn main_fs(@location(0) color: vec4f) -> @location(0) vec4f {
  return color;
}
