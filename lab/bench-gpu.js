// The browser end of the WebGPU bench, the twin of lab/bench-page.js: lab/bench-gpu.html loads this
// module, and tools/bench.js (npm run bench) drives it through window.bench, documented below. It
// renders into its own texture (no canvas: headless Chromium cannot present a WebGPU one) and
// reads that back for the error measures.
// Methods: flat (lab/flat.wgsl), gouraud (WP04P4/shader.wgsl), phong (WP04P5/shader.wgsl),
// impostor (lab/impostor.wgsl), with the same camera, light and material as lab/bench-page.js.

/**
 * window.bench: published once the pipelines are built, and then window.benchReady = true (a
 * failure shows in #messages as an .error instead). Unlike the WebGL bench, the calls that wait
 * for the GPU return Promises. URL parameter of lab/bench-gpu.html: size (the target's width and
 * height in pixels, default 256).
 *
 * @typedef {object} GPUBench
 * @property {'webgpu'} api
 * @property {string} renderer the adapter's vendor, architecture and description (adapter.info)
 * @property {number} maxLevel the largest subdivision level (MAX_LEVEL of common/sphere.js)
 * @property {(level: number) => {vertices: number, bytes: number}} setMesh builds the sphere at
 *   `level` (sphereMesh, the slides' drawArrays layout, plus the face centroids for flat shading)
 *   and writes it into the vertex buffers made once for the largest level (queue.writeBuffer)
 * @property {(method: 'flat'|'gouraud'|'phong'|'impostor') => void} setMethod the pipeline to draw with
 * @property {(angle: number) => void} setAngle the orbit angle α in radians: eye = (3 sin α, 0, 3 cos α)
 * @property {(material: {kd?: number, ka?: number, ks?: number, s?: number}) => void} setMaterial
 *   changes some of the material (the shaders take ka = kd)
 * @property {(frames: number, warmup?: number) => Promise<number[]>} frameTimes draws `warmup`
 *   frames (default 3), then `frames` timed ones, each one render pass submitted and awaited with
 *   queue.onSubmittedWorkDone(); returns ms per frame
 * @property {() => Promise<string>} capture draws once; returns the target, RGBA bytes, row 0 at the
 *   top, as base64 (copyTextureToBuffer, mapAsync)
 * @property {() => object} scene the view, as lab/bench-page.js's scene() gives it
 * @property {(level: number, repeats: number) => Promise<{ours: number[], cold: number[], classic: number[], bound: number[]}>} levelChange
 *   times one level change `repeats` times four ways, each to the end of the upload (awaiting
 *   onSubmittedWorkDone): ours (a click: the level built ahead in idle time, one writeBuffer into
 *   the one buffer), cold (sphereMesh built on the spot + writeBuffer), classic (the
 *   textbook's vec4 arrays, flattened, into a new buffer each time, the old one destroyed), bound
 *   (the same bytes copied by one flat loop into a reused array + writeBuffer). ms per change.
 *   Leaves the mesh at `level`.
 * @property {() => Promise<string[]>} gpuErrors the validation and device-loss errors so far (none
 *   when nothing went wrong)
 */

import { lookAt, mat3, mat4, normalMatrix, perspectiveZO } from '../common/math.js';
import { MAX_LEVEL, sphereMesh, vertexBytes } from '../common/sphere.js';
import { createShaderModule, createUniformBuffer, loadWGSL, setUniforms } from '../common/gpu.js';
import { run } from '../common/page.js';
import { arriveByClick, arriveCold, classicSphere, settle, faceCentroids } from './meshes.js';
import { BACKGROUND, EYE_DISTANCE, FOVY } from '../common/course.js';

const FORMAT = 'rgba8unorm';

async function main() {
  const params = new URLSearchParams(location.search);
  const size = Number(params.get('size')) || 256;

  // The device (no canvas: the frames go to a texture of our own)
  if (!navigator.gpu) throw new Error('This browser has no WebGPU (navigator.gpu is missing): the WebGPU bench needs it.');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('WebGPU is there, but this browser found no GPU adapter for it.');
  const device = await adapter.requestDevice();
  const errors = [];
  device.addEventListener('uncapturederror', (e) => errors.push(e.error.message));
  device.lost.then((info) => errors.push(`device lost: ${info.message}`));
  const info = adapter.info || {};

  const sources = {
    gouraud: await loadWGSL('../WP04P4/shader.wgsl'),
    phong: await loadWGSL('../WP04P5/shader.wgsl'),
    flat: await loadWGSL('flat.wgsl'),
    impostor: await loadWGSL('impostor.wgsl'),
  };

  const camera = { eye: [0, 0, EYE_DISTANCE], at: [0, 0, 0], up: [0, 1, 0], fovy: FOVY, aspect: 1, near: 0.1, far: 10 };
  const light = { position: [0, 0, -1, 0], Le: 1, La: 0.2 };
  const material = { kd: 0.8, ka: 0.8, ks: 0.5, s: 40 };
  const P = perspectiveZO(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = mat4(), N = mat3();
  const t = Math.tan((FOVY * Math.PI) / 360);
  const uniforms = { P, V, N, lightPos: light.position, blinnPhong: false, tanHalf: [t * camera.aspect, t] };

  // Set-up, once: the buffers (sized for the largest level), the target, one pipeline per method
  const positionBuffer = device.createBuffer({ label: 'sphere vertices', size: vertexBytes(MAX_LEVEL), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
  const faceBuffer = device.createBuffer({ label: 'face centroids', size: vertexBytes(MAX_LEVEL), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
  const quadBuffer = device.createBuffer({ label: 'impostor quad', size: 48, usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(quadBuffer, 0, new Float32Array([-1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1, 1]));
  const target = device.createTexture({ label: 'bench target', size: [size, size], format: FORMAT,
    usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
  const depth = device.createTexture({ label: 'depth', size: [size, size], format: 'depth24plus', usage: GPUTextureUsage.RENDER_ATTACHMENT });
  const bytesPerRow = Math.ceil((4 * size) / 256) * 256;
  const readback = device.createBuffer({ label: 'readback', size: bytesPerRow * size, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });

  const position = { arrayStride: 12, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x3' }] };
  const layouts = {
    gouraud: [position], phong: [position],
    flat: [position, { arrayStride: 12, attributes: [{ shaderLocation: 1, offset: 0, format: 'float32x3' }] }],
    impostor: [{ arrayStride: 8, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x2' }] }],
  };
  const methods = {};
  for (const [name, wgsl] of Object.entries(sources)) {
    const module = await createShaderModule(device, wgsl);
    const pipeline = device.createRenderPipeline({
      label: `bench ${name}`,
      layout: 'auto',
      vertex: { module, entryPoint: 'main_vs', buffers: layouts[name] },
      fragment: { module, entryPoint: 'main_fs', targets: [{ format: FORMAT }] },
      primitive: { topology: 'triangle-list', frontFace: 'ccw', cullMode: name === 'impostor' ? 'none' : 'back' },
      depthStencil: { depthWriteEnabled: true, depthCompare: 'less', format: 'depth24plus' },
    });
    const block = createUniformBuffer(device, wgsl.code, `${name} uniforms`);
    const bindGroup = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer: block.buffer } }] });
    methods[name] = { pipeline, block, bindGroup };
  }

  let method = 'phong', level = 0, count = 0, angle = 0;
  let faces = new Float32Array(0);

  // The uniforms of the current method (set-up for a series of timed frames, not timed)
  function prepare() {
    camera.eye[0] = EYE_DISTANCE * Math.sin(angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(angle);
    lookAt(camera.eye, camera.at, camera.up, V);
    normalMatrix(V, N);
    setUniforms(device, methods[method].block, uniforms, { kd: material.kd, ks: material.ks, s: material.s, Le: light.Le, La: light.La });
  }

  // ---- set-up ends here; drawing: one render pass per frame ----
  const [r, g, b, a] = BACKGROUND;
  function encode() {
    const { pipeline, bindGroup } = methods[method];
    const encoder = device.createCommandEncoder({ label: 'bench frame' });
    const pass = encoder.beginRenderPass({
      colorAttachments: [{ view: target.createView(), loadOp: 'clear', clearValue: { r, g, b, a }, storeOp: 'store' }],
      depthStencilAttachment: { view: depth.createView(), depthLoadOp: 'clear', depthClearValue: 1.0, depthStoreOp: 'store' },
    });
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bindGroup);
    if (method === 'impostor') {
      pass.setVertexBuffer(0, quadBuffer);
      pass.draw(6);
    } else {
      pass.setVertexBuffer(0, positionBuffer);
      if (method === 'flat') pass.setVertexBuffer(1, faceBuffer);
      pass.draw(count);
    }
    pass.end();
    return encoder;
  }
  // Waiting for the queue is the analogue of the WebGL bench's 1-pixel readPixels
  const sync = () => device.queue.onSubmittedWorkDone();

  /** @type {GPUBench} */
  window.bench = {
    api: 'webgpu',
    renderer: [info.vendor, info.architecture, info.description || info.device].filter(Boolean).join(', ') || 'unknown adapter',
    maxLevel: MAX_LEVEL,
    setMesh(lvl) {
      level = lvl;
      const positions = sphereMesh(lvl);
      count = positions.length / 3;
      device.queue.writeBuffer(positionBuffer, 0, positions);
      if (faces.length < positions.length) faces = new Float32Array(positions.length);
      device.queue.writeBuffer(faceBuffer, 0, faceCentroids(positions, count, faces), 0, positions.length);
      return { vertices: count, bytes: vertexBytes(lvl) };
    },
    setMethod(name) { method = name; prepare(); },
    setAngle(x) { angle = x; prepare(); },
    setMaterial(m) { Object.assign(material, m); prepare(); },
    async frameTimes(frames, warmup = 3) {
      prepare();
      for (let i = 0; i < warmup; i++) {
        device.queue.submit([encode().finish()]);
        await sync();
      }
      const times = [];
      for (let i = 0; i < frames; i++) {
        const t0 = performance.now();
        device.queue.submit([encode().finish()]);
        await sync();
        times.push(performance.now() - t0);
      }
      return times;
    },
    async capture() {
      prepare();
      const encoder = encode();
      encoder.copyTextureToBuffer({ texture: target }, { buffer: readback, bytesPerRow }, [size, size]);
      device.queue.submit([encoder.finish()]);
      await readback.mapAsync(GPUMapMode.READ);
      const padded = new Uint8Array(readback.getMappedRange());
      const rgba = new Uint8Array(size * size * 4);
      for (let j = 0; j < size; j++) rgba.set(padded.subarray(j * bytesPerRow, j * bytesPerRow + 4 * size), j * 4 * size);
      readback.unmap();
      let text = '';
      for (let i = 0; i < rgba.length; i += 0x8000) text += String.fromCharCode.apply(null, rgba.subarray(i, i + 0x8000));
      return btoa(text);
    },
    scene() {
      return { camera: JSON.parse(JSON.stringify(camera)), light, material, model: 'phong', shading: method,
        cullFace: true, level, canvas: { width: size, height: size } };
    },
    async levelChange(lvl, repeats) {
      const ours = [], cold = [], classic = [], bound = [];
      const source = sphereMesh(lvl).slice();
      const copy = new Float32Array(source.length);
      const boundBuffer = device.createBuffer({ label: 'bound', size: source.byteLength, usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
      let classicBuffer = null;
      const show = (positions) => device.queue.writeBuffer(positionBuffer, 0, positions);
      for (let k = 0; k < repeats; k++) {
        ours.push(await arriveByClick(lvl, show, sync));
        cold.push(await arriveCold(lvl, show, sync));

        await settle();
        let t0 = performance.now();
        const data = classicSphere(lvl);
        if (classicBuffer) classicBuffer.destroy();
        classicBuffer = device.createBuffer({ label: 'classic', size: data.byteLength, usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
        device.queue.writeBuffer(classicBuffer, 0, data);
        await sync();
        classic.push(performance.now() - t0);

        await settle();
        t0 = performance.now();
        for (let i = 0; i < source.length; i++) copy[i] = source[i];
        device.queue.writeBuffer(boundBuffer, 0, copy);
        await sync();
        bound.push(performance.now() - t0);
      }
      boundBuffer.destroy();
      classicBuffer?.destroy();
      this.setMesh(lvl);
      return { ours, cold, classic, bound };
    },
    async gpuErrors() {
      await sync();
      return [...errors];
    },
  };
  window.benchReady = true;
}

run(main);
