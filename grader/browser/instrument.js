// What the grader watches on a student's page, as an init script (runs before the page's own
// scripts, changes none of its files): which API the page asked for, shader and adapter
// failures, which events each control listens to, and a read-back of the canvas in either API
// (WebGL contexts get preserveDrawingBuffer so the last frame can be read at any time; WebGPU
// frames come from grader/browser/webgpu-capture.js, which must be added first). It is injected
// as named parts, in order (instrumentScript), which share what they record on window.__grade.

import { watchInstancedDraws } from './instanced-draws.js';
import { watchPresent } from './present.js';
import { watchUnseenFrames } from './unseen-frames.js';

/** window.__grade: what the parts below record, and state(), what the page interface reads of it. */
function gradeState() {
  const g = { api: null, apis: [], draws: 0, vertices: 0, pending: 0, shaderErrors: [], gpuErrors: [],
    adapter: undefined, webgpuMissing: false, wgsl: [], glsl: [],
    faces: { depthTest: false, culling: false, cullMode: null }, noCull: false, cullOn: false };
  // how each WebGL prototype sends a draw (watchWebGL's, used by instanced-draws.js too)
  Object.defineProperty(g, 'senders', { value: new Map() });
  // (read-only: a page that assigns to it is noted, grader/browser/tamper.js)
  Object.defineProperty(window, '__grade', { get: () => g, set: () => { g.replacedByPage = true; }, enumerable: false });

  /** What the page interface's state() gives the grading core (playwright-page.js and the check page's
   * frame driver both read it here, so they cannot drift apart). */
  g.state = () => ({ api: g.api, frames: window.__webgpuCapture ? window.__webgpuCapture.frames : 0, adapter: g.adapter,
    webgpuMissing: g.webgpuMissing, draws: g.draws, vertices: g.vertices, pending: g.pending,
    animation: window.__checkClock && window.__checkClock.frames ? window.__checkClock.frames() : null,
    shaderErrors: [...g.shaderErrors], gpuErrors: [...g.gpuErrors], faces: { ...g.faces } });
}

/** Which API the page asked for (getContext), WebGL canvases keeping their drawing buffer. */
function watchContexts() {
  const g = window.__grade;
  const apiOf = { webgl: 'webgl', 'experimental-webgl': 'webgl', webgl2: 'webgl2', webgpu: 'webgpu' };
  const realGetContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, attrs, ...rest) {
    const api = apiOf[type];
    const clearsOnPresent = api && api !== 'webgpu' && !(attrs && attrs.preserveDrawingBuffer);
    if (api && api !== 'webgpu') attrs = { ...(attrs || {}), preserveDrawingBuffer: true };
    const ctx = realGetContext.call(this, type, attrs, ...rest);
    if (api === 'webgpu' && !ctx) g.webgpuMissing = true; // a browser without WebGPU (Firefox ESR)
    if (ctx && clearsOnPresent && !('__gradeClearsOnPresent' in ctx)) Object.defineProperty(ctx, '__gradeClearsOnPresent', { value: true });
    if (api && ctx) {
      g.api = api;
      if (!g.apis.includes(api)) g.apis.push(api);
      this.setAttribute('data-grade-api', api);
    }
    return ctx;
  };
}

/** WebGL: shader sources and errors, the depth test and culling, draws counted, a present after each task that drew. */
function watchWebGL() {
  const g = window.__grade;
  // (a present after each task that drew: grader/browser/present.js)
  const drew = g.drew;
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    const { compileShader, linkProgram, shaderSource, drawArrays, drawElements } = proto;
    proto.shaderSource = function (shader, source) {
      g.glsl.push(String(source).slice(0, 20000));
      return shaderSource.call(this, shader, source);
    };
    proto.compileShader = function (shader) {
      compileShader.call(this, shader);
      if (!this.getShaderParameter(shader, this.COMPILE_STATUS) && !this.isContextLost()) {
        g.shaderErrors.push(`shader does not compile: ${(this.getShaderInfoLog(shader) || '').trim()}`);
      }
    };
    proto.linkProgram = function (program) {
      linkProgram.call(this, program);
      if (!this.getProgramParameter(program, this.LINK_STATUS) && !this.isContextLost()) {
        g.shaderErrors.push(`program does not link: ${(this.getProgramInfoLog(program) || '').trim()}`);
      }
    };
    // the slide's WP04P2: the depth test and back-face culling enabled (recorded, never changed)
    const { enable, disable, cullFace, frontFace } = proto;
    proto.enable = function (cap) {
      if (cap === this.DEPTH_TEST) g.faces.depthTest = true;
      if (cap === this.CULL_FACE) g.faces.culling = g.cullOn = true;
      return enable.call(this, cap);
    };
    proto.disable = function (cap) {
      if (cap === this.CULL_FACE) g.cullOn = false;
      return disable.call(this, cap);
    };
    // the grader's experiment (g.noCull): the same frames drawn with culling off, so that with the
    // depth test on the faces nearest the viewer show, whichever way the mesh is wound
    const bare = (gl, draw, a) => {
      if (g.unseen.skip(gl)) return undefined; // (a frame nobody looks at: unseen-frames.js)
      if (!(g.noCull && g.cullOn)) return draw.apply(gl, a);
      disable.call(gl, gl.CULL_FACE);
      try {
        return draw.apply(gl, a);
      } finally {
        enable.call(gl, gl.CULL_FACE);
      }
    };
    proto.cullFace = function (mode) {
      g.faces.cullMode = mode === this.FRONT ? 'front' : mode === this.BACK ? 'back' : 'front-and-back';
      return cullFace.call(this, mode);
    };
    // the slide's experiment, gl.frontFace(gl.CW) ("you should now see the back side"): recorded
    // only once the page sets it (the default is CCW), the last call winning
    proto.frontFace = function (mode) {
      if (mode === this.CW || mode === this.CCW) g.faces.frontFace = mode === this.CW ? 'cw' : 'ccw';
      return frontFace.call(this, mode);
    };
    // the page's own work, counted (draw calls and vertices): what a page costs, never read off a clock
    // (separate triangles drawn one after another go to the GPU as one draw: grader/browser/draw-batch.js)
    const batch = window.__drawBatch, send = (gl, a) => bare(gl, drawArrays, a);
    const counted = (gl, n) => { g.draws++; g.vertices += Math.max(0, n | 0); drew(gl); };
    const arrays = (gl, a) => (batch ? batch.arrays(gl, a, send) : send(gl, a));
    proto.drawArrays = function (...a) { counted(this, a[2]); return arrays(this, a); };
    proto.drawElements = function (...a) { counted(this, a[1]); return bare(this, drawElements, a); };
    // (instanced draws, watchInstancedDraws, counted and sent as these are)
    g.senders.set(proto, (gl, draw, a, n) => { counted(gl, n); return bare(gl, draw, a); });
  }
}

/** What the page waits for in real time (fetch, XHR, WebGPU), and WebGPU's shaders, pipelines and draws. */
function watchWaits() {
  const g = window.__grade;
  const add = EventTarget.prototype.addEventListener;
  // what the page waits for in real time (a fetch, an XHR, a WebGPU adapter or device): the grader
  // lets frames run only once none is pending, so that what a page shows after n frames does not
  // depend on how long the network or the GPU took
  const awaited = (promise) => {
    g.pending++;
    const done = () => { g.pending--; };
    promise.then(done, done);
    return promise;
  };
  if (window.fetch) {
    const realFetch = window.fetch;
    window.fetch = function (...a) { return awaited(realFetch.apply(this, a)); };
    // (a response's body is read in real time too)
    for (const k of ['text', 'json', 'arrayBuffer', 'blob']) {
      const read = Response.prototype[k];
      if (read) Response.prototype[k] = function (...a) { return awaited(read.apply(this, a)); };
    }
  }
  if (window.XMLHttpRequest) {
    const send = XMLHttpRequest.prototype.send;
    XMLHttpRequest.prototype.send = function (...a) {
      if (!this.__gradeAwaited) {
        Object.defineProperty(this, '__gradeAwaited', { value: true });
        // (a synchronous request is over when send returns: loadend has fired by then)
        g.pending++;
        add.call(this, 'loadend', () => { g.pending--; });
      }
      return send.apply(this, a);
    };
  }
  if (navigator.gpu && window.GPUAdapter) {
    const gpu = navigator.gpu, requestAdapter = gpu.requestAdapter.bind(gpu);
    gpu.requestAdapter = async (...a) => {
      const adapter = await awaited(requestAdapter(...a));
      g.adapter = adapter ? 'ok' : null;
      if (!adapter) g.gpuErrors.push('requestAdapter() gave no adapter');
      return adapter;
    };
    const requestDevice = GPUAdapter.prototype.requestDevice;
    GPUAdapter.prototype.requestDevice = async function (...a) {
      const device = await awaited(requestDevice.apply(this, a));
      device.addEventListener('uncapturederror', (e) => { if (g.gpuErrors.length < 20) g.gpuErrors.push(`WebGPU: ${e.error.message}`); });
      return device;
    };
    const createShaderModule = GPUDevice.prototype.createShaderModule;
    GPUDevice.prototype.createShaderModule = function (desc) {
      const module = createShaderModule.call(this, desc);
      g.wgsl.push(String(desc && desc.code).slice(0, 20000));
      module.getCompilationInfo().then((info) => {
        for (const m of info.messages) if (m.type === 'error') g.shaderErrors.push(`WGSL does not compile (line ${m.lineNum}): ${m.message}`);
      }, () => {});
      return module;
    };
    const D = GPUDevice.prototype, P = GPURenderPassEncoder.prototype;
    const createPipeline = D.createRenderPipeline, createAsync = D.createRenderPipelineAsync;
    const mapAsync = GPUBuffer.prototype.mapAsync, onSubmittedWorkDone = GPUQueue.prototype.onSubmittedWorkDone;
    // a shader's compilation messages and an error scope are answered in real time
    const M = GPUShaderModule.prototype, getCompilationInfo = M.getCompilationInfo, popErrorScope = D.popErrorScope;
    M.getCompilationInfo = function (...a) { return awaited(getCompilationInfo.apply(this, a)); };
    D.popErrorScope = function (...a) { return awaited(popErrorScope.apply(this, a)); };
    GPUBuffer.prototype.mapAsync = function (...a) { return awaited(mapAsync.apply(this, a)); };
    GPUQueue.prototype.onSubmittedWorkDone = function (...a) { return awaited(onSubmittedWorkDone.apply(this, a)); };
    const seePipeline = (desc) => {
      const ds = desc && desc.depthStencil, prim = (desc && desc.primitive) || {};
      if (ds && ds.depthCompare && ds.depthCompare !== 'always') g.faces.depthTest = true;
      if (prim.cullMode && prim.cullMode !== 'none') { g.faces.culling = true; g.faces.cullMode = prim.cullMode; }
      if (prim.frontFace === 'cw' || prim.frontFace === 'ccw') g.faces.frontFace = prim.frontFace;
    };
    D.createRenderPipeline = function (desc) { seePipeline(desc); return createPipeline.call(this, desc); };
    D.createRenderPipelineAsync = function (desc) { seePipeline(desc); return awaited(createAsync.call(this, desc)); };
    const draw = P.draw, drawIndexed = P.drawIndexed;
    const count = (n, instances) => Math.max(0, n | 0) * (instances === undefined ? 1 : Math.max(0, instances | 0));
    P.draw = function (...a) { g.draws++; g.vertices += count(a[0], a[1]); return draw.apply(this, a); };
    P.drawIndexed = function (...a) { g.draws++; g.vertices += count(a[0], a[1]); return drawIndexed.apply(this, a); };
  } else {
    g.adapter = null;
    // a browser without WebGPU (Firefox ESR): a page that asks for navigator.gpu gets undefined, as
    // it would, and the grader knows it asked (a WebGPU part is then not graded here, never failed)
    if (!('gpu' in navigator)) {
      Object.defineProperty(Navigator.prototype, 'gpu', {
        configurable: true, enumerable: false, get() { g.webgpuMissing = true; return undefined; },
      });
    }
  }
}

/** Which events each control listens to. */
function watchListeners() {
  const add = EventTarget.prototype.addEventListener;
  // which events each control listens to (addEventListener, or on<event> properties/attributes)
  EventTarget.prototype.addEventListener = function (type, ...rest) {
    if (this instanceof Element) {
      const set = this.__gradeEvents || (this.__gradeEvents = new Set());
      set.add(type);
      if ((type === 'input' || type === 'change') && typeof rest[0] === 'function') {
        (this.__gradeHandlers ||= []).push(String(rest[0]).slice(0, 200));
      }
    }
    return add.call(this, type, ...rest);
  };
}

/** The page interface's hands on the page's controls: click, controls, setValue. */
function controlsInterface() {
  const g = window.__grade;
  /**
   * A click as a user's, on control `index`: pointer and mouse down and up at its centre, then
   * click (which toggles a checkbox). { ok, why }: not when it is disabled, hidden or covered.
   */
  g.click = (index) => {
    const el = document.querySelector(`[data-grade-control="${index}"]`);
    if (!el) return { ok: false, why: 'it is no longer on the page' };
    if (el.disabled) return { ok: false, why: 'it is disabled' };
    el.scrollIntoView({ block: 'center', inline: 'center' });
    const r = el.getBoundingClientRect();
    if (!r.width || !r.height) return { ok: false, why: 'it is not visible' };
    const x = r.left + r.width / 2, y = r.top + r.height / 2;
    const hit = document.elementFromPoint(x, y);
    if (!hit || !(hit === el || el.contains(hit) || hit.control === el)) {
      return { ok: false, why: `another element (${hit ? hit.tagName.toLowerCase() : 'none'}) covers it` };
    }
    const opts = { bubbles: true, cancelable: true, composed: true, clientX: x, clientY: y, button: 0, view: window };
    el.dispatchEvent(new PointerEvent('pointerdown', { ...opts, buttons: 1, pointerType: 'mouse', isPrimary: true }));
    el.dispatchEvent(new MouseEvent('mousedown', { ...opts, buttons: 1 }));
    if (el.focus) el.focus();
    el.dispatchEvent(new PointerEvent('pointerup', { ...opts, pointerType: 'mouse', isPrimary: true }));
    el.dispatchEvent(new MouseEvent('mouseup', opts));
    el.click();
    return { ok: true };
  };

  /** The words right before a control (and after it, for a checkbox), up to a line break or another control. */
  const INLINE = /^(SUB|SUP|B|I|EM|STRONG|SPAN|LABEL|SMALL|CODE|FONT|OUTPUT)$/;
  const CONTROL = 'button, input, select, textarea';
  const nearbyText = (el, after) => {
    const words = (dir) => {
      let out = '';
      for (let n = el[dir]; n && out.length < 60; n = n[dir]) {
        if (n.nodeType === 3) out = dir === 'previousSibling' ? n.textContent + out : out + n.textContent;
        else if (n.nodeType === 1 && INLINE.test(n.tagName) && !n.matches(CONTROL) && !n.querySelector(CONTROL)) {
          out = dir === 'previousSibling' ? n.textContent + out : out + n.textContent;
        } else break;
      }
      return out.trim();
    };
    let text = words('previousSibling');
    if (after) text += ' ' + words('nextSibling');
    const cell = el.parentElement;
    const aloneInCell = cell && /^T[DH]$/.test(cell.tagName) && cell.querySelectorAll(CONTROL).length === 1;
    if (!text.trim() && aloneInCell && cell.previousElementSibling) {
      text = cell.previousElementSibling.textContent;
    }
    return text.trim();
  };

  /** The page's controls with what a teacher would read on them (a colour picker too: one parameter, set as a whole). */
  g.controls = () => {
    const els = [...document.querySelectorAll('button, input, select, [role=button], a[onclick]')];
    return els.map((el, index) => {
      el.setAttribute('data-grade-control', String(index));
      const labels = el.labels ? [...el.labels].map((l) => l.textContent) : [];
      const before = el.previousElementSibling;
      const prev = before && /^(LABEL|SPAN|B|P)$/.test(before.tagName) ? before.textContent : '';
      const parentText = el.parentElement && el.parentElement.tagName === 'LABEL' ? el.parentElement.textContent : '';
      const type = el.tagName === 'INPUT' ? (el.type || 'text') : el.tagName.toLowerCase();
      // an input or select without a label is named by the words beside it: "Diffuse k<sub>d</sub>: <input>",
      // "<input type=checkbox> Orbit", or the table cell before its own
      const nearby = el.tagName === 'INPUT' || el.tagName === 'SELECT' ? nearbyText(el, type === 'checkbox' || type === 'radio') : '';
      const own = [el.textContent, el.value && el.tagName !== 'INPUT' ? '' : '', el.getAttribute('aria-label'), el.title];
      const text = [...own, ...labels, parentText, prev, nearby]
        .filter(Boolean).join(' ').replace(/\s+/g, ' ').trim();
      const events = [...(el.__gradeEvents || [])];
      for (const ev of ['click', 'input', 'change']) if (el['on' + ev] && !events.includes(ev)) events.push(ev);
      // a slider's handlers, as text: changeKs(0, v), changeKs(1, v), changeKs(2, v) set one parameter's channels
      const handlers = () => [el.oninput, el.onchange, ...(el.__gradeHandlers || [])].filter(Boolean);
      const handler = /^(range|number|color)$/.test(type) ? handlers().map((f) => String(f).slice(0, 200)).join(' ') : '';
      return { index, type, id: el.id || '', name: el.name || '',
        text: type === 'submit' || type === 'button' ? (el.value + ' ' + text).trim() : text,
        value: el.value, min: el.min, max: el.max, step: el.step, checked: el.checked, disabled: el.disabled, events,
        visible: el.getClientRects().length > 0,
        options: el.tagName === 'SELECT' ? [...el.options].map((o) => o.value) : undefined, ...(handler ? { handler } : {}) };
    }).filter((c) => c.visible && !['hidden', 'text', 'number', 'file'].includes(c.type) || c.type === 'number');
  };

  /** Sets a range/number input and sends only the events asked for (default: input, then change). */
  g.setValue = (index, value, events = ['input', 'change']) => {
    const el = document.querySelector(`[data-grade-control="${index}"]`);
    if (!el) return false;
    el.value = String(value);
    for (const ev of events) el.dispatchEvent(new Event(ev, { bubbles: true }));
    return true;
  };
}

/** The parts, in the order they are installed (window.__grade first; the listeners' wrapper after the waits' own use of addEventListener). */
export const INSTRUMENT_PARTS = [gradeState, watchContexts, watchPresent, watchUnseenFrames, watchWebGL,
  watchInstancedDraws, watchWaits, watchListeners, controlsInterface];

/** The init script, as source: each part called in order (for addInitScript, evaluateOnNewDocument or a frame's script). */
export const instrumentScript = INSTRUMENT_PARTS.map((part) => `(${part})();`).join('\n');
