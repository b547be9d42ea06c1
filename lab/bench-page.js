// The browser end of the bench: lab/bench.html loads this module, and tools/bench.js (npm run
// bench) drives it through window.bench, documented below. It draws nothing by itself.
// Methods: flat (one normal per face), diffuse (WP04P3's shaders: Gouraud, diffuse light only),
// gouraud (WP04P4's shaders), phong (WP04P5's shaders),
// impostor (one quad, ray–sphere per fragment), all with the same camera, light and material as
// the exercises' default view. Layouts: the slides' drawArrays, or shared vertices + drawElements.

/**
 * window.bench: published once the programs are compiled, and then window.benchReady = true (a
 * failure shows in #messages as an .error instead). Every call is synchronous. URL parameters of
 * lab/bench.html: size (the canvas's width and height in pixels, default 256), api=webgl for
 * WebGL 1 (default WebGL 2).
 *
 * @typedef {object} Bench
 * @property {'webgl2'|'webgl'} api the context in use
 * @property {string} renderer the GPU's name (UNMASKED_RENDERER_WEBGL where the browser gives it)
 * @property {number} maxLevel the largest subdivision level (MAX_LEVEL of common/sphere.js)
 * @property {boolean} uint32 whether 32-bit indices are available (WebGL 2, or OES_element_index_uint)
 * @property {(level: number, layout?: 'arrays'|'indexed') => {vertices: number, bytes: number, indexBits?: number}} setMesh
 *   builds the sphere at `level` and uploads it: 'arrays' (the default) is sphereMesh for
 *   drawArrays plus the face centroids for flat shading, 'indexed' is lab/meshes.js's
 *   indexedSphere for drawElements. Returns the vertex count, the bytes of positions (and of
 *   indices), and for 'indexed' the index size in bits (16 or 32).
 * @property {(method: 'flat'|'diffuse'|'gouraud'|'phong'|'impostor') => void} setMethod the program to draw with
 * @property {(angle: number) => void} setAngle the orbit angle α in radians: eye = (3 sin α, 0, 3 cos α)
 * @property {(material: {kd?: number, ka?: number, ks?: number, s?: number}) => void} setMaterial
 *   changes some of the material; the shaders take ka = kd, so give ka equal to kd or scene()
 *   will not describe what is drawn
 * @property {(frames: number, warmup?: number) => number[]} frameTimes draws `warmup` frames
 *   (default 3), then `frames` timed ones, each finished by a 1-pixel readPixels; returns ms per frame
 * @property {() => string} capture draws once; returns the whole canvas, RGBA bytes, row 0 at the
 *   top, as base64
 * @property {() => object} scene the view as a page's window.scene gives it (camera, light,
 *   material, model, shading = the method, cullFace, level, canvas), for common/exact-render.js
 * @property {(level: number, repeats: number) => {ours: number[], cold: number[], classic: number[], bound: number[]}} levelChange
 *   times one level change `repeats` times four ways (ours, ours cold, the textbook's classic,
 *   the copy-only bound: see the function); ms per change. Leaves the mesh at `level` in the current layout.
 * @property {(level: number, repeats: number) => number[]} indexedChange times building and
 *   uploading the indexed layout, ms per change; leaves the indexed mesh bound
 * @property {() => number} glError gl.getError(): 0 when nothing went wrong
 */

import { lookAt, mat3, mat4, normalMatrix, perspective } from '../common/math.js';
import { MAX_LEVEL, sphereMesh, vertexBytes } from '../common/sphere.js';
import { loadProgram } from '../common/shaders.js';
import { createContext, run } from '../common/page.js';
import { arriveByClick, arriveCold, classicSphere, settle, faceCentroids, indexedSphere } from './meshes.js';
import { BACKGROUND, EYE_DISTANCE, FOVY } from '../common/course.js';


async function main() {
  const params = new URLSearchParams(location.search);
  const canvas = document.getElementById('gl-canvas');
  canvas.width = canvas.height = Number(params.get('size')) || 256;
  const { gl, api } = createContext(canvas, params.get('api') === 'webgl' ? 'webgl' : 'webgl2');
  gl.viewport(0, 0, canvas.width, canvas.height);
  gl.clearColor(...BACKGROUND);
  gl.enable(gl.DEPTH_TEST);
  gl.enable(gl.CULL_FACE);
  const uint32 = api === 'webgl2' || !!gl.getExtension('OES_element_index_uint');

  const programs = {
    diffuse: await loadProgram(gl, '../WP04P3/shader.vert', '../WP04P3/shader.frag'),
    gouraud: await loadProgram(gl, '../WP04P4/shader.vert', '../WP04P4/shader.frag'),
    phong: await loadProgram(gl, '../WP04P5/shader.vert', '../WP04P5/shader.frag'),
    flat: await loadProgram(gl, 'flat.vert', '../WP04P4/shader.frag'),
    impostor: await loadProgram(gl, 'impostor.vert', 'impostor.frag'),
  };

  const camera = { eye: [0, 0, EYE_DISTANCE], at: [0, 0, 0], up: [0, 1, 0], fovy: FOVY, aspect: 1, near: 0.1, far: 10 };
  const light = { position: [0, 0, -1, 0], Le: 1, La: 0.2 };
  const material = { kd: 0.8, ka: 0.8, ks: 0.5, s: 40 };
  const P = perspective(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = mat4(), N = mat3();

  const positionBuffer = gl.createBuffer();
  const faceBuffer = gl.createBuffer();
  const indexBuffer = gl.createBuffer();
  const quadBuffer = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, quadBuffer);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1, 1]), gl.STATIC_DRAW);
  let faces = new Float32Array(0);

  let method = 'phong', layout = 'arrays', level = 0, count = 0, indexType = gl.UNSIGNED_SHORT;
  let angle = 0;
  const pixel = new Uint8Array(4);

  function setUniforms(program) {
    const u = (name) => gl.getUniformLocation(program, name);
    gl.useProgram(program);
    camera.eye[0] = EYE_DISTANCE * Math.sin(angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(angle);
    lookAt(camera.eye, camera.at, camera.up, V);
    gl.uniformMatrix4fv(u('P'), false, P);
    gl.uniformMatrix4fv(u('V'), false, V);
    gl.uniformMatrix3fv(u('N'), false, normalMatrix(V, N));
    gl.uniform4fv(u('lightPos'), light.position);
    gl.uniform3f(u('kd'), material.kd, material.kd, material.kd);
    gl.uniform3f(u('ks'), material.ks, material.ks, material.ks);
    gl.uniform1f(u('s'), material.s);
    gl.uniform3f(u('Le'), light.Le, light.Le, light.Le);
    gl.uniform3f(u('La'), light.La, light.La, light.La);
    gl.uniform1i(u('blinnPhong'), 0);
    const t = Math.tan((FOVY * Math.PI) / 360);
    gl.uniform2f(u('tanHalf'), t * camera.aspect, t);
  }

  // Bind the attributes of the current method (set-up for a series of timed frames, not timed).
  function prepare() {
    const { program } = programs[method];
    setUniforms(program);
    for (let i = 0; i < 4; i++) gl.disableVertexAttribArray(i);
    if (method === 'impostor') {
      const a = gl.getAttribLocation(program, 'aCorner');
      gl.bindBuffer(gl.ARRAY_BUFFER, quadBuffer);
      gl.vertexAttribPointer(a, 2, gl.FLOAT, false, 0, 0);
      gl.enableVertexAttribArray(a);
      return;
    }
    const a = gl.getAttribLocation(program, 'aPosition');
    gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
    gl.vertexAttribPointer(a, 3, gl.FLOAT, false, 0, 0);
    gl.enableVertexAttribArray(a);
    if (method === 'flat') {
      const f = gl.getAttribLocation(program, 'aFace');
      gl.bindBuffer(gl.ARRAY_BUFFER, faceBuffer);
      gl.vertexAttribPointer(f, 3, gl.FLOAT, false, 0, 0);
      gl.enableVertexAttribArray(f);
    }
  }

  function draw() {
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (method === 'impostor') gl.drawArrays(gl.TRIANGLES, 0, 6);
    else if (layout === 'indexed') gl.drawElements(gl.TRIANGLES, count, indexType, 0);
    else gl.drawArrays(gl.TRIANGLES, 0, count);
  }

  // A 1-pixel read waits for the frame to finish (gl.finish does not block here).
  function sync() {
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  }

  let classicBuffer = null;

  /** @type {Bench} */
  window.bench = {
    api,
    renderer: (() => {
      const ext = gl.getExtension('WEBGL_debug_renderer_info');
      return ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    })(),
    maxLevel: MAX_LEVEL,
    uint32,
    /** Builds the mesh at `lvl` in `how`'s layout and uploads it; returns the bytes uploaded. */
    setMesh(lvl, how = 'arrays') {
      level = lvl;
      layout = how;
      if (how === 'indexed') {
        const { positions, indices } = indexedSphere(lvl);
        gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
        gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
        gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
        indexType = indices instanceof Uint32Array ? gl.UNSIGNED_INT : gl.UNSIGNED_SHORT;
        count = indices.length;
        return { vertices: positions.length / 3, bytes: positions.byteLength + indices.byteLength, indexBits: indices.BYTES_PER_ELEMENT * 8 };
      }
      const positions = sphereMesh(lvl);
      count = positions.length / 3;
      gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
      if (faces.length < positions.length) faces = new Float32Array(positions.length);
      gl.bindBuffer(gl.ARRAY_BUFFER, faceBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, faceCentroids(positions, count, faces).subarray(0, positions.length), gl.STATIC_DRAW);
      return { vertices: count, bytes: vertexBytes(lvl) };
    },
    setMethod(name) { method = name; prepare(); },
    setAngle(a) { angle = a; prepare(); },
    /** Changes the material (the stability run uses one whose highlight never clamps). */
    setMaterial(m) { Object.assign(material, m); prepare(); },
    /** ms per frame for `frames` frames after `warmup`, each frame synchronised by a 1-pixel read. */
    frameTimes(frames, warmup = 3) {
      prepare();
      for (let i = 0; i < warmup; i++) { draw(); sync(); }
      const times = [];
      for (let i = 0; i < frames; i++) {
        const t0 = performance.now();
        draw();
        sync();
        times.push(performance.now() - t0);
      }
      return times;
    },
    /** Draws once and returns the whole canvas, RGBA, row 0 at the top, as base64. */
    capture() {
      prepare();
      draw();
      const w = canvas.width, h = canvas.height;
      const data = new Uint8Array(w * h * 4);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, data);
      const flipped = new Uint8Array(data.length);
      for (let j = 0; j < h; j++) flipped.set(data.subarray((h - 1 - j) * w * 4, (h - j) * w * 4), j * w * 4);
      let text = '';
      for (let i = 0; i < flipped.length; i += 0x8000) text += String.fromCharCode.apply(null, flipped.subarray(i, i + 0x8000));
      return btoa(text);
    },
    /** The scene as the pages publish it, for the reference renderer. */
    scene() {
      // WP04P3 (diffuse) has neither ambient nor specular light
      const diffuse = method === 'diffuse';
      return { camera: JSON.parse(JSON.stringify(camera)), model: 'phong', shading: diffuse ? 'gouraud' : method,
        light: diffuse ? { position: light.position, Le: light.Le } : light, material: diffuse ? { kd: material.kd } : material,
        cullFace: true, level, canvas: { width: canvas.width, height: canvas.height } };
    },
    /**
     * ms for one level change, `repeats` times: ours (a click on Subdivide, first visit included:
     * the level was built ahead in idle time, so the click is one bufferData into the one buffer),
     * cold (the level built on the spot, as a jump to it from the URL), classic (vec4 arrays,
     * flatten, a new buffer each time), bound (the same bytes copied by one flat loop into a
     * reused array + bufferData). Each is synchronised by a 1-pixel read, like a frame.
     */
    async levelChange(lvl, repeats) {
      const ours = [], cold = [], classic = [], bound = [];
      const source = sphereMesh(lvl).slice();
      const target = new Float32Array(source.length);
      const boundBuffer = gl.createBuffer();
      const show = (positions) => {
        gl.bindBuffer(gl.ARRAY_BUFFER, positionBuffer);
        gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
      };
      for (let r = 0; r < repeats; r++) {
        ours.push(await arriveByClick(lvl, show, sync));
        cold.push(await arriveCold(lvl, show, sync));

        await settle();
        let t0 = performance.now();
        const data = classicSphere(lvl);
        if (classicBuffer) gl.deleteBuffer(classicBuffer);
        classicBuffer = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, classicBuffer);
        gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
        sync();
        classic.push(performance.now() - t0);

        await settle();
        t0 = performance.now();
        for (let i = 0; i < source.length; i++) target[i] = source[i];
        gl.bindBuffer(gl.ARRAY_BUFFER, boundBuffer);
        gl.bufferData(gl.ARRAY_BUFFER, target, gl.STATIC_DRAW);
        sync();
        bound.push(performance.now() - t0);
      }
      gl.deleteBuffer(boundBuffer);
      this.setMesh(lvl, layout);
      return { ours, cold, classic, bound };
    },
    /** Times building + uploading the indexed layout. */
    indexedChange(lvl, repeats) {
      const times = [];
      for (let r = 0; r < repeats; r++) {
        const t0 = performance.now();
        this.setMesh(lvl, 'indexed');
        sync();
        times.push(performance.now() - t0);
      }
      return times;
    },
    glError: () => gl.getError(),
  };
  window.benchReady = true;
}

run(main);
