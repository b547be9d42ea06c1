// WP04P4: the Phong reflection model per vertex (Gouraud shading), computed in eye space, where
// the eye is at the origin; the colour is interpolated across each triangle.
attribute vec4 aPosition;   // a vertex of the unit sphere (w = 1)
uniform mat4 P;             // projection
uniform mat4 V;             // view, recomputed by lookAt as the camera orbits
uniform mat3 N;             // normal matrix of V M (M = identity): N = ((V M)^T)^-1
uniform vec4 lightPos;      // world space: w = 0 a directional light (direction xyz), w = 1 a point light
uniform vec3 kd;            // diffuse reflection coefficient (k_a = k_d)
uniform vec3 ks;            // specular reflection coefficient
uniform float s;            // shininess
uniform vec3 Le;            // light emission (a point light: its intensity)
uniform vec3 La;            // ambient light
uniform bool blinnPhong;    // the specular term: Phong (false) or Blinn-Phong (true)
varying vec4 vColor;

void main() {
  vec4 pos = aPosition;                 // pos = M * aPosition with M = identity
  vec3 x = (V * pos).xyz;               // the surface point in eye space
  vec3 n = normalize(N * pos.xyz);      // unit sphere: n = p, taken to eye space by N
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
  vColor = vec4(L_rd + L_rs + L_ra, 1.0);
  gl_Position = P * V * pos;
}
