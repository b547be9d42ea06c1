// WebGPU for the steps: the device and the canvas's context (or a clear message why there is
// none), WGSL fetched from its file with errors shown by file and line, and the uniforms by their
// names in the shader: the uniform struct's layout is read from the WGSL itself, so a step keeps
// its uniforms as one object, as its WebGL twin does (common/shaders.js setUniforms).
import { listing } from './shaders.js';

/** An error whose message the page shows with a link (here: the same view in WebGL). */
function withWebGLLink(message) {
  const err = new Error(message);
  const query = new URLSearchParams(location.search);
  query.set('api', 'webgl2');
  err.link = { href: `${location.pathname}?${query}`, text: 'Open this view in WebGL instead' };
  return err;
}

/**
 * The adapter's device and the canvas configured for it.
 * @returns {Promise<{device: GPUDevice, context: GPUCanvasContext, format: GPUTextureFormat}>}
 * @throws {Error} with a link to the WebGL view, when the browser has no WebGPU or no adapter
 */
export async function requestGPU(canvas) {
  if (!navigator.gpu) {
    throw withWebGLLink('This browser has no WebGPU (navigator.gpu is missing; it needs a recent ' +
      'Chrome or Edge, Safari 26 or Firefox 141, served over http://localhost or https://).');
  }
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw withWebGLLink('WebGPU is there, but this browser found no GPU adapter for it.');
  const device = await adapter.requestDevice();
  if (!device) throw withWebGLLink('WebGPU is there, but the GPU adapter gave no device.');
  const context = canvas.getContext('webgpu');
  const format = navigator.gpu.getPreferredCanvasFormat();
  context.configure({ device, format, alphaMode: 'opaque' });
  return { device, context, format };
}

/** Fetches a WGSL file (relative to the page). */
export async function loadWGSL(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (err) {
    throw new Error(`Could not load the shader ${url}: ${err.message}`, { cause: err });
  }
  if (!response.ok) throw new Error(`Could not load the shader ${url}: the server answered ${response.status} ${response.statusText}`);
  return { code: await response.text(), name: url };
}

/**
 * Compiles WGSL; a compilation error throws an Error naming the file and line, with the source
 * listed and the line marked (the page shows it), as the WebGL steps do for GLSL.
 */
export async function createShaderModule(device, { code, name }) {
  // in an error scope: a bad module is reported here, by file and line, not as a stray device error
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ label: name, code });
  const [info] = await Promise.all([module.getCompilationInfo(), device.popErrorScope()]);
  const error = info.messages.find((m) => m.type === 'error');
  if (error) {
    const err = new Error(`Shader error in ${name}, line ${error.lineNum}: ${error.message}`);
    err.details = listing(code, error.lineNum);
    throw err;
  }
  return module;
}

// WGSL's host-shareable types: [alignment, size] in bytes
const TYPES = {
  f32: [4, 4], u32: [4, 4], i32: [4, 4],
  vec2f: [8, 8], vec3f: [16, 12], vec4f: [16, 16],
  mat3x3f: [16, 48], mat4x4f: [16, 64],
};
const SPELLED = { 'vec2<f32>': 'vec2f', 'vec3<f32>': 'vec3f', 'vec4<f32>': 'vec4f', 'mat3x3<f32>': 'mat3x3f', 'mat4x4<f32>': 'mat4x4f' };

/**
 * The layout of a uniform struct in WGSL source: each member's byte offset and type, by WGSL's
 * alignment rules (a vec3f takes 16 bytes' alignment, a mat3x3f three 16-byte columns).
 * @returns {{size: number, fields: {name: string, type: string, offset: number}[]}}
 */
export function uniformLayout(code, struct = 'Uniforms') {
  const plain = code.replace(/\/\/.*$/gm, '');
  const match = new RegExp(`struct\\s+${struct}\\s*\\{([^}]*)\\}`).exec(plain);
  if (!match) throw new Error(`uniformLayout: the WGSL has no struct ${struct}`);
  const fields = [];
  let end = 0, largest = 4;
  for (const member of match[1].split(',').map((m) => m.trim()).filter(Boolean)) {
    const [, name, spelled] = /^(?:@\w+\(\d+\)\s*)*(\w+)\s*:\s*(\S+)$/.exec(member) || [];
    const type = SPELLED[spelled] || spelled;
    if (!TYPES[type]) throw new Error(`uniformLayout: ${struct}.${name || member} has a type this helper does not lay out (${spelled})`);
    const [align, size] = TYPES[type];
    const offset = Math.ceil(end / align) * align;
    fields.push({ name, type, offset });
    end = offset + size;
    largest = Math.max(largest, align);
  }
  return { size: Math.ceil(end / largest) * largest, fields };
}

/**
 * One uniform buffer for the struct `Uniforms` of this WGSL, with the bytes that fill it.
 * @returns {{buffer: GPUBuffer, layout: object, f32: Float32Array, u32: Uint32Array}}
 */
export function createUniformBuffer(device, code, label) {
  const layout = uniformLayout(code);
  const bytes = new ArrayBuffer(layout.size);
  const buffer = device.createBuffer({ label, size: layout.size, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
  return { buffer, layout, f32: new Float32Array(bytes), u32: new Uint32Array(bytes) };
}

/**
 * Writes the uniform buffer: each member of the WGSL struct takes `uniforms[name]`, or else
 * `values[name]` (a step's parameters: kd, ks, s, Le, La). A number given for a vector fills every
 * component; a boolean goes to a u32 as 0 or 1; a mat3x3f takes a column-major 3×3 (9 numbers).
 */
export function setUniforms(device, block, uniforms, values = {}) {
  const { f32, u32, layout } = block;
  for (let i = 0; i < layout.fields.length; i++) {
    const { name, type, offset } = layout.fields[i];
    const v = name in uniforms ? uniforms[name] : values[name];
    if (v === undefined) throw new Error(`setUniforms: the shader's uniform ${name} has no value`);
    const at = offset / 4;
    if (type === 'u32' || type === 'i32') u32[at] = Number(v);
    else if (type === 'f32') f32[at] = v;
    else if (type === 'mat3x3f') {
      for (let c = 0; c < 3; c++) for (let r = 0; r < 3; r++) f32[at + 4 * c + r] = v[3 * c + r];
    } else {
      const n = type === 'mat4x4f' ? 16 : Number(type[3]);
      for (let k = 0; k < n; k++) f32[at + k] = typeof v === 'number' ? v : v[k];
    }
  }
  device.queue.writeBuffer(block.buffer, 0, f32);
}
