// What a graded page did to the grader's hooks, as the last init script (after the clock): each
// function the grader put in place or reads through (its instrumentation's wrappers of WebGL, the
// canvas's read-back, the frozen clock, window.__grade's methods) is noted as it stands before the
// page's first script (WebGPU's too, where the browser has it), and window.__tamper.read() lists
// those the page has replaced since. The
// grader's own methods are made read-only, and navigator.webdriver reads false, as in a browser a
// student uses. A hand-in is untrusted code: the audit gives such a part `review`, naming the hook.
export function tamperScript() {
  if (window.__tamper) return;
  const watched = []; // [label, holder, name, value]
  const watch = (label, holder, name) => {
    if (!holder) return;
    const d = Object.getOwnPropertyDescriptor(holder, name);
    if (d) watched.push([label, holder, name, d.value || d.get]);
  };
  const protos = {
    HTMLCanvasElement: window.HTMLCanvasElement,
    CanvasRenderingContext2D: window.CanvasRenderingContext2D,
    Document: window.Document,
    WebGLRenderingContext: window.WebGLRenderingContext,
    WebGL2RenderingContext: window.WebGL2RenderingContext,
    EventTarget: window.EventTarget,
    GPUAdapter: window.GPUAdapter,
    GPUDevice: window.GPUDevice,
    GPUQueue: window.GPUQueue,
    GPUBuffer: window.GPUBuffer,
    GPURenderPassEncoder: window.GPURenderPassEncoder,
    GPUShaderModule: window.GPUShaderModule,
  };
  const names = {
    HTMLCanvasElement: ['getContext', 'toDataURL', 'toBlob'], CanvasRenderingContext2D: ['drawImage', 'getImageData'], Document: ['createElement', 'querySelectorAll'],
    WebGLRenderingContext: ['drawArrays', 'drawElements', 'bufferData', 'bufferSubData', 'vertexAttribPointer', 'enable', 'disable', 'cullFace', 'frontFace', 'useProgram', 'uniformMatrix4fv', 'getExtension', 'shaderSource', 'compileShader', 'linkProgram',
      'clearDepth', 'clearStencil', 'depthMask', 'stencilMask', 'stencilMaskSeparate'],
    EventTarget: ['addEventListener'],
    // WebGPU: what the instrumentation, the geometry's and the sent values' records and the frame capture wrap
    GPUAdapter: ['requestDevice'], GPUDevice: ['createBuffer', 'createShaderModule', 'createRenderPipeline', 'createRenderPipelineAsync', 'popErrorScope'],
    GPUQueue: ['submit', 'writeBuffer', 'onSubmittedWorkDone'], GPUBuffer: ['getMappedRange', 'unmap', 'mapAsync'],
    GPURenderPassEncoder: ['setPipeline', 'setVertexBuffer', 'setIndexBuffer', 'draw', 'drawIndexed'], GPUShaderModule: ['getCompilationInfo'],
  };
  names.WebGL2RenderingContext = [...names.WebGLRenderingContext, 'bindVertexArray'];
  for (const [cls, list] of Object.entries(names)) {
    for (const n of list) watch(`${cls}.prototype.${n}`, protos[cls] && protos[cls].prototype, n);
  }
  for (const n of ['Date', 'setTimeout', 'setInterval', 'requestAnimationFrame', 'fetch']) watch(n, window, n);
  watch('Date.now', window.Date, 'now');
  // the grader's own methods and the frozen clock's now(): read-only, and a page that assigns to one is noted
  const tried = new Set();
  const now = performance.now;
  const nowGuard = { get: () => now, set: () => { tried.add('performance.now'); }, configurable: true, enumerable: true };
  try { Object.defineProperty(performance, 'now', nowGuard); } catch { /* kept as it is */ }
  watch('performance.now', performance, 'now');
  const g = window.__grade;
  if (g) {
    for (const n of ['state', 'pixels', 'readBack', 'click', 'controls', 'setValue']) {
      const f = g[n];
      if (typeof f !== 'function') continue;
      const guard = { get: () => f, set: () => { tried.add(`window.__grade.${n}`); }, configurable: false, enumerable: true };
      try { Object.defineProperty(g, n, guard); } catch { /* (already fixed) */ }
    }
  }
  // a page that asks whether a driver runs it is told no, as a student's own browser would, and noted
  const asked = () => { tried.add('navigator.webdriver (it asked whether a driver runs it)'); return false; };
  try {
    Object.defineProperty(Navigator.prototype, 'webdriver', { configurable: true, enumerable: true, get: asked });
  } catch { /* kept as it is */ }

  const rec = {};
  /** The hooks the page has replaced (or tried to) since it started, by name. */
  rec.read = () => [...watched.filter(([, holder, name, value]) => {
    const d = Object.getOwnPropertyDescriptor(holder, name);
    return !d || (d.value || d.get) !== value;
  }).map(([label]) => label), ...(g && g.replacedByPage ? ['window.__grade'] : []), ...tried];
  Object.defineProperty(window, '__tamper', { value: rec });
}
