// The browser's own WebGL functions, kept before any other script runs (the grader's wrappers
// included): window.__glNative. The grader draws a page's geometry again in a context of its own
// (grader/browser/surface.js) with these, so that nothing it does is counted, recorded or seen as
// the page's (the instrumentation's draws, shader sources and errors, culling state). Frozen, and
// not writable: a page cannot put its own functions in their place.
export function nativesScript() {
  if (window.__glNative) return;
  const out = {};
  for (const C of [window.WebGLRenderingContext, window.WebGL2RenderingContext]) {
    if (!C) continue;
    const fns = {};
    for (const name of Object.getOwnPropertyNames(C.prototype)) {
      const d = Object.getOwnPropertyDescriptor(C.prototype, name);
      if (d && typeof d.value === 'function') fns[name] = d.value;
    }
    out[C.name] = Object.freeze(fns);
  }
  if (window.OffscreenCanvas) out.offscreenGetContext = window.OffscreenCanvas.prototype.getContext;
  Object.defineProperty(window, '__glNative', { value: Object.freeze(out), enumerable: false, writable: false, configurable: false });
}

/** The init script as text. */
export const nativesInit = `(${nativesScript})();`;
