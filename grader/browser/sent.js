// What a graded page sets for its shaders, started by grader/browser/geometry.js's init script (with
// its helpers: `wrap` hears a call after it ran, `bytesIn` reads an upload's bytes): the last
// value of each uniform (WebGL: by the uniform's name; WebGPU: each 16 bytes of a uniform buffer),
// each constant attribute (gl.vertexAttrib*), and a digest of each vertex buffer's last upload.
// window.__sent.read() gives { key: digest }: two reads compared tell what the page sent
// differently between them (a slider's input event that changed kd, a view matrix that turned).
export function sentScript({ wrap: after, bytesIn }) {
  if (window.__sent) return;
  const values = new Map(); // key → digest (a string)
  const buffers = []; // the buffer keys, oldest first: a page that makes a buffer a frame keeps the last MAX_BUFFERS
  const MAX_BUFFERS = 256;
  const setBuffer = (key, digest) => {
    if (!values.has(key)) {
      buffers.push(key);
      if (buffers.length > MAX_BUFFERS) values.delete(buffers.shift());
    }
    values.set(key, digest);
  };
  const names = new WeakMap(); // WebGLUniformLocation → its name
  const ids = new WeakMap(); // a buffer (WebGL or WebGPU) → a number
  let nextId = 0;
  const idOf = (o) => ids.get(o) ?? (ids.set(o, ++nextId), nextId);
  const rec = {};
  Object.defineProperty(window, '__sent', { value: rec, enumerable: false });
  const digestOf = (v) => {
    if (v === null || v === undefined) return String(v);
    if (typeof v === 'number' || typeof v === 'boolean') return String(v);
    if (ArrayBuffer.isView(v) || Array.isArray(v)) return Array.prototype.slice.call(v, 0, 64).join(',');
    return '?';
  };
  // a large upload is known by its length and 64 of its bytes, evenly spread
  const sampleOf = (src) => {
    const bytes = bytesIn(src);
    if (!bytes) return String(src);
    const step = Math.max(1, Math.floor(bytes.length / 64)), out = [bytes.length];
    for (let k = 0; k < bytes.length; k += step) out.push(bytes[k]);
    return out.join(',');
  };

  const protos = [window.WebGLRenderingContext, window.WebGL2RenderingContext].filter(Boolean).map((c) => c.prototype);
  for (const proto of protos) {
    after(proto, 'getUniformLocation', (gl, [, name], loc) => { if (loc) names.set(loc, String(name)); });
    for (const fn of Object.getOwnPropertyNames(proto).filter((n) => /^uniform(Matrix)?[1-4](u?i|f)v?$|^uniformMatrix[234]x[234]fv$/.test(n))) {
      after(proto, fn, (gl, [loc, ...args]) => {
        if (!loc) return;
        const value = /Matrix/.test(fn) ? args[1] : /v$/.test(fn) ? args[0] : args;
        values.set(`uniform ${names.get(loc) || '?'}`, digestOf(value));
      });
    }
    for (const fn of ['vertexAttrib1f', 'vertexAttrib2f', 'vertexAttrib3f', 'vertexAttrib4f', 'vertexAttrib1fv', 'vertexAttrib2fv', 'vertexAttrib3fv', 'vertexAttrib4fv']) {
      after(proto, fn, (gl, [index, ...args]) => values.set(`attribute ${index}`, digestOf(/v$/.test(fn) ? args[0] : args)));
    }
    const bound = new WeakMap(); // context → the ARRAY_BUFFER bound
    after(proto, 'bindBuffer', (gl, [target, buffer]) => { if (target === gl.ARRAY_BUFFER) bound.set(gl, buffer); });
    after(proto, 'bufferData', (gl, [target, src]) => {
      const b = target === gl.ARRAY_BUFFER && bound.get(gl);
      if (b && typeof src !== 'number') setBuffer(`buffer ${idOf(b)}`, sampleOf(src));
    });
    after(proto, 'bufferSubData', (gl, [target, at, src]) => {
      const b = target === gl.ARRAY_BUFFER && bound.get(gl);
      if (b) setBuffer(`buffer ${idOf(b)} at ${at}`, sampleOf(src));
    });
  }

  if (window.GPUDevice && window.GPUQueue) {
    const UNIFORM = 0x40, VERTEX = 0x20;
    const kinds = new WeakMap(); // GPUBuffer → 'uniform' | 'vertex'
    after(GPUDevice.prototype, 'createBuffer', (device, [desc], buffer) => {
      if (desc && desc.usage & UNIFORM) kinds.set(buffer, 'uniform');
      else if (desc && desc.usage & VERTEX) kinds.set(buffer, 'vertex');
    });
    after(GPUQueue.prototype, 'writeBuffer', (queue, [buffer, at, data, dataOffset, size]) => {
      const kind = kinds.get(buffer), bytes = kind && bytesIn(data, dataOffset, size);
      if (!bytes) return;
      if (kind === 'vertex') { setBuffer(`buffer ${idOf(buffer)} at ${at}`, sampleOf(bytes)); return; }
      // a uniform buffer, 16 bytes at a time (a vec4, or a matrix's column)
      const id = idOf(buffer);
      for (let k = 0; k < bytes.length; k += 16) values.set(`uniform buffer ${id} at ${at + k}`, bytes.subarray(k, k + 16).join(','));
    });
  }

  /** Every key's digest as it was last sent. */
  rec.read = () => Object.fromEntries(values);
}
