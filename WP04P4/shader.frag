// WP04P4: the colour interpolated from the triangle's vertices (Gouraud).
precision mediump float;
varying vec4 vColor;

void main() {
  gl_FragColor = vColor;
}
