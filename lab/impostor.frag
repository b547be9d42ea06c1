// Bench only: the exact impostor. Each fragment casts its ray from the eye (eye space: the
// origin), intersects the unit sphere and applies the same Phong reflection model as WP04P5.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform mat4 V;
uniform vec2 tanHalf;       // (tan(fovy/2) * aspect, tan(fovy/2))
uniform vec4 lightPos;
uniform vec3 kd;
uniform vec3 ks;
uniform float s;
uniform vec3 Le;
uniform vec3 La;
uniform bool blinnPhong;
varying vec2 vNdc;

void main() {
  vec3 d = normalize(vec3(vNdc * tanHalf, -1.0));   // the ray through this pixel, eye space
  vec3 c = (V * vec4(0.0, 0.0, 0.0, 1.0)).xyz;      // the sphere's centre in eye space
  float b = dot(d, c);
  float disc = b * b - dot(c, c) + 1.0;             // |t d - c|^2 = 1
  if (disc < 0.0) discard;
  vec3 x = (b - sqrt(disc)) * d;                    // the near hit
  vec3 n = normalize(x - c);                        // V is rigid: the normal is x - c
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
  gl_FragColor = vec4(kd * L_i * max(cosTheta, 0.0) + ks * L_i * highlight + kd * La, 1.0);
}
