// WP04P3: Gouraud shading. The diffuse reflection is computed per vertex, in world space, and the
// colour is interpolated across each triangle.
attribute vec4 aPosition;   // a vertex of the unit sphere (w = 1)
uniform mat4 P;             // projection
uniform mat4 V;             // view, recomputed by lookAt as the camera orbits
uniform vec4 lightPos;      // world space: w = 0 a directional light (direction xyz), w = 1 a point light
uniform vec3 kd;            // diffuse reflection coefficient
uniform vec3 Le;            // light emission (a point light: its intensity)
varying vec4 vColor;

void main() {
  vec4 pos = aPosition;     // pos = M * aPosition with M = identity
  vec3 n = normalize(pos.xyz); // unit sphere: n = p
  // w_i = normalize(l) with l = -l_e for a directional light, p_l - x for a point light
  vec3 w_i = lightPos.w == 0.0 ? normalize(-lightPos.xyz) : normalize(lightPos.xyz - pos.xyz);
  // L_i = V L_e (V = 1); a point light falls off as 1 / ||p_l - x||^2
  vec3 toLight = lightPos.xyz - pos.xyz;
  vec3 L_i = lightPos.w == 0.0 ? Le : Le / dot(toLight, toLight);
  // L_r,d = k_d L_i max(n . w_i, 0)
  vec3 L_rd = kd * L_i * max(dot(n, w_i), 0.0);
  vColor = vec4(L_rd, 1.0);
  gl_Position = P * V * pos;
}
