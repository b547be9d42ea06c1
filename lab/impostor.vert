// Bench only: the exact impostor. One screen-filling quad; the fragment shader finds the sphere.
attribute vec2 aCorner;     // (±1, ±1) in normalised device coordinates
varying vec2 vNdc;

void main() {
  vNdc = aCorner;
  gl_Position = vec4(aCorner, 0.0, 1.0);
}
