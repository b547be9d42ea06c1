// WP04P2: the colour interpolated from the triangle's vertices.
precision mediump float;
varying vec4 vColor;

void main() {
  gl_FragColor = vColor;
}
