// WP04P1: a vertex of the unit sphere, seen through the camera.
attribute vec4 aPosition; // x, y, z from the buffer; WebGL fills in w = 1
uniform mat4 P;           // projection
uniform mat4 V;           // view (lookAt)
varying vec4 vColor;

void main() {
  // c = 0.5 p + 0.5: the normal of a unit sphere is its position
  vColor = vec4(0.5 * aPosition.xyz + 0.5, 1.0);
  gl_Position = P * V * aPosition;
}
