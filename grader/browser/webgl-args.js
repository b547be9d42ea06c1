// A WebGL call's arguments as WebGL takes them. WebGL's functions are declared in WebIDL, and the
// browser converts every argument to its declared type before it acts: an index or an enum
// (GLuint, GLenum, GLbitfield: unsigned long) is ToNumber'd, undefined and NaN and ±∞ become 0, a
// fraction is truncated and the rest taken modulo 2^32 (so `gl.vPosition`, a property no one set,
// is attribute 0, and -1 is 4294967295); GLint and GLsizei (long) likewise modulo 2^32 and signed;
// GLintptr (long long) truncated; GLboolean is ToBoolean; GLfloat is a 32-bit float. The grader's
// recorder (grader/browser/geometry.js's `wrap`, which sent.js shares) hears each call after it ran
// and stores what it reads of it through takenArgs, so its record is of the call WebGL made, not of
// the values the page wrote. WebGL 1, WebGL 2 and the extensions' methods (ANGLE_instanced_arrays,
// OES_vertex_array_object) alike, by name. Self-contained: put into graded pages as text
// (geometry.js's init script) and called by the unit tests in Node.

/**
 * (name, args) → args as WebGL took them: the arguments of the calls in SIGNATURES converted by
 * their declared types (only those the page passed: an optional one left out stays out), any other
 * call's args unchanged (the same array).
 */
export function webglArgs() {
  // (ToNumber throws only for a Symbol or a BigInt, and then the call itself threw before the record heard it)
  const number = (v) => {
    try { return Number(v); } catch { return NaN; }
  };
  const TWO_64 = 2 ** 64, TWO_63 = 2 ** 63;
  const types = {
    u: (v) => number(v) >>> 0, // unsigned long: ToUint32 is WebIDL's conversion exactly
    i: (v) => number(v) | 0, // long: ToInt32
    p: (v) => { // long long: truncated, modulo 2^64, signed
      const x = Math.trunc(number(v));
      if (!Number.isFinite(x)) return 0;
      const m = x - Math.floor(x / TWO_64) * TWO_64;
      return (m >= TWO_63 ? m - TWO_64 : m) + 0; // (+ 0: never −0)
    },
    b: (v) => !!v, // boolean
    f: (v) => Math.fround(number(v)), // unrestricted float
    _: (v) => v, // an object, a union or a string: as passed
  };
  // each call's arguments' types, in order (u GLuint/GLenum/GLbitfield, i GLint/GLsizei, p GLintptr,
  // b GLboolean, f GLfloat, _ as passed), from the WebGL 1 and 2 and the extensions' IDL
  const draws = { drawArrays: 'uii', drawElements: 'uiup', drawArraysInstanced: 'uiii', drawElementsInstanced: 'uiupi' };
  const SIGNATURES = {
    bindBuffer: 'u_',
    bufferData: 'u_uuu', // (target, size or data, usage[, srcOffset, length])
    bufferSubData: 'up_uu', // (target, offset, data[, srcOffset, length])
    vertexAttribPointer: 'uiubip',
    enableVertexAttribArray: 'u',
    disableVertexAttribArray: 'u',
    vertexAttribDivisor: 'uu',
    vertexAttribDivisorANGLE: 'uu',
    clear: 'u',
    ...draws,
    drawArraysInstancedANGLE: draws.drawArraysInstanced,
    drawElementsInstancedANGLE: draws.drawElementsInstanced,
    vertexAttrib1f: 'uf', vertexAttrib2f: 'uff', vertexAttrib3f: 'ufff', vertexAttrib4f: 'uffff',
    vertexAttrib1fv: 'u_', vertexAttrib2fv: 'u_', vertexAttrib3fv: 'u_', vertexAttrib4fv: 'u_',
  };
  return (name, args) => {
    const sig = Object.prototype.hasOwnProperty.call(SIGNATURES, name) ? SIGNATURES[name] : null;
    return sig ? Array.prototype.map.call(args, (v, k) => (types[sig[k]] || types._)(v)) : args;
  };
}

/** The converter's maker as text, for a page's script. */
export const webglArgsScript = `${webglArgs}`;
