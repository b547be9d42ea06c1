// WP04P5: Phong shading. The Phong reflection model per fragment, in eye space; interpolation
// shortens direction vectors, so every one is normalised here again.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform mat4 V;             // view
uniform vec4 lightPos;      // world space: w = 0 a directional light (direction xyz), w = 1 a point light
uniform vec3 kd;            // diffuse reflection coefficient (k_a = k_d)
uniform vec3 ks;            // specular reflection coefficient
uniform float s;            // shininess
uniform vec3 Le;            // light emission (a point light: its intensity)
uniform vec3 La;            // ambient light
uniform bool blinnPhong;    // the specular term: Phong (false) or Blinn-Phong (true)
varying vec3 vPosition;
varying vec3 vNormal;

void main() {
  vec3 x = vPosition;                   // the surface point in eye space
  vec3 n = normalize(vNormal);          // re-normalised for every fragment
  vec4 l = V * lightPos;                // the light in eye space
  vec3 toLight = l.xyz - x;
  // w_i = normalize(-l_e) (directional) or normalize(p_l - x) (point); w_o = -normalize(V pos)
  vec3 w_i = l.w == 0.0 ? normalize(-l.xyz) : normalize(toLight);
  vec3 w_o = -normalize(x);
  // L_i = L_e, or I / ||p_l - x||^2 for a point light
  vec3 L_i = l.w == 0.0 ? Le : Le / dot(toLight, toLight);
  float cosTheta = dot(n, w_i);
  // L_r,d = k_d L_i max(n . w_i, 0)
  vec3 L_rd = kd * L_i * max(cosTheta, 0.0);
  // Phong: w_r = 2 (w_i . n) n - w_i, cos(phi) = w_r . w_o
  // Blinn-Phong: w_h = normalize(w_i + w_o), cos(psi) = n . w_h (no halfway vector when w_i = -w_o)
  vec3 w_r = 2.0 * cosTheta * n - w_i;
  vec3 h = w_i + w_o;
  float cosPhi = blinnPhong ? (dot(h, h) > 0.0 ? dot(n, normalize(h)) : 0.0) : dot(w_r, w_o);
  // L_r,s = k_s L_i max(cos, 0)^s; none on the side facing away from the light
  float highlight = cosTheta > 0.0 && cosPhi > 0.0 ? pow(cosPhi, s) : 0.0;
  vec3 L_rs = ks * L_i * highlight;
  // L_r,a = k_a L_a with k_a = k_d
  vec3 L_ra = kd * La;
  gl_FragColor = vec4(L_rd + L_rs + L_ra, 1.0);
}
