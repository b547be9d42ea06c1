// Bench only: flat shading. The Phong reflection model of WP04P4, evaluated once per triangle: all
// three vertices light the triangle's centroid with the centroid's normal, so they agree.
attribute vec4 aPosition;   // a vertex of the unit sphere (w = 1)
attribute vec3 aFace;       // the centroid of its triangle
uniform mat4 P;
uniform mat4 V;
uniform mat3 N;
uniform vec4 lightPos;
uniform vec3 kd;
uniform vec3 ks;
uniform float s;
uniform vec3 Le;
uniform vec3 La;
uniform bool blinnPhong;
varying vec4 vColor;

void main() {
  vec3 x = (V * vec4(aFace, 1.0)).xyz;
  vec3 n = normalize(N * aFace);
  vec4 l = V * lightPos;
  vec3 toLight = l.xyz - x;
  vec3 w_i = l.w == 0.0 ? normalize(-l.xyz) : normalize(toLight);
  vec3 w_o = -normalize(x);
  vec3 L_i = l.w == 0.0 ? Le : Le / dot(toLight, toLight);
  float cosTheta = dot(n, w_i);
  vec3 w_r = 2.0 * cosTheta * n - w_i;
  vec3 h = w_i + w_o;
  float cosPhi = blinnPhong ? (dot(h, h) > 0.0 ? dot(n, normalize(h)) : 0.0) : dot(w_r, w_o);
  float highlight = cosTheta > 0.0 && cosPhi > 0.0 ? pow(cosPhi, s) : 0.0;
  vColor = vec4(kd * L_i * max(cosTheta, 0.0) + ks * L_i * highlight + kd * La, 1.0);
  gl_Position = P * V * aPosition;
}
