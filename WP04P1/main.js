// WP04P1: a solid sphere in perspective; Subdivide / Coarsen refill one recycled vertex buffer.
import { lookAt, perspective } from '../common/math.js';
import { MAX_LEVEL, chooseLevel, sphereMesh } from '../common/sphere.js';
import { loadShaders, programFrom } from '../common/shaders.js';
import { createContext, onClick, onContextLoss, publishScene, readParams, run, writeParams } from '../common/page.js';

// The course's clear colour (the slides' render pass): cornflower blue.
const BACKGROUND = [0.3921, 0.5843, 0.9294, 1.0];
// The camera: a perspective view of the unit sphere from 3 units along the +z axis.
const EYE_DISTANCE = 3, FOVY = 45;

async function main() {
  // URL state: every parameter can be set in the query string; bad values are fixed and reported.
  const { values: state } = readParams({
    api: { type: 'enum', values: ['webgl2', 'webgl'], default: 'webgl2' },
    size: { type: 'int', min: 16, max: 2048, default: 512 },
    // Model no more than the scene needs: by default the least level that looks round at this size
    level: { type: 'int', min: 0, max: MAX_LEVEL, default: (v) => chooseLevel(v.size, FOVY, EYE_DISTANCE).level },
  });

  // Context and shaders (fetched once)
  const canvas = document.getElementById('gl-canvas');
  canvas.width = canvas.height = state.size;
  const { gl, api } = createContext(canvas, state.api);
  const shaders = await loadShaders('shader.vert', 'shader.frag');

  // Camera
  const camera = { eye: [0, 0, EYE_DISTANCE], at: [0, 0, 0], up: [0, 1, 0], fovy: FOVY, aspect: canvas.width / canvas.height, near: 0.1, far: 10 };
  const P = perspective(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = lookAt(camera.eye, camera.at, camera.up);

  // GL set-up: the program, its locations, the one vertex buffer and the uniforms. It runs once;
  // again only if the browser restores a lost context.
  let numVertices = 0;
  function initGL() {
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(...BACKGROUND);
    const program = programFrom(gl, shaders);
    gl.useProgram(program);
    const aPosition = gl.getAttribLocation(program, 'aPosition');
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'P'), false, P);
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'V'), false, V);
    const vBuffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vBuffer);
    gl.vertexAttribPointer(aPosition, 3, gl.FLOAT, false, 0, 0);
    gl.enableVertexAttribArray(aPosition);
    initSphere(state.level);
  }
  // A level change refills the one buffer (slide "Replacing an object")
  function initSphere(level) {
    const positions = sphereMesh(level);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    numVertices = positions.length / 3;
  }
  initGL();
  onContextLoss(canvas, () => { initGL(); render(); });

  // What the page publishes after each frame (window.scene, the page contract)
  const scene = { exercise: 'WP04P1', api, level: 0, vertices: 0, frame: 0, camera, shading: 'normals' };

  // Controls
  const info = document.getElementById('info');
  const autoLevel = chooseLevel(state.size, FOVY, EYE_DISTANCE).level;
  const subdivide = document.getElementById('subdivide');
  const coarsen = document.getElementById('coarsen');
  function setLevel(level) {
    state.level = level;
    initSphere(level);
    subdivide.disabled = level >= MAX_LEVEL;
    coarsen.disabled = level <= 0;
    info.value = `level ${level} · ${numVertices.toLocaleString('en')} vertices` +
      (level === autoLevel ? ` (the least level that looks round at ${state.size} px)` : '');
    writeParams(state);
    render();
  }
  onClick('subdivide', () => setLevel(Math.min(state.level + 1, MAX_LEVEL)));
  onClick('coarsen', () => setLevel(Math.max(state.level - 1, 0)));

  // ---- set-up ends here; drawing (on demand: nothing moves) ----
  function render() {
    if (gl.isContextLost()) return;
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLES, 0, numVertices);
    scene.level = state.level;
    scene.vertices = numVertices;
    scene.frame++;
    publishScene(scene);
  }
  setLevel(state.level);
}

run(main);
