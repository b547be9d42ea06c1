// What a graded page sends to WebGL as geometry, as an init script added after instrument.js (so
// its wrappers see the page's own calls): the bytes of each buffer (bufferData, bufferSubData),
// the attribute layout (vertexAttribPointer, vertex array objects), the program, the culling state
// (as instrument.js keeps it) and each draw's range, grouped into frames (a frame starts at a clear of the colour buffer, or
// at a task's first draw on a page that never clears; in WebGPU, a queue's submit ends it:
// grader/browser/geometry-webgpu.js). Nothing is changed; nothing is analysed
// until the grader asks: window.__geometry.read() sums up the last frame's triangles (analyseMesh,
// grader/browser/mesh.js, a pure function also run by the unit tests).
// The same script starts grader/browser/sent.js's record (the uniforms), which shares its helpers.
// Every WebGL call is recorded as WebGL took it (grader/browser/webgl-args.js: WebIDL's conversions,
// so `gl.vPosition`, undefined, as an index is attribute 0, as it is to WebGL).
import { meshAnalysisScript } from './mesh.js';
import { webglArgsScript } from './webgl-args.js';
import { webgpuRecorderScript } from './geometry-webgpu.js';
import { sentScript } from './sent.js';
import { surfaceReaderScript, picturesScript } from './surface.js';
import { webgpuSurfaceReaderScript } from './surface-webgpu.js';

/** The init script as text: the recorders of what a page sends (its geometry, WebGL and WebGPU, and its uniforms) with the analysis in it. */
const recorders = [meshAnalysisScript, webgpuRecorderScript, sentScript, geometryStore, frameRecorder, recordWebGL,
  extensionsOf, geometryReader, programInfoOf, surfaceReaderScript, webgpuSurfaceReaderScript(picturesScript),
  webglArgsScript];
export const recordersInit = `(${geometryScript})(${recorders.join(', ')});`;

/** The init script's body (its parts are passed in as arguments: the script is their text). */
function geometryScript(analyseMesh, recordWebGPU, recordSent, geometryStore, frameRecorder, recordWebGL,
  extensionsOf, geometryReader, programInfoOf, surfaceReader, webgpuSurfaceReader, webglArgs) {
  if (window.__geometry || !window.WebGLRenderingContext) return;
  const G = geometryStore(webglArgs());
  Object.defineProperty(window, '__geometry', { value: G.rec, enumerable: false });
  Object.assign(G, frameRecorder(G, window.__grade)); // (instrument.js: the culling state the page set)
  recordWebGL(G, extensionsOf);
  const { frameOf, closeFrame, wrap, bytesIn, MAX_DRAWS, FLOAT, TRIANGLES } = G;
  const infoOf = programInfoOf(G, analyseMesh);
  const read = geometryReader(G, analyseMesh, infoOf);
  recordWebGPU({
    frameOf,
    closeFrame,
    wrap,
    bytesIn,
    vertexInputs: analyseMesh.vertexInputs,
    MAX_DRAWS,
    FLOAT,
    TRIANGLES,
  });
  recordSent({ wrap, bytesIn });
  G.rec.read = read;
  // the surface per pixel (grader/browser/surface.js; a frame drawn with WebGPU: surface-webgpu.js, a promise)
  const webgl = surfaceReader(G, infoOf), webgpu = webgpuSurfaceReader(G);
  G.rec.surface = (opts) => webgpu(opts) || webgl(opts);
}

/**
 * What the record keeps: the bytes each buffer holds, each context's and vertex array's state, each
 * program's attributes, the frames (rec), and the helpers that read an upload and wrap a method
 * (`taken(name, args)`: a WebGL call's arguments as WebGL took them, webgl-args.js).
 */
function geometryStore(taken) {
  const TRIANGLES = 4, FLOAT = 0x1406, COLOR_BUFFER_BIT = 0x4000;
  const MAX_DRAWS = 512, HISTORY = 32;
  const bytesOf = new WeakMap(); // WebGLBuffer → Uint8Array: what the page uploaded last
  const ctxState = new WeakMap(); // context → { array, vao, defaultVao, program }
  const vaoState = new WeakMap(); // vertex array object → { attribs, elements, snap }
  const programInfo = new WeakMap(); // program → { position, attributes } (from its vertex shader)
  const rec = { cur: null, last: null, history: [], clears: 0, task: false };
  Object.defineProperty(window, '__geometry', { value: rec, enumerable: false });

  const newVao = () => ({ attribs: [], elements: null, snap: null });
  const stateOf = (gl) => {
    let st = ctxState.get(gl);
    if (!st) {
      const vao = newVao();
      ctxState.set(gl, st = { array: null, vao, defaultVao: vao, program: null });
    }
    return st;
  };
  /**
   * The bytes an upload names, as a view (no copy): a typed array's `offset` and `length` count its
   * elements, an ArrayBuffer's count bytes (bufferData's srcOffset and length, writeBuffer's dataOffset
   * and size); null where `src` is no data.
   */
  const bytesIn = (src, offset, length) => {
    if (!src || !(src instanceof ArrayBuffer || ArrayBuffer.isView(src))) return null;
    const per = ArrayBuffer.isView(src) ? src.BYTES_PER_ELEMENT || 1 : 1;
    const base = ArrayBuffer.isView(src) ? src.byteOffset : 0, whole = ArrayBuffer.isView(src) ? src.buffer : src;
    const start = base + (offset ? offset * per : 0);
    const len = length ? length * per : src.byteLength - (offset ? offset * per : 0);
    return new Uint8Array(whole, start, Math.max(0, len));
  };
  // a buffer's own copy of an upload (bufferData(target, size) makes it zeros)
  const copy = (src, offset, length) => {
    if (typeof src === 'number') return src > 0 && src < 2 ** 28 ? new Uint8Array(src) : null;
    const view = bytesIn(src, offset, length);
    return view && view.slice();
  };
  /**
   * Wraps proto[name] so that `after(this, args, result)` hears each call after it ran, its
   * arguments as WebGL took them (its errors never reach the page). Every record hears its calls here.
   */
  const wrap = (proto, name, after) => {
    const real = proto && proto[name];
    if (typeof real !== 'function') return;
    proto[name] = function (...a) {
      const out = real.apply(this, a);
      try { after(this, taken(name, a), out); } catch { /* the record never breaks the page */ }
      return out;
    };
  };
  return {
    TRIANGLES,
    FLOAT,
    COLOR_BUFFER_BIT,
    MAX_DRAWS,
    HISTORY,
    bytesOf,
    ctxState,
    vaoState,
    programInfo,
    rec,
    newVao,
    stateOf,
    bytesIn,
    copy,
    wrap,
  };
}

/** The frames: a draw recorded into the current one (separate triangles one after another: one range), a frame closed, a vertex array bound. */
function frameRecorder({ rec, HISTORY, MAX_DRAWS, TRIANGLES, stateOf, newVao, vaoState }, grade) {
  const closeFrame = () => {
    if (!rec.cur) return;
    rec.history.push({ vertices: rec.cur.vertices, draws: rec.cur.calls });
    if (rec.history.length > HISTORY) rec.history.shift();
    rec.last = rec.cur;
    rec.cur = null;
  };
  /** The frame a draw of `count` vertices goes into (the current one, or a new one). */
  const frameOf = (count) => {
    if (!rec.task) {
      rec.task = true;
      queueMicrotask(() => { rec.task = false; if (!rec.clears) closeFrame(); });
    }
    const f = rec.cur || (rec.cur = { draws: [], vertices: 0, calls: 0, over: 0 });
    f.vertices += count;
    f.calls++;
    return f;
  };
  const draw = (gl, d) => {
    const f = frameOf(d.count);
    const st = stateOf(gl), vao = st.vao;
    if (!vao.snap) vao.snap = vao.attribs.map((a) => a && { ...a });
    const faces = grade && grade.faces;
    const cullMode = grade && grade.cullOn ? (faces.cullMode === 'front-and-back' ? 'both' : faces.cullMode || 'back') : null;
    const cull = cullMode ? `${cullMode}/${faces.frontFace || 'ccw'}` : 'off';
    const prev = f.draws[f.draws.length - 1];
    if (
      prev &&
      !d.indexed &&
      !prev.indexed &&
      d.instances === undefined &&
      prev.instances === undefined &&
      d.mode === TRIANGLES &&
      prev.mode === TRIANGLES &&
      prev.gl === gl &&
      prev.program === st.program &&
      prev.attribs === vao.snap &&
      prev.cull === cull &&
      prev.first + prev.count === d.first
    ) {
      prev.count += d.count; // separate triangles drawn one after another: one range
      return;
    }
    if (f.draws.length >= MAX_DRAWS) { f.over++; return; }
    f.draws.push({ ...d, gl, program: st.program, attribs: vao.snap, elements: d.indexed ? vao.elements : null, cull });
  };
  const changed = (vao) => { vao.snap = null; };

  const bindVao = (gl, vao) => {
    const st = stateOf(gl);
    if (!vao) st.vao = st.defaultVao;
    else {
      if (!vaoState.has(vao)) vaoState.set(vao, newVao());
      st.vao = vaoState.get(vao);
    }
  };
  return { closeFrame, frameOf, draw, changed, bindVao };
}

/** The WebGL calls recorded: buffers and their bytes, the attribute layout (with divisors), vertex arrays, the program, clears and draws. */
function recordWebGL(
  { wrap, stateOf, bytesOf, copy, changed, bindVao, closeFrame, draw, rec, COLOR_BUFFER_BIT },
  extensionsOf,
) {
  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    wrap(proto, 'bindBuffer', (gl, [target, buffer]) => {
      const st = stateOf(gl);
      if (target === gl.ARRAY_BUFFER) st.array = buffer;
      else if (target === gl.ELEMENT_ARRAY_BUFFER) { st.vao.elements = buffer; }
    });
    const bound = (gl, target) => {
      const st = stateOf(gl);
      return target === gl.ARRAY_BUFFER ? st.array : target === gl.ELEMENT_ARRAY_BUFFER ? st.vao.elements : null;
    };
    wrap(proto, 'bufferData', (gl, [target, src, , offset, length]) => {
      const buffer = bound(gl, target);
      if (!buffer) return;
      const bytes = copy(src, offset, length);
      if (bytes) bytesOf.set(buffer, bytes);
      else bytesOf.delete(buffer);
    });
    wrap(proto, 'bufferSubData', (gl, [target, at, src, offset, length]) => {
      const buffer = bound(gl, target), bytes = buffer && bytesOf.get(buffer);
      const part = bytes && copy(src, offset, length);
      if (part && at >= 0 && at + part.length <= bytes.length) bytes.set(part, at);
    });
    wrap(proto, 'vertexAttribPointer', (gl, [index, size, type, normalized, stride, offset]) => {
      const st = stateOf(gl), a = st.vao.attribs[index] || {};
      st.vao.attribs[index] = { ...a, buffer: st.array, size, type, normalized, stride, offset };
      changed(st.vao);
    });
    wrap(proto, 'enableVertexAttribArray', (gl, [index]) => {
      const st = stateOf(gl);
      st.vao.attribs[index] = { ...(st.vao.attribs[index] || {}), enabled: true };
      changed(st.vao);
    });
    wrap(proto, 'disableVertexAttribArray', (gl, [index]) => {
      const st = stateOf(gl);
      if (st.vao.attribs[index]) {
        st.vao.attribs[index] = { ...st.vao.attribs[index], enabled: false };
        changed(st.vao);
      }
    });
    // (an attribute read once an instance: its divisor, which the grader's redraw sets again)
    const divisor = (gl, [index, n]) => {
      const st = stateOf(gl);
      st.vao.attribs[index] = { ...(st.vao.attribs[index] || {}), divisor: n };
      changed(st.vao);
    };
    wrap(proto, 'vertexAttribDivisor', divisor);
    wrap(proto, 'bindVertexArray', (gl, [vao]) => bindVao(gl, vao));
    wrap(proto, 'useProgram', (gl, [program]) => { stateOf(gl).program = program; });
    wrap(proto, 'clear', (gl, [mask]) => {
      if (!(mask & COLOR_BUFFER_BIT) || gl.getParameter(gl.FRAMEBUFFER_BINDING)) return;
      rec.clears++;
      closeFrame();
    });
    // (an instanced draw: its instance count kept, which the grader's redraw draws again)
    const instanced = (n) => (n === undefined ? {} : { instances: Math.max(0, n) });
    const arrays = (gl, [mode, first, count], instances) =>
      draw(gl, { mode, first, count: Math.max(0, count), indexed: false, ...instanced(instances) });
    const elements = (gl, [mode, count, type, offset], instances) => draw(gl,
      { mode, count: Math.max(0, count), type, offset, indexed: true, ...instanced(instances) });
    wrap(proto, 'drawArrays', (gl, a) => arrays(gl, a));
    wrap(proto, 'drawElements', (gl, a) => elements(gl, a));
    const arraysInstanced = (gl, a) => arrays(gl, a, a[3]), elementsInstanced = (gl, a) => elements(gl, a, a[4]);
    wrap(proto, 'drawArraysInstanced', arraysInstanced);
    wrap(proto, 'drawElementsInstanced', elementsInstanced);
    extensionsOf(proto, { wrap, bindVao, divisor, arraysInstanced, elementsInstanced });
  }

}

/** WebGL 1's vertex array objects and instancing, which come from extensions: their calls recorded as WebGL 2's. */
function extensionsOf(proto, { wrap, bindVao, divisor, arraysInstanced, elementsInstanced }) {
  const getExtension = proto.getExtension;
  proto.getExtension = function (name) {
    const ext = getExtension.call(this, name), gl = this;
    const methods = /instanced_arrays/i.test(String(name))
      ? { vertexAttribDivisorANGLE: divisor, drawArraysInstancedANGLE: arraysInstanced,
        drawElementsInstancedANGLE: elementsInstanced }
      : /vertex_array_object/i.test(String(name)) ? { bindVertexArrayOES: (g, [vao]) => bindVao(g, vao) } : {};
    if (!ext || ext.__geometryWrapped || !Object.keys(methods).length) return ext;
    Object.defineProperty(ext, '__geometryWrapped', { value: true });
    for (const [method, after] of Object.entries(methods)) wrap(ext, method, (_, a) => after(gl, a));
    return ext;
  };
}

/** infoOf(gl, program): the attributes of a program's vertex shader, and which one gl_Position is computed from (kept a program). */
function programInfoOf({ programInfo }, analyseMesh) {
  return (gl, program) => {
    if (!program) return null;
    let info = programInfo.get(program);
    if (info) return info;
    const shaders = gl.getAttachedShaders(program) || [];
    const vs = shaders.find((s) => gl.getShaderParameter(s, gl.SHADER_TYPE) === gl.VERTEX_SHADER);
    info = analyseMesh.vertexShader(vs ? gl.getShaderSource(vs) || '' : '');
    for (const a of info.attributes) a.location = gl.getAttribLocation(program, a.name);
    programInfo.set(program, info);
    return info;
  };
}

/** rec.read(limits): the last frame's geometry, summed up (analyseMesh.summary): small, plain data. */
function geometryReader({ rec, bytesOf, FLOAT, TRIANGLES }, analyseMesh, infoOf) {
  return (limits) => {
    const frame = rec.cur && rec.cur.draws.length ? rec.cur : rec.last;
    const frames = [...rec.history.map((h) => h.vertices), ...(rec.cur ? [rec.cur.vertices] : [])];
    if (!frame) return { frames, why: 'no draw call was seen' };
    const draws = frame.draws.map((d) => {
      if (d.resolve) return d.resolve(); // (a WebGPU draw)
      const info = infoOf(d.gl, d.program);
      const attrib = (loc) => {
        const a = d.attribs[loc];
        if (!a || !a.enabled || !a.buffer) return null;
        return { ...a, bytes: bytesOf.get(a.buffer) || null };
      };
      return {
        mode: d.mode,
        first: d.first,
        count: d.count,
        indexed: d.indexed,
        ...(d.instances === undefined ? {} : { instances: d.instances }),
        type: d.type,
        offset: d.offset,
        cull: d.cull,
        indices: d.indexed && d.elements ? bytesOf.get(d.elements) || null : null,
        attributes: info
          ? info.attributes.map((a) => ({
              name: a.name,
              type: a.type,
              position: a.name === info.position,
              ...(a.location >= 0 ? { data: attrib(a.location) } : {}),
            }))
          : [],
      };
    });
    return {
      frames,
      calls: frame.calls,
      over: frame.over,
      ...analyseMesh.summary(draws, { FLOAT, TRIANGLES, ...limits }),
    };
  };
}
