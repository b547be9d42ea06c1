// A part of the grader's instrument script (grader/browser/instrument.js, injected as text): the
// browser's present of a WebGL frame, done by the grader. A WebGL canvas keeps its drawing buffer
// (preserveDrawingBuffer) so that the last frame can be read at any time; where the page did not
// ask for that, its depth and stencil buffers are cleared after each task that drew, as the browser
// clears them when it shows the frame (a page that never clears its depth buffer draws each frame
// into a cleared one, not into the last frame's), and the page's state is left as it was.

/**
 * window.__grade.drew(gl): a draw on `gl` (watchWebGL's), which queues the present at the end of
 * the task. The clear values and write masks the present sets and puts back are kept here as the
 * page last set them (its calls wrapped): asking the context (getParameter) waits for the GPU to
 * finish every draw sent so far, four times a frame. What the browser keeps on its own side (the
 * framebuffer bound, the scissor test) is asked. A lost context forgets them: a restored one starts
 * from WebGL's defaults.
 */
export function watchPresent() {
  const g = window.__grade;
  const kept = new WeakMap(); // context → { depth, stencil, depthMask, front, back }
  const keptOf = (gl) => {
    let k = kept.get(gl);
    if (!k) kept.set(gl, (k = { depth: 1, stencil: 0, depthMask: true, front: 0xffffffff, back: 0xffffffff }));
    return k;
  };
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    // kept as the page's call left it: its argument, given again, converts as it did (a call that
    // throws keeps nothing; an unknown face changes nothing)
    const keeping = (f, set) => function (...a) {
      const r = f.apply(this, a);
      if (this.isContextLost()) kept.delete(this);
      else set(keptOf(this), ...a);
      return r;
    };
    const face = { [proto.FRONT]: ['front'], [proto.BACK]: ['back'], [proto.FRONT_AND_BACK]: ['front', 'back'] };
    proto.clearDepth = keeping(proto.clearDepth, (k, v) => { k.depth = Number(v); });
    proto.clearStencil = keeping(proto.clearStencil, (k, v) => { k.stencil = Number(v); });
    proto.depthMask = keeping(proto.depthMask, (k, v) => { k.depthMask = !!v; });
    proto.stencilMask = keeping(proto.stencilMask, (k, v) => { k.front = k.back = Number(v) >>> 0; });
    proto.stencilMaskSeparate = keeping(proto.stencilMaskSeparate, (k, f, v) => {
      for (const side of face[Number(f) >>> 0] || []) k[side] = Number(v) >>> 0;
    });
  }
  const presented = new WeakMap(); // context → a present is queued
  const present = (gl) => {
    presented.set(gl, false);
    if (gl.isContextLost()) return void kept.delete(gl);
    const { depth, stencil, depthMask, front, back } = keptOf(gl);
    const fb = gl.getParameter(gl.FRAMEBUFFER_BINDING), scissor = gl.isEnabled(gl.SCISSOR_TEST);
    if (fb) gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (scissor) gl.disable(gl.SCISSOR_TEST);
    gl.depthMask(true);
    gl.stencilMask(0xffffffff);
    gl.clearDepth(1);
    gl.clearStencil(0);
    gl.clear(gl.DEPTH_BUFFER_BIT | gl.STENCIL_BUFFER_BIT);
    gl.clearDepth(depth); gl.clearStencil(stencil);
    gl.depthMask(depthMask);
    gl.stencilMaskSeparate(gl.FRONT, front); gl.stencilMaskSeparate(gl.BACK, back);
    if (scissor) gl.enable(gl.SCISSOR_TEST);
    if (fb) gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  };
  Object.defineProperty(g, 'drew', {
    value: (gl) => {
      if (!gl.__gradeClearsOnPresent || presented.get(gl)) return;
      presented.set(gl, true);
      queueMicrotask(() => present(gl));
    },
  });
}
