// A run of draws that is one draw: many hand-ins draw their sphere a triangle at a time, as the
// textbook's examples do (`for (i = 0; i < n; i += 3) gl.drawArrays(gl.TRIANGLES, i, 3)`), and a
// level-6 sphere then costs 16,384 draw calls a frame, each one a trip through the browser's GPU
// process: on a machine without a GPU, most of what grading such a page costs. Draws of separate
// triangles (TRIANGLES), each starting where the last ended, with no other WebGL call between them,
// draw the same triangles in the same order as one draw over them all, so they are sent as one:
// the same pixels, bit for bit. The page's own work (the draw calls and vertices the grader
// counts, grader/browser/instrument.js) is counted as the page asked for it, before this.
//
// A held draw is sent before any other call on a WebGL context or one of its extensions, before
// anything reads a canvas (toDataURL, toBlob, drawImage, createImageBitmap, ...) or sizes one, and
// at the end of the task at the latest (a microtask). A merged draw that WebGL refuses (a triangle past the end
// of a buffer: WebGL refuses the whole draw) is sent again draw by draw, as the page asked, so
// the triangles before it still show; the errors the check reads are given back to the page's
// own getError first.
//
// An init script (drawBatchScript, a string), added before instrumentScript, which sends its draws
// through window.__drawBatch.arrays(gl, args, send): `send(gl, args)` draws at once.

/** The init script's body (its parts are passed in as arguments: the script is their text). */
function drawBatch(heldDraws, flushFirst) {
  if (window.__drawBatch) return;
  const B = heldDraws();
  flushFirst(B);
  const { TRIANGLES } = B;
  Object.defineProperty(window, '__drawBatch', {
    enumerable: false,
    value: {
      /** gl.drawArrays(...a) as `send(gl, a)` draws it: held while it continues a run of separate triangles. */
      arrays(gl, a, send) {
        const [mode, first, count] = a;
        if (!(
          a.length === 3 &&
          mode === TRIANGLES &&
          Number.isInteger(first) &&
          first >= 0 &&
          Number.isInteger(count) &&
          count > 0 &&
          count % 3 === 0 &&
          first + count <= 2 ** 31 - 1
        )) {
          if (B.held) {
            B.flush();
          }
          return send(gl, a);
        }
        const h = B.held;
        if (h && h.gl === gl && h.send === send && first === h.first + h.count) {
          h.counts.push(count);
          h.count += count;
          return undefined;
        }
        if (h) B.flush();
        B.held = { gl, send, first, count, counts: [count] };
        queueMicrotask(B.flush);
        return undefined;
      },
    },
  });
}

/**
 * The held run of draws ({ gl, send, first, count, counts: each draw's count } or null) and
 * flush(): it sent as one draw, or draw by draw where WebGL refuses the one; the errors the check
 * took are given back to the page's own getError first (B.errors, B.getError: the real one).
 */
function heldDraws() {
  const TRIANGLES = 4, NO_ERROR = 0;
  const errors = new WeakMap(); // context → the errors the check took, given back to the page first
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  const realGetError = new Map(protos.map((p) => [p, p.getError]));
  const getError = (gl) => realGetError.get(Object.getPrototypeOf(gl)).call(gl);
  const B = { TRIANGLES, held: null, errors, protos, getError };
  B.flush = function flush() {
    const h = B.held;
    if (!h) return;
    B.held = null;
    const { gl, send } = h;
    try {
      if (h.counts.length === 1) return void send(gl, [TRIANGLES, h.first, h.count]);
      const taken = errors.get(gl) || [];
      for (let e = getError(gl), k = 0; e !== NO_ERROR && k < 8; e = getError(gl), k++) taken.push(e);
      if (taken.length) errors.set(gl, taken);
      send(gl, [TRIANGLES, h.first, h.count]);
      if (getError(gl) === NO_ERROR) return;
      let first = h.first;
      for (const count of h.counts) {
        send(gl, [TRIANGLES, first, count]);
        first += count;
      }
    } catch { /* (a context gone meanwhile: the draws would have thrown nothing either) */ }
  };
  return B;
}

/** Every call on a WebGL context or its extensions, every read of a canvas and every resize of one sends the held draw first. */
function flushFirst(B) {
  const flushing = (f) => function (...a) {
    if (B.held) B.flush();
    return f.apply(this, a);
  };
  const wrapAll = (target, proto) => {
    for (const k of Object.getOwnPropertyNames(proto)) {
      const d = Object.getOwnPropertyDescriptor(proto, k);
      if (k === 'constructor' || typeof d.value !== 'function') continue;
      Object.defineProperty(target, k, { ...d, value: flushing(d.value) });
    }
  };
  const wrappedExtensions = new WeakSet();
  for (const proto of B.protos) {
    const { getExtension } = proto;
    wrapAll(proto, proto);
    proto.getError = function () {
      if (B.held) B.flush();
      const taken = B.errors.get(this);
      return taken && taken.length ? taken.shift() : B.getError(this);
    };
    proto.getExtension = function (...a) {
      if (B.held) B.flush();
      const ext = getExtension.apply(this, a);
      if (ext && typeof ext === 'object' && !wrappedExtensions.has(ext)) {
        wrappedExtensions.add(ext);
        wrapAll(ext, Object.getPrototypeOf(ext));
      }
      return ext;
    };
  }
  // whatever reads a canvas's pixels sees the held draw
  const readers = [[window.HTMLCanvasElement, ['toDataURL', 'toBlob', 'captureStream']], [window.CanvasRenderingContext2D, ['drawImage', 'createPattern']],
    [window.GPUQueue, ['copyExternalImageToTexture']]];
  for (const [c, names] of readers) {
    for (const k of names) if (c && typeof c.prototype[k] === 'function') c.prototype[k] = flushing(c.prototype[k]);
  }
  if (window.createImageBitmap) window.createImageBitmap = flushing(window.createImageBitmap);
  // ... and a canvas given a size anew (its drawing buffer cleared) gets the draws made before
  for (const k of ['width', 'height']) {
    const d = Object.getOwnPropertyDescriptor(HTMLCanvasElement.prototype, k);
    Object.defineProperty(HTMLCanvasElement.prototype, k, { ...d, set: flushing(d.set) });
  }
}

/** The init script (a string, for addInitScript / evaluateOnNewDocument, or a frame's script). */
export const drawBatchScript = `(${drawBatch})(${heldDraws}, ${flushFirst});`;
