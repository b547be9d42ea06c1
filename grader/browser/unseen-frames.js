// A part of the grader's instrument script (grader/browser/instrument.js, injected as text): the
// draws of a WebGL frame nobody looks at, left undone. When the grader lets n frames run, it reads
// the canvas only after the last of them, so the draws of the frames before it are work without
// evidence (most of what SwiftShader does over a grading). They are skipped only where that cannot
// change what is read:
// - the frame is followed by another in the same run of the clock (clock.js says which);
// - the draw goes to the canvas, not to a framebuffer of the page's own;
// - the page has so far begun each frame by clearing the canvas whole (colour, and depth where the
//   present does not clear it; no scissor, every channel written) before its first draw to it.
// Everything else about the frame happens: the page's JavaScript, its uniforms and buffers, the
// draws counted as the page asked for them (instrument.js counts before it sends).
// What could still tell is watched, and makes the run `unsafe` (the grader then gathers the part
// again with every frame drawn, grader/node/run/run-part.js):
// - a draw to the canvas, a read of it (readPixels, copyTex*, blitFramebuffer) or getError after
//   skipped draws with no whole clear between;
// - a run of the clock that ends with skipped draws not cleared away (its last frame was skipped:
//   the page stopped asking for frames).
// Off unless the grader's page opener turns it on (window.__grade.unseen.on): the check page and
// Firefox draw every frame.

/** window.__grade.unseen: { on, skipped, unsafe, frame(at, unseen), endFrame(), endRun(), skip(gl) }. */
export function watchUnseenFrames() {
  const g = window.__grade;
  const state = new WeakMap(); // context → { clearedAt, drewAt, clearsFirst }
  const dirty = new Set(); // contexts with skipped draws not yet cleared away
  const stateOf = (gl) => {
    let s = state.get(gl);
    if (!s) state.set(gl, (s = { clearedAt: null, drewAt: null, clearsFirst: null }));
    return s;
  };
  const U = {
    on: false,
    skipped: 0,
    unsafe: null, // why skipping could have changed what the page shows, once it could
    at: null, // the animation frame running now (its time), or null between frames
    unseen: false, // the frame running now is followed by another in this run of the clock
    frame(at, unseen) { Object.assign(U, { at, unseen }); },
    endFrame() { Object.assign(U, { at: null, unseen: false }); },
    endRun() {
      if (dirty.size && !U.unsafe) U.unsafe = 'a run of frames ended with draws skipped and not cleared away';
    },
    /** Whether the draw on `gl` now is left undone (counted already). */
    skip(gl) {
      if (!U.on) return false;
      const toCanvas = !gl.getParameter(gl.FRAMEBUFFER_BINDING);
      if (!toCanvas) return false;
      const s = stateOf(gl);
      // the first draw to the canvas in a frame: did the frame clear it whole first?
      if (U.at !== null && s.drewAt !== U.at) {
        s.drewAt = U.at;
        const first = s.clearedAt === U.at;
        s.clearsFirst = first && s.clearsFirst !== false;
      }
      if (U.unseen && U.at !== null && s.clearsFirst && s.clearedAt === U.at) {
        U.skipped++;
        dirty.add(gl);
        return true;
      }
      seen(gl, 'a draw to the canvas');
      return false;
    },
  };
  // a draw to the canvas, or a read of it, over skipped draws: what skipping changed could show
  const seen = (gl, what) => {
    if (dirty.has(gl) && !U.unsafe) U.unsafe = `${what} after skipped draws with no whole clear between`;
  };
  Object.defineProperty(g, 'unseen', { value: U });
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    const { clear } = proto;
    proto.clear = function (mask) {
      const r = clear.call(this, mask);
      if (U.on && !this.isContextLost() && !this.getParameter(this.FRAMEBUFFER_BINDING)) {
        const whole = (mask & this.COLOR_BUFFER_BIT) &&
          ((mask & this.DEPTH_BUFFER_BIT && this.getParameter(this.DEPTH_WRITEMASK)) || this.__gradeClearsOnPresent) &&
          !this.isEnabled(this.SCISSOR_TEST) && this.getParameter(this.COLOR_WRITEMASK).every(Boolean);
        const s = stateOf(this);
        if (whole) {
          if (U.at !== null && s.drewAt !== U.at) s.clearedAt = U.at;
          dirty.delete(this);
        }
      }
      return r;
    };
    for (const name of ['readPixels', 'copyTexImage2D', 'copyTexSubImage2D', 'blitFramebuffer', 'getError']) {
      const f = proto[name];
      if (!f) continue;
      // (after the call: a draw the batch held is sent, and skipped, before it)
      proto[name] = function (...a) {
        const r = f.apply(this, a);
        seen(this, name);
        return r;
      };
    }
  }
}
