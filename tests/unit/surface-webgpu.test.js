// The WGSL the grader draws a WebGPU page's surface with (grader/browser/surface-webgpu.js): the
// page's vertex entry point made a plain function and called from ours, whatever shape its inputs
// and result take (located parameters, a struct of them, builtins; a struct result or the clip
// position alone), and the layout of the resources the page bound, from its WGSL's declarations.
// The browser test (tests/browser/surface.spec.js) compiles and draws it on our own WebGPU steps.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { wgslForSurface, layoutEntries } from '../../grader/browser/surface-webgpu.js';

const OURS = /@vertex fn _grVs\((.*)\) -> _GrOut \{\n {2}let r = _grPage\(([^)]*)\);[\s\S]*?o\.clip = ([^;]+);\n {2}o\.p = ([^;]+);\n {2}o\.n = ([^;]+);/;

test('a vertex entry point with located parameters and a struct result: our entry point takes its parameters, calls it, reads its @builtin(position) member', () => {
  const code = `struct U { mvp: mat4x4f }
@group(0) @binding(0) var<uniform> u: U;
struct Out { @location(0) colour: vec4f, @builtin(position) where: vec4f }
@vertex
fn vs(@location(0) aPosition: vec3f, @location(1) aNormal: vec3f, @builtin(vertex_index) i: u32) -> Out {
  var o: Out; o.where = u.mvp * vec4f(aPosition, 1.0); o.colour = vec4f(aNormal, 1.0); return o;
}
@fragment fn fs(@location(0) c: vec4f) -> @location(0) vec4f { return c; }`;
  const w = wgslForSurface(code, 'vs');
  assert.equal(w.why, undefined);
  assert.equal(w.position, 'aPosition');
  assert.equal(w.normal, 'aNormal');
  // the page's entry point is a plain function now, its parameters without their attributes
  assert.match(w.code, /fn _grPage\(aPosition: vec3f, aNormal: vec3f, i: u32\) -> Out \{/);
  assert.doesNotMatch(w.code, /@vertex\s+fn vs/);
  const [, params, args, clip, p, n] = OURS.exec(w.code);
  assert.equal(params, '@location(0) aPosition: vec3f, @location(1) aNormal: vec3f, @builtin(vertex_index) i: u32');
  assert.equal(args, 'aPosition, aNormal, i');
  assert.equal(clip, 'r.where');
  assert.equal(p, 'vec4f(aPosition, 1.0)');
  assert.equal(n, 'vec4f(aNormal.xyz, 0.0)');
});

test('inputs in a struct and the clip position as the result: read through the parameter; no normal input: n = p', () => {
  const code = `struct In { @location(2) pos: vec4<f32>, @location(3) uv: vec2f };
@vertex fn main(input: In) -> @builtin(position) vec4<f32> { return input.pos; }`;
  const w = wgslForSurface(code);
  assert.equal(w.position, 'pos');
  assert.equal(w.normal, null);
  assert.match(w.code, /fn _grPage\(input: In\) -> vec4<f32> \{/);
  const [, , args, clip, p, n] = OURS.exec(w.code);
  assert.equal(args, 'input');
  assert.equal(clip, 'r');
  assert.equal(p, 'vec4f(input.pos)');
  assert.equal(n, 'vec4f(vec4f(input.pos).xyz, 0.0)');
});

test('the entry point the pipeline names, among several; comments are no code', () => {
  const code = `// @vertex fn commented(@location(0) p: vec3f) -> @builtin(position) vec4f
@vertex fn first(@location(0) a: vec2f) -> @builtin(position) vec4f { return vec4f(a, 0.0, 1.0); }
/* @vertex fn hidden() */
@vertex fn second(@location(0) vertex: vec3f) -> @builtin(position) vec4f { return vec4f(vertex, 1.0); }`;
  const w = wgslForSurface(code, 'second');
  assert.equal(w.position, 'vertex');
  assert.match(w.code, /@vertex fn first\(/); // (the other entry point left as it was)
  assert.match(w.code, /fn _grPage\(vertex: vec3f\)/);
  assert.equal(wgslForSurface(code).position, 'a');
});

test('what it cannot read it says: no entry point, no position input, no clip position', () => {
  assert.match(wgslForSurface('@fragment fn fs() -> @location(0) vec4f { return vec4f(1.0); }').why, /vertex entry point was not found/);
  assert.match(wgslForSurface('@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4f { return vec4f(0.0); }').why, /position input/);
  assert.match(wgslForSurface('struct O { @location(0) c: vec4f }\n@vertex fn vs(@location(0) p: vec3f) -> O { var o: O; return o; }').why, /clip position/);
  assert.match(wgslForSurface('@vertex fn other(@location(0) p: vec3f) -> @builtin(position) vec4f { return vec4f(p, 1.0); }', 'vs').why, /vs was not found/);
});

test('the layout of what the page bound: each entry by its declaration, for the bindings the page set only', () => {
  const code = `@group(0) @binding(0) var<uniform> u: U;
@binding(1) @group(0) var<storage, read> points: array<vec4f>;
@group(0) @binding(2) var s: sampler;
@group(0) @binding(3) var t: texture_2d<f32>;
@group(1) @binding(0) var<storage, read_write> out: array<f32>;
@group(0) @binding(4) var d: texture_depth_2d;`;
  const entries = layoutEntries(code, 0, [0, 1, 2, 3].map((binding) => ({ binding })));
  assert.deepEqual(entries, [
    { binding: 0, visibility: 3, buffer: { type: 'uniform' } },
    { binding: 1, visibility: 3, buffer: { type: 'read-only-storage' } },
    { binding: 2, visibility: 3, sampler: { type: 'filtering' } },
    { binding: 3, visibility: 3, texture: { sampleType: 'unfilterable-float', viewDimension: '2d', multisampled: false } },
  ]);
  assert.deepEqual(layoutEntries(code, 1, [{ binding: 0 }]), [{ binding: 0, visibility: 2, buffer: { type: 'storage' } }]);
  assert.match(layoutEntries('@group(0) @binding(0) var img: texture_storage_2d<rgba8unorm, write>;', 0, [{ binding: 0 }]).why, /does not bind again/);
});
