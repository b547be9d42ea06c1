// The surface a WebGPU page drew, per pixel, from what it sent: the last frame's triangle-list draws
// into its canvas drawn again on the page's own device with pipelines of the grader's own, into a
// float texture of the canvas's size (the page's canvas and passes are only read). The page's WGSL
// is kept whole; its vertex entry point becomes a plain function (its parameters' and result's
// attributes left out), and an entry point of ours with the page's own parameters calls it and
// hands on, per vertex, the position input (the model's space), the normal input (where one is
// named for a normal; else the position: n = p) and the clip position; a fragment entry point of
// ours writes them out in float, one pass each (an override constant picks which), with whether the
// face seen is a front face. The page's own vertex and index buffers and the resources of its bind
// groups are bound as it bound them, so each pixel's position and normal are the page's own,
// rasterised as the page rasterised them. Every call goes to the browser's own functions
// (window.__glNative.gpu: grader/browser/natives.js): nothing is counted, recorded, captured or seen as the page's.
// Self-contained parts, put into graded pages as text (webgpuSurfaceReaderScript, by grader/browser/geometry.js);
// wgslForSurface is also run by the unit tests in Node. The entry point is read by wgsl-vertex.js.
import { wgslVertexEntry } from './wgsl-vertex.js';

/**
 * The page's WGSL `code` with our entry points for the surface, around its vertex entry point
 * `entryPoint` (else its first @vertex function): { code, position, normal } (the inputs' names),
 * or { why } where the entry point or its position input is not found.
 */
export function wgslForSurface(code, entryPoint) {
  const e = wgslVertexEntry(code, entryPoint);
  if (e.why) return e;
  const { src, params, inputs, structOf } = e;
  if (e.body < 0) return { why: 'the vertex entry point\'s body was not found' };
  if (params.some((p) => !p)) return { why: 'the vertex entry point\'s parameters could not be read' };
  const size = (t) => { const m = /^vec([234])/.exec(t); return m ? Number(m[1]) : 0; };
  const vector = (i) => size(i.type) >= 3;
  const position = inputs.find((i) => vector(i) && /pos|vert/i.test(i.name))
    || inputs.find((i) => i.at === 0 && size(i.type) >= 2);
  if (!position) return { why: 'the vertex entry point\'s position input was not found' };
  const normal = inputs.find((i) => i !== position && vector(i) && /norm/i.test(i.name)) || null;
  const n = size(position.type);
  const p4 = n === 4 ? `vec4f(${position.path})` : n === 3 ? `vec4f(${position.path}, 1.0)` : `vec4f(${position.path}, 0.0, 1.0)`;
  // the clip position: the result itself, or its struct's @builtin(position) member
  const type = e.resultType;
  const members = structOf(type);
  const clipMember = members && members.find((m) => /@builtin\s*\(\s*position\s*\)/.test(m.attrs));
  if (!clipMember && !/^vec4(f|<\s*f32\s*>)$/.test(type)) return { why: 'the vertex entry point\'s clip position was not found' };
  const clip = clipMember ? `r.${clipMember.name}` : 'r';
  const plain = `fn _grPage(${params.map((p) => `${p.name}: ${p.type}`).join(', ')}) -> ${type} {`;
  const out = `${src.slice(0, e.at)}${plain}${src.slice(e.body + 1)}
struct _GrOut { @builtin(position) clip: vec4f, @location(0) p: vec4f, @location(1) n: vec4f, @location(2) c: vec4f }
override _grWhat: u32 = 0u;
@vertex fn _grVs(${e.paramsText}) -> _GrOut {
  let r = _grPage(${params.map((p) => p.name).join(', ')});
  var o: _GrOut;
  o.clip = ${clip};
  o.p = ${p4};
  o.n = vec4f(${normal ? normal.path : p4}.xyz, 0.0);
  o.c = o.clip;
  return o;
}
@fragment fn _grFs(i: _GrOut, @builtin(front_facing) front: bool) -> @location(0) vec4f {
  if (_grWhat == 0u) { return vec4f(i.p.xyz / i.p.w, select(2.0, 1.0, front)); }
  if (_grWhat == 1u) { return vec4f(i.n.xyz, 1.0); }
  return i.c;
}
`;
  return { code: out, position: position.name, normal: normal ? normal.name : null };
}

/**
 * A bind group layout entry for each binding the page's WGSL declares in group `group` (its
 * `var` type), for the bindings `entries` (the page's bind group) holds: [{ binding, visibility,
 * buffer | sampler | texture | externalTexture }], or { why }.
 */
export function layoutEntries(code, group, entries) {
  const src = String(code).replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, ' ');
  const DECL = /((?:@(?:group|binding)\s*\(\s*\d+\s*\)\s*){2})var\s*(<[^>]*>)?\s*\w+\s*:\s*([^;=]+)/g;
  const declared = new Map();
  for (const m of src.matchAll(DECL)) {
    const g = /@group\s*\(\s*(\d+)/.exec(m[1]), b = /@binding\s*\(\s*(\d+)/.exec(m[1]);
    if (g && b && Number(g[1]) === group) {
      declared.set(Number(b[1]), { space: (m[2] || '').replace(/[<>\s]/g, ''), type: m[3].trim() });
    }
  }
  const VERTEX = 1, FRAGMENT = 2;
  const out = [];
  for (const e of entries) {
    const d = declared.get(e.binding);
    if (!d) continue;
    const view = (t) => (/cube_array/.test(t) ? 'cube-array' : /cube/.test(t) ? 'cube' : /2d_array/.test(t) ? '2d-array' : /3d/.test(t) ? '3d' : /1d/.test(t) ? '1d' : '2d');
    if (d.space === 'uniform') out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, buffer: { type: 'uniform' } });
    else if (d.space.startsWith('storage')) {
      const rw = /read_write/.test(d.space);
      out.push({ binding: e.binding, visibility: rw ? FRAGMENT : VERTEX | FRAGMENT, buffer: { type: rw ? 'storage' : 'read-only-storage' } });
    } else if (/^sampler_comparison/.test(d.type)) out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, sampler: { type: 'comparison' } });
    else if (/^sampler/.test(d.type)) out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, sampler: { type: 'filtering' } });
    else if (/^texture_external/.test(d.type)) out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, externalTexture: {} });
    else if (/^texture_depth/.test(d.type)) {
      const texture = { sampleType: 'depth', viewDimension: view(d.type), multisampled: /multisampled/.test(d.type) };
      out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, texture });
    }
    else if (/^texture_(1d|2d|3d|cube|multisampled)/.test(d.type)) {
      const sampleType = /<\s*u32/.test(d.type) ? 'uint' : /<\s*i32/.test(d.type) ? 'sint' : 'unfilterable-float'; // (the most a float texture's format allows)
      const texture = { sampleType, viewDimension: view(d.type), multisampled: /multisampled/.test(d.type) };
      out.push({ binding: e.binding, visibility: VERTEX | FRAGMENT, texture });
    } else return { why: `binding ${e.binding} of group ${group} (${d.type}) is of a kind the grader does not bind again` };
  }
  return out;
}

/**
 * The reader, from its parts: ({ rec, TRIANGLES }) → (opts) → null where the last frame drew
 * nothing with WebGPU, else a promise of what grader/browser/surface.js's reader gives ({ width,
 * height, position, normal, box, covered, fit, normals, points } or { why }).
 */
function webgpuSurfaceOf({ pipelineMaker, encodePasses, readFloats, pictures }) {
  return ({ rec, TRIANGLES }) => ({ fitSamples }) => {
    const frame = rec.cur && rec.cur.draws.length ? rec.cur : rec.last;
    const all = frame ? frame.draws.filter((d) => d.gpu) : [];
    if (!all.length) return null;
    return drawAgain(
      all.filter((d) => d.mode === TRIANGLES && d.count >= 3 && d.gpu.size && d.gpu.desc.device),
      fitSamples,
    );
  };

  async function drawAgain(draws, fitSamples) {
    const N = window.__glNative && window.__glNative.gpu;
    if (!N || !N.GPUDevice) return { why: 'the browser\'s own WebGPU functions were not kept for the grader' };
    if (!draws.length) return { why: 'no triangle list (triangle-list) was drawn into a texture in the last frame' };
    // the draws into the largest texture: the canvas's
    const size = draws.reduce((a, d) => (d.gpu.size.width * d.gpu.size.height > a.width * a.height ? d.gpu.size : a), {
      width: 0,
      height: 0,
    });
    const mine = draws.filter((d) => d.gpu.size.width === size.width && d.gpu.size.height === size.height);
    const device = mine[0].gpu.desc.device;
    const call = (cls, name, self, ...a) => N[cls][name].apply(self, a);
    const dev = (name, ...a) => call('GPUDevice', name, device, ...a);
    const made = [];
    dev('pushErrorScope', 'validation');
    let out;
    try {
      const maker = pipelineMaker(dev, call);
      const passes = await encodePasses(mine, size, { call, dev, made, maker });
      const pics = pictures(await readFloats(passes, size, call), size.width, size.height, fitSamples);
      const inputs = maker.inputs();
      out = pics.why
        ? pics
        : { width: size.width, height: size.height, position: inputs.position, normal: inputs.normal, ...pics };
    } catch (err) {
      out = { why: `the page's geometry could not be drawn again: ${String(err && err.message).slice(0, 240)}` };
    }
    const error = await dev('popErrorScope').catch(() => null);
    if (error && !out.why) out = { why: `the page's geometry could not be drawn again: ${String(error.message).slice(0, 240)}` };
    for (const x of made) try { x.destroy(); } catch { /* (gone with the device) */ }
    return out;
  }
}

/**
 * Our pipelines for the page's: { layoutsOf(desc, groups) (each bound group's layout entries, from
 * the page's WGSL), pipelineOf(desc, layouts, what) (a promise), inputs() (the first module's
 * position and normal inputs) }. Each throws with the reason where it cannot.
 */
function pipelineMaker(dev, call) {
  const modules = new Map(), pipelines = new Map();
  let inputs = null;
  // our module for a page pipeline's vertex stage (its WGSL with our entry points), checked
  const moduleOf = async (desc) => {
    let m = modules.get(desc);
    if (!m) {
      const w = wgslForSurface(desc.code || '', desc.entryPoint);
      if (w.why) throw new Error(w.why);
      const module = dev('createShaderModule', { code: w.code });
      const info = await call('GPUShaderModule', 'getCompilationInfo', module);
      const error = [...info.messages].find((x) => x.type === 'error');
      if (error) throw new Error(`the grader's shader from the page's WGSL: ${error.message}`);
      modules.set(desc, m = module);
      inputs = inputs || w;
    }
    return m;
  };
  const layoutsOf = (desc, groups) => {
    const last = groups.reduce((k, g, i) => (g ? i : k), -1);
    return Array.from({ length: last + 1 }, (x, i) => {
      const g = groups[i];
      if (!g) return [];
      if (g.dynamic) throw new Error('a bind group with dynamic offsets');
      if (!g.entries) throw new Error(`bind group ${i} was made before the grader's record began`);
      const entries = layoutEntries(desc.code || '', i, g.entries);
      if (entries.why) throw new Error(entries.why);
      return entries;
    });
  };
  const pipelineOf = async (desc, layouts, what) => {
    const key = `${what} ${JSON.stringify(layouts)}`;
    let byDesc = pipelines.get(desc);
    if (!byDesc) pipelines.set(desc, byDesc = new Map());
    if (!byDesc.has(key)) {
      const module = await moduleOf(desc);
      const prim = desc.primitive || {};
      byDesc.set(key, dev('createRenderPipeline', {
        layout: dev('createPipelineLayout', { bindGroupLayouts: layouts.map((entries) => dev('createBindGroupLayout', { entries })) }),
        vertex: { module, entryPoint: '_grVs', buffers: desc.buffers,
          ...(desc.constants ? { constants: desc.constants } : {}) },
        fragment: { module, entryPoint: '_grFs', targets: [{ format: 'rgba32float' }], constants: { _grWhat: what } },
        primitive: { topology: 'triangle-list', cullMode: prim.cullMode || 'none', frontFace: prim.frontFace || 'ccw' },
        depthStencil: { format: 'depth32float', depthWriteEnabled: !!desc.depth, depthCompare: desc.depth ? desc.depth.compare : 'always' },
      }));
    }
    return byDesc.get(key);
  };
  return { layoutsOf, pipelineOf, inputs: () => inputs };
}

/**
 * The page's draws `mine` drawn again in three passes (what: 0 the position and the face, 1 the
 * normal, 2 the clip position) into a float texture of `size`, each copied into a buffer, and
 * submitted: { reads (the buffers), row (their rows' bytes, padded to 256) }. Each draw's layouts
 * and bind groups are made once, for the three passes.
 */
async function encodePasses(mine, { width, height }, { call, dev, made, maker }) {
  const colour = dev('createTexture', { size: [width, height], format: 'rgba32float', usage: 0x10 | 0x01 }); // RENDER_ATTACHMENT | COPY_SRC
  const depth = dev('createTexture', { size: [width, height], format: 'depth32float', usage: 0x10 });
  const row = Math.ceil((16 * width) / 256) * 256;
  const reads = [0, 1, 2].map(() => dev('createBuffer', { size: row * height, usage: 0x0001 | 0x0008 })); // MAP_READ | COPY_DST
  made.push(colour, depth, ...reads);
  // the page's own resources, in groups of ours (a layout made alike is the pipeline's)
  const bound = mine.map(({ gpu: { desc, groups } }) => {
    const layouts = maker.layoutsOf(desc, groups);
    return { layouts, groups: layouts.map((entries, i) => {
      const used = new Set(entries.map((e) => e.binding));
      const kept = groups[i] ? groups[i].entries.filter((e) => used.has(e.binding)) : [];
      return dev('createBindGroup', { layout: dev('createBindGroupLayout', { entries }), entries: kept });
    }) };
  });
  const encoder = dev('createCommandEncoder');
  for (const what of [0, 1, 2]) {
    const pass = call('GPUCommandEncoder', 'beginRenderPass', encoder, {
      colorAttachments: [{ view: call('GPUTexture', 'createView', colour), loadOp: 'clear', clearValue: { r: 0, g: 0, b: 0, a: 0 }, storeOp: 'store' }],
      depthStencilAttachment: { view: call('GPUTexture', 'createView', depth), depthLoadOp: 'clear', depthClearValue: 1, depthStoreOp: 'store' },
    });
    const enc = (name, ...a) => call('GPURenderPassEncoder', name, pass, ...a);
    for (const [k, d] of mine.entries()) {
      const { desc, vertex, index, call: c } = d.gpu;
      enc('setPipeline', await maker.pipelineOf(desc, bound[k].layouts, what));
      bound[k].groups.forEach((group, i) => enc('setBindGroup', i, group));
      vertex.forEach((v, slot) => { if (v) enc('setVertexBuffer', slot, v.buffer, v.offset); });
      if (c.indexed) {
        enc('setIndexBuffer', index.buffer, index.format, index.offset);
        enc('drawIndexed', c.count, c.instances, c.first, c.base || 0, c.firstInstance);
      } else enc('draw', c.count, c.instances, c.first, c.firstInstance);
    }
    call('GPURenderPassEncoder', 'end', pass);
    call('GPUCommandEncoder', 'copyTextureToBuffer', encoder, { texture: colour }, { buffer: reads[what], bytesPerRow: row }, [width, height]);
  }
  call('GPUQueue', 'submit', mine[0].gpu.desc.device.queue, [call('GPUCommandEncoder', 'finish', encoder)]);
  return { reads, row };
}

/** Each read-back buffer (`reads`, rows of `row` bytes) as floats, its rows from the bottom up (as WebGL reads them: pictures() turns them). */
async function readFloats({ reads, row }, { width, height }, call) {
  const floats = row / 4;
  const passes = [];
  for (const b of reads) {
    await call('GPUBuffer', 'mapAsync', b, 0x0001);
    const src = new Float32Array(call('GPUBuffer', 'getMappedRange', b));
    const px = new Float32Array(width * height * 4);
    for (let y = 0; y < height; y++) {
      px.set(src.subarray(y * floats, y * floats + 4 * width), 4 * (height - 1 - y) * width);
    }
    call('GPUBuffer', 'unmap', b);
    passes.push(px);
  }
  return passes;
}

/** The reader's maker as an expression for a page's script: ({ rec, TRIANGLES }) → rec's WebGPU surface reader; `picturesText` is surface.js's pictures(). */
export const webgpuSurfaceReaderScript = (picturesText) => `((${webgpuSurfaceOf})((() => {
  const wgslVertexEntry = ${wgslVertexEntry}, wgslForSurface = ${wgslForSurface}, layoutEntries = ${layoutEntries};
  const pipelineMaker = ${pipelineMaker};
  return { pipelineMaker, encodePasses: ${encodePasses}, readFloats: ${readFloats}, pictures: ${picturesText} };
})()))`;
