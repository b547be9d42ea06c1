// WP04P3 in WebGPU: Gouraud shading. The diffuse reflection is computed per vertex, in world
// space, and the colour is interpolated across each triangle.
struct Uniforms {
  P: mat4x4f,         // projection (WebGPU: clip-space z in [0, 1])
  V: mat4x4f,         // view, recomputed by lookAt as the camera orbits
  lightPos: vec4f,    // world space: w = 0 a directional light (direction xyz), w = 1 a point light
  kd: vec3f,          // diffuse reflection coefficient
  Le: vec3f,          // light emission (a point light: its intensity)
};
@group(0) @binding(0) var<uniform> u: Uniforms;

struct VertexOut {
  @builtin(position) position: vec4f,
  @location(0) color: vec4f,
};

@vertex
fn main_vs(@location(0) aPosition: vec4f) -> VertexOut {  // a vertex of the unit sphere (w = 1)
  var out: VertexOut;
  let pos = aPosition;                  // pos = M * aPosition with M = identity
  let n = normalize(pos.xyz);           // unit sphere: n = p
  let directional = u.lightPos.w == 0.0;
  // w_i = normalize(l) with l = -l_e for a directional light, p_l - x for a point light
  let toLight = u.lightPos.xyz - pos.xyz;
  let w_i = select(normalize(toLight), normalize(-u.lightPos.xyz), directional);
  // L_i = V L_e (V = 1); a point light falls off as 1 / ||p_l - x||^2
  let L_i = select(u.Le / dot(toLight, toLight), u.Le, directional);
  // L_r,d = k_d L_i max(n . w_i, 0)
  let L_rd = u.kd * L_i * max(dot(n, w_i), 0.0);
  out.color = vec4f(L_rd, 1.0);
  out.position = u.P * u.V * pos;
  return out;
}

// The colour interpolated from the triangle's vertices (Gouraud)
@fragment
fn main_fs(@location(0) color: vec4f) -> @location(0) vec4f {
  return color;
}
