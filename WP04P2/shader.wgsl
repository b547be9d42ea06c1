// WP04P2 in WebGPU: as WP04P1; the depth test and culling are pipeline state (webgpu.js).
struct Uniforms {
  P: mat4x4f,   // projection (WebGPU: clip-space z in [0, 1])
  V: mat4x4f,   // view (lookAt)
};
@group(0) @binding(0) var<uniform> u: Uniforms;

struct VertexOut {
  @builtin(position) position: vec4f,
  @location(0) color: vec4f,
};

@vertex
fn main_vs(@location(0) aPosition: vec4f) -> VertexOut {  // x, y, z from the buffer; w = 1
  var out: VertexOut;
  // c = 0.5 p + 0.5: the normal of a unit sphere is its position
  out.color = vec4f(0.5 * aPosition.xyz + 0.5, 1.0);
  out.position = u.P * u.V * aPosition;
  return out;
}

// The colour interpolated from the triangle's vertices
@fragment
fn main_fs(@location(0) color: vec4f) -> @location(0) vec4f {
  return color;
}
