// Bench only: the exact impostor in WebGPU, the twin of lab/impostor.vert and .frag. One
// screen-filling quad; each fragment casts its ray from the eye (eye space: the origin),
// intersects the unit sphere and applies the same Phong reflection model as WP04P5.
struct Uniforms {
  V: mat4x4f,         // view
  tanHalf: vec2f,     // (tan(fovy/2) * aspect, tan(fovy/2))
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
  @location(0) ndc: vec2f,
};

@vertex
fn main_vs(@location(0) aCorner: vec2f) -> VertexOut {  // (±1, ±1) in normalised device coordinates
  var out: VertexOut;
  out.ndc = aCorner;
  out.position = vec4f(aCorner, 0.0, 1.0);
  return out;
}

@fragment
fn main_fs(in: VertexOut) -> @location(0) vec4f {
  let d = normalize(vec3f(in.ndc * u.tanHalf, -1.0));  // the ray through this pixel, eye space
  let c = (u.V * vec4f(0.0, 0.0, 0.0, 1.0)).xyz;       // the sphere's centre in eye space
  let b = dot(d, c);
  let disc = b * b - dot(c, c) + 1.0;                  // |t d - c|^2 = 1
  if (disc < 0.0) { discard; }
  let x = (b - sqrt(disc)) * d;                        // the near hit
  let n = normalize(x - c);                            // V is rigid: the normal is x - c
  let l = u.V * u.lightPos;
  let directional = l.w == 0.0;
  let toLight = l.xyz - x;
  let w_i = select(normalize(toLight), normalize(-l.xyz), directional);
  let w_o = -normalize(x);
  let L_i = select(u.Le / dot(toLight, toLight), u.Le, directional);
  let cosTheta = dot(n, w_i);
  let w_r = 2.0 * cosTheta * n - w_i;
  let h = w_i + w_o;
  let cosPsi = select(0.0, dot(n, h * inverseSqrt(max(dot(h, h), 1e-30))), dot(h, h) > 0.0);
  let cosPhi = select(dot(w_r, w_o), cosPsi, u.blinnPhong == 1u);
  let highlight = select(0.0, pow(max(cosPhi, 1e-30), u.s), cosTheta > 0.0 && cosPhi > 0.0);
  return vec4f(u.kd * L_i * max(cosTheta, 0.0) + u.ks * L_i * highlight + u.kd * u.La, 1.0);
}
