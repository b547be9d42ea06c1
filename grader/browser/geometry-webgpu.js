// What a WebGPU page sends as geometry, for grader/browser/geometry.js (which calls this inside the
// graded page, with its frame bookkeeping): the bytes of each vertex and index buffer (created
// mapped, or written by queue.writeBuffer), each pipeline's vertex layout, topology and culling, and
// each draw with the buffers and bind groups bound then and the size of the texture it drew into.
// A frame ends at a queue's submit. Each draw is resolved into the form grader/browser/mesh.js sums
// up only when the grader asks; its `gpu` (the pipeline's description, the bound objects, the call)
// is what grader/browser/surface-webgpu.js draws again.
export function webgpuGeometry(recorder, recordBindings, drawResolver) {
  if (!window.GPUDevice || !window.GPURenderPassEncoder) return;
  const { frameOf, closeFrame, wrap: after, bytesIn, vertexInputs, MAX_DRAWS, FLOAT, TRIANGLES } = recorder;
  const VERTEX = 0x20, INDEX = 0x10;
  const bytesOf = new WeakMap(); // GPUBuffer → Uint8Array
  const mapped = new WeakMap(); // GPUBuffer → its mapped ranges, copied at unmap
  const codeOf = new WeakMap(); // GPUShaderModule → WGSL
  const pipes = new WeakMap(); // GPURenderPipeline → { buffers, topology, cull, inputs, desc }
  const passes = new WeakMap(); // GPURenderPassEncoder → { pipeline, vertex, index, groups, size }
  const D = GPUDevice.prototype, Q = GPUQueue.prototype, B = GPUBuffer.prototype, P = GPURenderPassEncoder.prototype;
  after(D, 'createBuffer', (device, [desc], buffer) => {
    if (!desc || !(desc.usage & (VERTEX | INDEX)) || !(desc.size > 0 && desc.size < 2 ** 28)) return;
    bytesOf.set(buffer, new Uint8Array(desc.size));
    if (desc.mappedAtCreation) mapped.set(buffer, []);
  });
  after(B, 'getMappedRange', (buffer, [offset = 0], range) => {
    const m = mapped.get(buffer);
    if (m && range) m.push({ offset, range });
  });
  const unmap = B.unmap;
  B.unmap = function (...a) {
    const m = mapped.get(this), bytes = bytesOf.get(this);
    try {
      for (const { offset, range } of m && bytes ? m : []) {
        if (offset + range.byteLength <= bytes.length) bytes.set(new Uint8Array(range), offset);
      }
    } catch { /* (a detached range: nothing kept) */ }
    mapped.delete(this);
    return unmap.apply(this, a);
  };
  after(Q, 'writeBuffer', (queue, [buffer, at, data, dataOffset, size]) => {
    const bytes = bytesOf.get(buffer), part = bytes && bytesIn(data, dataOffset, size);
    if (part && at + part.length <= bytes.length) bytes.set(part, at);
  });
  after(Q, 'submit', () => closeFrame());
  after(D, 'createShaderModule', (device, [desc], module) => codeOf.set(module, String((desc && desc.code) || '')));
  const stateOf = (pass) => passes.get(pass)
    || passes.set(pass, { pipeline: null, vertex: [], index: null, groups: [], size: null }).get(pass);
  const drawnAgainAs = recordBindings(after, stateOf);
  const see = (device, desc, pipeline) => {
    const v = (desc && desc.vertex) || {}, prim = (desc && desc.primitive) || {};
    pipes.set(pipeline, {
      desc: drawnAgainAs(device, desc, codeOf.get(v.module) || ''),
      buffers: [...(v.buffers || [])].map((b) => b && { stride: b.arrayStride,
        attributes: [...(b.attributes || [])].map((a) => ({ format: a.format, offset: a.offset || 0,
          location: a.shaderLocation })) }),
      topology: prim.topology || 'triangle-list',
      cull: prim.cullMode && prim.cullMode !== 'none' ? `${prim.cullMode}/${prim.frontFace || 'ccw'}` : 'off',
      inputs: vertexInputs(codeOf.get(v.module) || '', v.entryPoint),
    });
  };
  after(D, 'createRenderPipeline', (device, [desc], pipeline) => see(device, desc, pipeline));
  after(D, 'createRenderPipelineAsync', (device, [desc], promise) => promise.then((pipeline) => see(device, desc, pipeline), () => {}));
  after(P, 'setPipeline', (pass, [pipeline]) => { stateOf(pass).pipeline = pipeline; });
  after(P, 'setVertexBuffer', (pass, [slot, buffer, offset = 0]) => {
    stateOf(pass).vertex[slot] = buffer ? { buffer, offset } : null;
  });
  after(P, 'setIndexBuffer', (pass, [buffer, format, offset = 0]) => { stateOf(pass).index = { buffer, format, offset }; });
  const resolver = drawResolver({ pipes, bytesOf, FLOAT, TRIANGLES });
  const { topologyMode } = resolver;
  const push = (pass, d) => {
    const f = frameOf(d.count);
    if (f.draws.length >= MAX_DRAWS) { f.over++; return; }
    const st = stateOf(pass);
    const snap = { pipeline: st.pipeline, vertex: [...st.vertex], index: st.index && { ...st.index } };
    const pipe = pipes.get(st.pipeline);
    f.draws.push({ mode: topologyMode(pipe), count: d.count, resolve: resolver(snap, d),
      gpu: pipe && { desc: pipe.desc, vertex: snap.vertex, index: snap.index, groups: [...st.groups], size: st.size,
        call: d } });
  };
  after(P, 'draw', (pass, [count, instances = 1, first = 0, firstInstance = 0]) =>
    push(pass, { count: count | 0, first: first | 0, indexed: false, instances, firstInstance }));
  after(P, 'drawIndexed', (pass, [count, instances = 1, firstIndex = 0, baseVertex = 0, firstInstance = 0]) =>
    push(pass, { count: count | 0, first: firstIndex | 0, base: baseVertex | 0, indexed: true, instances,
      firstInstance }));
}

/**
 * A draw resolved, when the grader asks, into the form grader/browser/mesh.js sums up: (the pass's
 * state as the draw saw it, the draw) → () → { mode, count, indexed, cull, indices, attributes, ... },
 * from the pipelines seen (`pipes`) and the buffers' bytes (`bytesOf`); its topologyMode(pipeline
 * seen) is the WebGL mode a draw is recorded with.
 */
export function webgpuDrawResolver({ pipes, bytesOf, FLOAT, TRIANGLES }) {
  // (WebGL's mode for a topology: lines as LINES and LINE_STRIP, so that a wireframe is told as in WebGL)
  const MODES = { 'triangle-list': TRIANGLES, 'line-list': 1, 'line-strip': 3 };
  const topologyMode = (pipe) => (pipe && pipe.topology in MODES ? MODES[pipe.topology] : -1);
  const SIZES = { float32x2: 2, float32x3: 3, float32x4: 4 };
  const resolve = (st, d) => () => {
    const pipe = pipes.get(st.pipeline);
    if (!pipe) return { mode: 0, count: d.count, attributes: [] };
    const attributes = [];
    pipe.buffers.forEach((b, slot) => {
      const bound = st.vertex[slot];
      for (const a of b ? b.attributes : []) {
        const input = pipe.inputs.byLocation[a.location] || { name: `@location(${a.location})` };
        const size = SIZES[a.format] || 0;
        const data = bound && { bytes: bytesOf.get(bound.buffer) || null, size, type: size ? FLOAT : 0,
          stride: b.stride, offset: bound.offset + a.offset, enabled: true };
        const type = size >= 3 ? `vec${size}` : a.format;
        attributes.push({ name: input.name, type, position: a.location === pipe.inputs.position, data });
      }
    });
    const index = d.indexed && st.index;
    const bytes = index && index.format === 'uint32' ? 4 : 2;
    return { mode: topologyMode(pipe), first: d.first, count: d.count, indexed: d.indexed,
      cull: pipe.cull,
      type: bytes === 4 ? 0x1405 : 0x1403, offset: index ? index.offset + d.first * bytes : 0, base: d.base || 0,
      indices: index ? bytesOf.get(index.buffer) || null : null, attributes };
  };
  return Object.assign(resolve, { topologyMode });
}

/**
 * For the surface (grader/browser/surface-webgpu.js): each bind group's entries, and what a pass
 * binds and draws into (its bind groups; the size of its first colour attachment's texture), kept
 * in the pass's state (`stateOf`). Returns what a pipeline is drawn again as: (device, desc, its
 * vertex stage's WGSL) → { device, code, entryPoint, constants, buffers, primitive, depth }.
 */
export function webgpuBindings(after, stateOf) {
  const groupsOf = new WeakMap(); // GPUBindGroup → its entries ({ binding, resource })
  const textureOf = new WeakMap(); // GPUTextureView → its GPUTexture
  after(GPUDevice.prototype, 'createBindGroup', (device, [desc], group) =>
    groupsOf.set(group, [...((desc && desc.entries) || [])]
      .map((e) => ({ binding: e.binding, resource: e.resource }))));
  after(GPUTexture.prototype, 'createView', (texture, args, view) => textureOf.set(view, texture));
  // the size of the texture a pass draws into (its first colour attachment's)
  after(GPUCommandEncoder.prototype, 'beginRenderPass', (encoder, [desc], pass) => {
    const a = desc && desc.colorAttachments && [...desc.colorAttachments].find(Boolean);
    const t = a && textureOf.get(a.view);
    if (t) stateOf(pass).size = { width: t.width, height: t.height };
  });
  after(GPURenderPassEncoder.prototype, 'setBindGroup', (pass, [index, group, offsets]) => {
    const dynamic = !!(offsets && offsets.length);
    stateOf(pass).groups[index] = group ? { group, entries: groupsOf.get(group) || null, dynamic } : null;
  });
  return (device, desc, code) => {
    const v = desc.vertex || {}, depth = desc.depthStencil;
    return { device, code, entryPoint: v.entryPoint, constants: v.constants, buffers: v.buffers,
      primitive: desc.primitive || {}, depth: depth ? { compare: depth.depthCompare || 'less' } : null };
  };
}

/** The recorder as an expression for a page's script: (G) → the WebGPU record, with its bindings'. */
export const webgpuRecorderScript = `((g) => (${webgpuGeometry})(g, ${webgpuBindings}, ${webgpuDrawResolver}))`;
