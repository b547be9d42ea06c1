// What a WebGPU page sends as geometry, for grader/browser/geometry.js (which calls this inside the
// graded page, with its frame bookkeeping): the bytes of each vertex and index buffer (created
// mapped, or written by queue.writeBuffer), each pipeline's vertex layout, topology and culling, and
// each draw with the buffers bound then. A frame ends at a queue's submit. Each draw is resolved
// into the form grader/browser/mesh.js sums up only when the grader asks.
export function webgpuGeometry({ frameOf, closeFrame, wrap: after, bytesIn, vertexInputs, MAX_DRAWS, FLOAT, TRIANGLES }) {
  if (!window.GPUDevice || !window.GPURenderPassEncoder) return;
  const VERTEX = 0x20, INDEX = 0x10;
  const bytesOf = new WeakMap(); // GPUBuffer → Uint8Array
  const mapped = new WeakMap(); // GPUBuffer → its mapped ranges, copied at unmap
  const codeOf = new WeakMap(); // GPUShaderModule → WGSL
  const pipes = new WeakMap(); // GPURenderPipeline → { buffers, topology, cull, inputs }
  const passes = new WeakMap(); // GPURenderPassEncoder → { pipeline, vertex, index }
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
    try {
      const m = mapped.get(this), bytes = bytesOf.get(this);
      if (m && bytes) for (const { offset, range } of m) if (offset + range.byteLength <= bytes.length) bytes.set(new Uint8Array(range), offset);
      mapped.delete(this);
    } catch { /* (a detached range: nothing kept) */ }
    return unmap.apply(this, a);
  };
  after(Q, 'writeBuffer', (queue, [buffer, at, data, dataOffset, size]) => {
    const bytes = bytesOf.get(buffer), part = bytes && bytesIn(data, dataOffset, size);
    if (part && at + part.length <= bytes.length) bytes.set(part, at);
  });
  after(Q, 'submit', () => closeFrame());
  after(D, 'createShaderModule', (device, [desc], module) => codeOf.set(module, String((desc && desc.code) || '')));
  const see = (desc, pipeline) => {
    const v = (desc && desc.vertex) || {}, prim = (desc && desc.primitive) || {};
    pipes.set(pipeline, {
      buffers: [...(v.buffers || [])].map((b) => b && { stride: b.arrayStride, attributes: [...(b.attributes || [])].map((a) => ({ format: a.format, offset: a.offset || 0, location: a.shaderLocation })) }),
      topology: prim.topology || 'triangle-list',
      cull: prim.cullMode && prim.cullMode !== 'none' ? `${prim.cullMode}/${prim.frontFace || 'ccw'}` : 'off',
      inputs: vertexInputs(codeOf.get(v.module) || '', v.entryPoint),
    });
  };
  after(D, 'createRenderPipeline', (device, [desc], pipeline) => see(desc, pipeline));
  after(D, 'createRenderPipelineAsync', (device, [desc], promise) => promise.then((pipeline) => see(desc, pipeline), () => {}));
  const stateOf = (pass) => passes.get(pass) || passes.set(pass, { pipeline: null, vertex: [], index: null }).get(pass);
  after(P, 'setPipeline', (pass, [pipeline]) => { stateOf(pass).pipeline = pipeline; });
  after(P, 'setVertexBuffer', (pass, [slot, buffer, offset = 0]) => { stateOf(pass).vertex[slot] = buffer ? { buffer, offset } : null; });
  after(P, 'setIndexBuffer', (pass, [buffer, format, offset = 0]) => { stateOf(pass).index = { buffer, format, offset }; });
  const SIZES = { float32x2: 2, float32x3: 3, float32x4: 4 };
  const resolver = (st, d) => () => {
    const pipe = pipes.get(st.pipeline);
    if (!pipe) return { mode: 0, count: d.count, attributes: [] };
    const attributes = [];
    pipe.buffers.forEach((b, slot) => {
      const bound = st.vertex[slot];
      for (const a of b ? b.attributes : []) {
        const input = pipe.inputs.byLocation[a.location] || { name: `@location(${a.location})` };
        const size = SIZES[a.format] || 0;
        attributes.push({ name: input.name, type: size >= 3 ? `vec${size}` : a.format, position: a.location === pipe.inputs.position,
          data: bound && { bytes: bytesOf.get(bound.buffer) || null, size, type: size ? FLOAT : 0, stride: b.stride, offset: bound.offset + a.offset, enabled: true } });
      }
    });
    const index = d.indexed && st.index;
    const bytes = index && index.format === 'uint32' ? 4 : 2;
    return { mode: pipe.topology === 'triangle-list' ? TRIANGLES : -1, first: d.first, count: d.count, indexed: d.indexed, cull: pipe.cull,
      type: bytes === 4 ? 0x1405 : 0x1403, offset: index ? index.offset + d.first * bytes : 0, base: d.base || 0,
      indices: index ? bytesOf.get(index.buffer) || null : null, attributes };
  };
  const push = (pass, d) => {
    const f = frameOf(d.count);
    if (f.draws.length >= MAX_DRAWS) { f.over++; return; }
    const st = stateOf(pass);
    const snap = { pipeline: st.pipeline, vertex: [...st.vertex], index: st.index && { ...st.index } };
    const pipe = pipes.get(st.pipeline);
    f.draws.push({ mode: pipe && pipe.topology === 'triangle-list' ? TRIANGLES : -1, count: d.count, resolve: resolver(snap, d) });
  };
  after(P, 'draw', (pass, [count, , first = 0]) => push(pass, { count: count | 0, first: first | 0, indexed: false }));
  after(P, 'drawIndexed', (pass, [count, , firstIndex = 0, baseVertex = 0]) => push(pass, { count: count | 0, first: firstIndex | 0, base: baseVertex | 0, indexed: true }));
}
