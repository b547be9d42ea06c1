// WP04P5: Phong shading. The vertex shader only moves the point and its normal to eye space;
// the reflection model is evaluated per fragment.
attribute vec4 aPosition;   // a vertex of the unit sphere (w = 1)
uniform mat4 P;             // projection
uniform mat4 V;             // view, recomputed by lookAt as the camera orbits
uniform mat3 N;             // normal matrix of V M (M = identity): N = ((V M)^T)^-1
varying vec3 vPosition;     // the surface point in eye space
varying vec3 vNormal;       // its normal in eye space (shortened by interpolation)

void main() {
  vec4 pos = aPosition;     // pos = M * aPosition with M = identity
  vPosition = (V * pos).xyz;
  vNormal = N * pos.xyz;    // unit sphere: n = p
  gl_Position = P * V * pos;
}
