// WP04P5's "we must normalize the direction vectors in the fragment shader", read from a fragment
// shader's code (grader/core/measure/fragment-normals.js): interpolated vectors that enter dot()
// or reflect() as they come are named; normalised ones, positions and colours are not.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { unnormalisedInputs } from '../../grader/core/measure/fragment-normals.js';

const glsl = (body, decl = 'varying vec3 N, L, E;') => ({ glsl: ['attribute vec4 a; void main() { gl_Position = a; }', `precision mediump float;\n${decl}\nvoid main() {\n${body}\n}`], wgsl: [] });

test('GLSL: N and L used in dot() as they are interpolated are named; H built by normalize(L + E) normalises neither', () => {
  const fs = glsl('vec3 H = normalize(L + E);\nfloat kd = max(dot(L, N), 0.0);\nfloat ks = pow(max(dot(N, H), 0.0), 10.0);\ngl_FragColor = vec4(vec3(kd + ks), 1.0);');
  assert.deepEqual(unnormalisedInputs(fs), ['N', 'L']);
});

test('GLSL: normalised in the fragment shader, directly, through a name, by length() or dot(v, v): nothing named', () => {
  assert.deepEqual(unnormalisedInputs(glsl('vec3 n = normalize(N);\nvec3 l = normalize(L.xyz);\ngl_FragColor = vec4(vec3(dot(n, l)), 1.0);')), []);
  assert.deepEqual(unnormalisedInputs(glsl('vec3 n = N;\nn = normalize(n);\nL = normalize(L);\ngl_FragColor = vec4(vec3(dot(n, L)), 1.0);')), []);
  assert.deepEqual(unnormalisedInputs(glsl('vec3 n = N / length(N);\nvec3 l = L * inversesqrt(dot(L, L));\ngl_FragColor = vec4(vec3(dot(n, l)), 1.0);')), []);
});

test('GLSL: a position inside normalize(lightPos - p) and a colour in dot() are not directions used as they come', () => {
  const fs = glsl('vec3 w_i = normalize(vec3(0.0, 0.0, 1.0) - p);\ngl_FragColor = vec4(v_Color * dot(normalize(n), w_i) + dot(v_Color, vec3(0.3)), 1.0);', 'varying vec3 p, n, v_Color;');
  assert.deepEqual(unnormalisedInputs(fs), []);
});

test('GLSL ES 3.00: `in highp vec4 v_n;` used in reflect() is named; the vertex shader is not read', () => {
  const src = { glsl: ['#version 300 es\nin vec4 a; out vec4 v_n; void main() { v_n = normalize(a); gl_Position = a; }',
    '#version 300 es\nprecision mediump float;\nin highp vec4 v_n;\nout vec4 color;\nvoid main() { vec3 r = reflect(vec3(0.0, 0.0, -1.0), v_n.xyz); color = vec4(r, 1.0); }'], wgsl: [] };
  assert.deepEqual(unnormalisedInputs(src), ['v_n']);
});

test('WGSL: a struct input\'s @location fields used in dot() as they come are named, normalised ones not', () => {
  const wgsl = `struct VOut { @builtin(position) pos: vec4f, @location(0) normal: vec3<f32>, @location(1) w_o: vec3f, @location(2) color: vec3f };
@vertex fn vs(@location(0) p: vec4f) -> VOut { var o: VOut; o.pos = p; o.normal = p.xyz; o.w_o = p.xyz; o.color = p.xyz; return o; }
@fragment fn fs(input: VOut) -> @location(0) vec4f {
  let n = input.normal; // as it comes
  let w_o = normalize(input.w_o);
  return vec4f(input.color * max(dot(input.normal, w_o), 0.0) + dot(input.color, w_o), 1.0);
}`;
  assert.deepEqual(unnormalisedInputs({ glsl: [], wgsl: [wgsl] }), ['input.normal']);
  assert.deepEqual(unnormalisedInputs({ glsl: [], wgsl: [wgsl.replace('dot(input.normal', 'dot(normalize(input.normal)')] }), []);
});

test('WGSL: @location parameters of the @fragment function', () => {
  const wgsl = '@fragment fn main(@location(0) n: vec3f, @location(1) l: vec3f) -> @location(0) vec4f { let d = max(dot(normalize(n), l), 0.0); return vec4f(d, d, d, 1.0); }';
  assert.deepEqual(unnormalisedInputs({ glsl: [], wgsl: [wgsl] }), ['l']);
});
