// The recorder's WebGL arguments as WebGL takes them (grader/browser/webgl-args.js): WebIDL's
// conversions of an index, an enum, a count, an offset and a flag, in WebGL 1, 2 and the extensions.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { webglArgs } from '../../grader/browser/webgl-args.js';

const taken = webglArgs();
const FLOAT = 0x1406, TRIANGLES = 4;

test('an attribute index the page left undefined or NaN is attribute 0, as WebGL takes it', () => {
  const gl = {}; // a page's `gl.vPosition`, a property it never set
  assert.deepEqual(taken('vertexAttribPointer', [gl.vPosition, 4, FLOAT, false, 0, 0]), [0, 4, FLOAT, false, 0, 0]);
  assert.deepEqual(taken('enableVertexAttribArray', [gl.vPosition]), [0]);
  assert.deepEqual(taken('disableVertexAttribArray', [NaN]), [0]);
  assert.deepEqual(taken('vertexAttribDivisor', [undefined, 1]), [0, 1]);
  assert.deepEqual(taken('vertexAttribDivisorANGLE', [null, '1']), [0, 1]);
  assert.deepEqual(taken('vertexAttrib3f', [undefined, 1, '0.5', undefined]), [0, 1, 0.5, NaN]);
});

test('unsigned longs (GLuint, GLenum, GLbitfield) are truncated modulo 2^32', () => {
  assert.deepEqual(taken('enableVertexAttribArray', [2.9]), [2]);
  assert.deepEqual(taken('enableVertexAttribArray', [-1]), [2 ** 32 - 1]);
  assert.deepEqual(taken('enableVertexAttribArray', [2 ** 32 + 3]), [3]);
  assert.deepEqual(taken('enableVertexAttribArray', [Infinity]), [0]);
  assert.deepEqual(taken('enableVertexAttribArray', ['1']), [1]);
  assert.deepEqual(taken('enableVertexAttribArray', [true]), [1]);
  assert.deepEqual(taken('enableVertexAttribArray', [[2]]), [2]); // (an array ToNumber's through its string)
  assert.deepEqual(taken('enableVertexAttribArray', [{ valueOf: () => 1 }]), [1]);
  assert.deepEqual(taken('clear', [String(0x4100)]), [0x4100]);
  assert.deepEqual(taken('bindBuffer', ['34962', null]), [0x8892, null]);
});

test('longs (GLint, GLsizei) are signed, long longs (GLintptr) truncated, booleans ToBoolean', () => {
  assert.deepEqual(taken('drawArrays', [TRIANGLES, -0.5, 2 ** 31]), [TRIANGLES, 0, -(2 ** 31)]);
  assert.deepEqual(taken('drawArrays', [String(TRIANGLES), '3', 6.9]), [TRIANGLES, 3, 6]);
  assert.deepEqual(taken('drawElements', [TRIANGLES, 36, 0x1403, 2 ** 40 + 0.75]), [TRIANGLES, 36, 0x1403, 2 ** 40]);
  assert.deepEqual(taken('drawElements', [TRIANGLES, 36, 0x1403, undefined]), [TRIANGLES, 36, 0x1403, 0]);
  assert.ok(Object.is(taken('drawElements', [TRIANGLES, 3, 0x1403, -0.5])[3], 0), 'never −0');
  assert.equal(taken('drawElements', [TRIANGLES, 3, 0x1403, 2 ** 64 + 2 ** 12])[3], 2 ** 12);
  assert.equal(taken('drawElements', [TRIANGLES, 3, 0x1403, 2 ** 63])[3], -(2 ** 63));
  assert.deepEqual(taken('vertexAttribPointer', [1, '3', FLOAT, 'false', undefined, '12']), [1, 3, FLOAT, true, 0, 12]);
  assert.deepEqual(taken('vertexAttribPointer', [1, 3, FLOAT, 0, 24, NaN]), [1, 3, FLOAT, false, 24, 0]);
  assert.deepEqual(taken('drawArraysInstancedANGLE', [TRIANGLES, 0, 6, undefined]), [TRIANGLES, 0, 6, 0]);
  assert.deepEqual(taken('drawElementsInstanced', [TRIANGLES, 6, 0x1403, 0, '2']), [TRIANGLES, 6, 0x1403, 0, 2]);
});

test('data and objects pass as they are, optional arguments left out stay out, other calls are untouched', () => {
  const data = new Float32Array(3), vao = {};
  assert.deepEqual(taken('bufferData', [0x8892, data, 0x88E4]), [0x8892, data, 0x88E4]);
  assert.equal(taken('bufferData', [0x8892, data, 0x88E4])[1], data);
  assert.deepEqual(taken('bufferData', [0x8892, data, 0x88E4, '1', undefined]), [0x8892, data, 0x88E4, 1, 0]);
  assert.deepEqual(taken('bufferSubData', [0x8892, '8', data]), [0x8892, 8, data]);
  assert.deepEqual(taken('vertexAttrib4fv', [undefined, data]), [0, data]);
  const args = [vao];
  assert.equal(taken('bindVertexArrayOES', args), args);
  assert.equal(taken('writeBuffer', args), args);
  assert.equal(taken('toString', args), args, 'a name on Object.prototype is no signature');
});

test('every WebGL call the recorder hears has its signature, WebGL 1, 2 and the extensions alike', () => {
  const here = path.dirname(fileURLToPath(import.meta.url));
  const source = (f) => readFileSync(path.join(here, '../../grader/browser', f), 'utf8');
  // the calls geometry.js's recordWebGL and extensionsOf wrap, and sent.js's WebGL ones
  const geometry = source('geometry.js');
  const webgl = geometry.slice(geometry.indexOf('function recordWebGL'), geometry.indexOf('function programInfoOf'));
  const sent = source('sent.js');
  const names = new Set([
    ...[...webgl.matchAll(/wrap\(proto, '(\w+)'/g)].map((m) => m[1]),
    ...[...webgl.matchAll(/(\w+ANGLE|\w+OES):/g)].map((m) => m[1]),
    ...[...sent.slice(0, sent.indexOf('GPUDevice')).matchAll(/after\(proto, '(\w+)'/g)].map((m) => m[1]),
    ...['1', '2', '3', '4'].flatMap((k) => [`vertexAttrib${k}f`, `vertexAttrib${k}fv`]),
  ]);
  assert.ok(names.size >= 20, [...names].join(' '));
  // the calls whose arguments are objects or strings only: nothing to convert
  const objectsOnly = new Set(['bindVertexArray', 'bindVertexArrayOES', 'useProgram', 'getUniformLocation']);
  const probe = [undefined, undefined, undefined];
  const missing = [...names].filter((n) => !objectsOnly.has(n) && taken(n, probe) === probe);
  assert.deepEqual(missing, []);
});

test('frida\'s P4, recorded: its index gl.vPosition (undefined) taken as 0, so its mesh and surface are read', () => {
  const here = path.dirname(fileURLToPath(import.meta.url));
  const facts = JSON.parse(readFileSync(path.join(here, '../fixtures/artifacts/frida/WP04P4/facts.json'), 'utf8'));
  assert.equal(facts.geometry.why, undefined, facts.geometry.why);
  assert.equal(facts.geometry.position, 'vPosition');
  assert.ok(facts.geometry.analysed > 1000, `${facts.geometry.analysed} triangles read`);
  assert.equal(facts.surface.why, undefined, facts.surface.why);
  assert.equal(facts.surface.position, 'vPosition');
  assert.ok(facts.surface.covered > 10000, `${facts.surface.covered} pixels of surface`);
});
