// A part of the grader's instrument script (grader/browser/instrument.js, injected as text): a
// page that draws its sphere with drawArraysInstanced or drawElementsInstanced (or the
// ANGLE_instanced_arrays extension's) has its draws counted and sent as a plain draw is.

/**
 * Instanced draws (WebGL 2's; WebGL 1's from ANGLE_instanced_arrays) counted, every instance's
 * vertices, and sent as watchWebGL sends any draw (window.__grade.senders, a prototype's: the
 * grader's culling experiment applies to them too).
 */
export function watchInstancedDraws() {
  const g = window.__grade, sent = new WeakSet();
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    const sender = g.senders.get(proto);
    const send = (gl, draw, a, n, k) => sender(gl, draw, a, Math.max(0, a[n] | 0) * Math.max(0, a[k] | 0));
    const { drawArraysInstanced: arrays, drawElementsInstanced: elements, getExtension } = proto;
    if (arrays) proto.drawArraysInstanced = function (...a) { return send(this, arrays, a, 2, 3); };
    if (elements) proto.drawElementsInstanced = function (...a) { return send(this, elements, a, 1, 4); };
    proto.getExtension = function (...a) {
      const ext = getExtension.apply(this, a), gl = this;
      if (!ext || typeof ext.drawArraysInstancedANGLE !== 'function' || sent.has(ext)) return ext;
      sent.add(ext);
      // (the extension's own method, called on it: the sender calls what it is given on the context)
      const on = (f) => function (...b) { return f.apply(ext, b); };
      const [arraysA, elementsA] = [on(ext.drawArraysInstancedANGLE), on(ext.drawElementsInstancedANGLE)];
      ext.drawArraysInstancedANGLE = (...b) => send(gl, arraysA, b, 2, 3);
      ext.drawElementsInstancedANGLE = (...b) => send(gl, elementsA, b, 1, 4);
      return ext;
    };
  }
}
