// The browser's own WebGL and WebGPU functions, kept before any other script runs (the grader's
// wrappers included): window.__glNative (its WebGPU classes' functions under `gpu`). The grader
// draws a page's geometry again in a context or with pipelines of its own (grader/browser/surface.js,
// surface-webgpu.js) with these, so that nothing it does is counted, recorded or seen as the page's
// (the instrumentation's draws, frames, shader sources and errors, culling state). Frozen, and not
// writable: a page cannot put its own functions in their place.
export function nativesScript() {
  if (window.__glNative) return;
  const functionsOf = (C) => {
    const fns = {};
    for (const name of Object.getOwnPropertyNames(C.prototype)) {
      const d = Object.getOwnPropertyDescriptor(C.prototype, name);
      if (d && typeof d.value === 'function') fns[name] = d.value;
    }
    return Object.freeze(fns);
  };
  const out = {};
  for (const C of [window.WebGLRenderingContext, window.WebGL2RenderingContext]) if (C) out[C.name] = functionsOf(C);
  if (window.OffscreenCanvas) out.offscreenGetContext = window.OffscreenCanvas.prototype.getContext;
  if (window.GPUDevice) {
    const gpu = {};
    for (const name of ['GPUDevice', 'GPUQueue', 'GPUCommandEncoder', 'GPURenderPassEncoder', 'GPUBuffer', 'GPUTexture', 'GPURenderPipeline', 'GPUShaderModule']) {
      if (window[name]) gpu[name] = functionsOf(window[name]);
    }
    out.gpu = Object.freeze(gpu);
  }
  const frozen = { value: Object.freeze(out), enumerable: false, writable: false, configurable: false };
  Object.defineProperty(window, '__glNative', frozen);
}

/** The init script as text. */
export const nativesInit = `(${nativesScript})();`;
