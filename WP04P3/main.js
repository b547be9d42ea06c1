// WP04P3: Gouraud shading. Diffuse light per vertex from a directional or point light fixed in
// world space; a tick() loop orbits the camera around the sphere.
import { lookAt, mat4, perspective } from '../common/math.js';
import { MAX_LEVEL, chooseLevel, sphereMesh } from '../common/sphere.js';
import { loadShaders, programFrom } from '../common/shaders.js';
import { checkbox, createContext, onClick, onContextLoss, publishScene, readParams, run, select, setSlider, slider, writeParams } from '../common/page.js';

// The course's clear colour (the slides' render pass): cornflower blue.
const BACKGROUND = [0.3921, 0.5843, 0.9294, 1.0];
// The camera orbits the unit sphere at radius r in the xz-plane.
const EYE_DISTANCE = 3, FOVY = 45;
// Which of chooseLevel's measured shading errors this step has: Gouraud, diffuse only
const SHADING = 'diffuse';
const ORBIT_SPEED = (2 * Math.PI) / 12; // radians per second: one orbit in 12 s
// Where each kind of light starts: a directional light's xyz is the direction it shines in (l_e);
// a point light's is its position.
const LIGHT_DEFAULTS = { directional: [0, 0, -1], point: [0, 0, 2] };

async function main() {
  // URL state: every parameter can be set in the query string; bad values are fixed and reported.
  const { values: state } = readParams({
    api: { type: 'enum', values: ['webgl2', 'webgl'], default: 'webgl2' },
    size: { type: 'int', min: 16, max: 2048, default: 512 },
    height: { type: 'int', min: 16, max: 2048, default: (v) => v.size },
    near: { type: 'number', min: 0.01, max: 100, default: 0.1 },
    far: { type: 'number', min: 0.02, max: 1000, default: 10 },
    // Model no more than the scene needs: by default the least level that looks round at this size
    level: { type: 'int', min: 0, max: MAX_LEVEL, default: (v) => chooseLevel(v.height, FOVY, EYE_DISTANCE, { shading: SHADING }).level },
    orbit: { type: 'bool', default: true },
    angle: { type: 'number', min: -1e6, max: 1e6, default: 0 },
    light: { type: 'enum', values: ['directional', 'point'], default: 'directional' },
    lx: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][0] },
    ly: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][1] },
    lz: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][2] },
    kd: { type: 'number', min: 0, max: 1, default: 0.8 },
    Le: { type: 'number', min: 0, max: 1e12, default: 1 }, // a far point light needs a large intensity
  });
  state.angle = wrapAngle(state.angle);
  state.far = Math.max(state.far, state.near * 1.01);

  // Context and shaders (fetched once)
  const canvas = document.getElementById('gl-canvas');
  canvas.width = state.size;
  canvas.height = state.height;
  const { gl, api } = createContext(canvas, state.api);
  const shaders = await loadShaders('shader.vert', 'shader.frag');

  // Camera: e = (r sin α, 0, r cos α), looking at the centre
  const camera = { eye: [0, 0, EYE_DISTANCE], at: [0, 0, 0], up: [0, 1, 0], fovy: FOVY, aspect: canvas.width / canvas.height, near: state.near, far: state.far };
  const P = perspective(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = mat4();

  // Light and material, as uploaded and published
  const light = { position: [0, 0, 0, 0], Le: 1 };
  const material = { kd: 1 };

  // GL set-up: the program, its locations, the one vertex buffer and the uniforms. It runs once;
  // again only if the browser restores a lost context.
  let uV, uLightPos, uKd, uLe;
  let numVertices = 0;
  function initGL() {
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(...BACKGROUND);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.CULL_FACE);
    const program = programFrom(gl, shaders);
    gl.useProgram(program);
    const aPosition = gl.getAttribLocation(program, 'aPosition');
    uV = gl.getUniformLocation(program, 'V');
    uLightPos = gl.getUniformLocation(program, 'lightPos');
    uKd = gl.getUniformLocation(program, 'kd');
    uLe = gl.getUniformLocation(program, 'Le');
    gl.uniformMatrix4fv(gl.getUniformLocation(program, 'P'), false, P);
    const vBuffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vBuffer);
    gl.vertexAttribPointer(aPosition, 3, gl.FLOAT, false, 0, 0);
    gl.enableVertexAttribArray(aPosition);
    setLight();
    initSphere(state.level);
  }
  // Light and material uniforms, uploaded when a control changes them
  function setLight() {
    light.position[0] = state.lx;
    light.position[1] = state.ly;
    light.position[2] = state.lz;
    light.position[3] = state.light === 'point' ? 1 : 0; // homogeneous: w = 1 a point, w = 0 a direction
    light.Le = state.Le;
    material.kd = state.kd;
    gl.uniform4fv(uLightPos, light.position);
    gl.uniform3f(uLe, state.Le, state.Le, state.Le);
    gl.uniform3f(uKd, state.kd, state.kd, state.kd);
  }
  // A level change refills the one buffer (slide "Replacing an object")
  function initSphere(level) {
    const positions = sphereMesh(level);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    numVertices = positions.length / 3;
  }
  initGL();
  onContextLoss(canvas, () => { initGL(); changed(); });

  // What the page publishes after each frame (window.scene, the page contract)
  const scene = { exercise: 'WP04P3', api, level: 0, vertices: 0, frame: 0, camera, light, material,
    shading: 'gouraud', depthTest: true, cullFace: true, frontFace: 'ccw', orbit: false, angle: 0 };

  // Controls
  const info = document.getElementById('info');
  const autoLevel = chooseLevel(state.height, FOVY, EYE_DISTANCE, { shading: SHADING }).level;
  const subdivide = document.getElementById('subdivide');
  const coarsen = document.getElementById('coarsen');
  function setLevel(level) {
    state.level = level;
    initSphere(level);
    subdivide.disabled = level >= MAX_LEVEL;
    coarsen.disabled = level <= 0;
    info.value = `level ${level} · ${numVertices.toLocaleString('en')} vertices` +
      (level === autoLevel ? ` (the least level that looks round at ${state.height} px and shades within 1/255)` : '');
    changed();
  }
  onClick('subdivide', () => setLevel(Math.min(state.level + 1, MAX_LEVEL)));
  onClick('coarsen', () => setLevel(Math.max(state.level - 1, 0)));
  checkbox('orbit', state.orbit, (on) => { state.orbit = on; changed(); });
  const remembered = { ...LIGHT_DEFAULTS, [state.light]: [state.lx, state.ly, state.lz] };
  select('light', state.light, (kind) => {
    remembered[state.light] = [state.lx, state.ly, state.lz];
    state.light = kind;
    [state.lx, state.ly, state.lz] = remembered[kind];
    for (const axis of ['lx', 'ly', 'lz']) setSlider(axis, state[axis]);
    setLight();
    changed();
  });
  for (const name of ['lx', 'ly', 'lz', 'kd', 'Le']) {
    slider(name, state[name], (v) => { state[name] = v; setLight(); changed(); });
  }

  // ---- set-up ends here; drawing: one requestAnimationFrame chain, running while orbiting ----
  let pending = false;
  let lastTime = null;
  function changed() {
    writeParams(state);
    if (!pending) {
      pending = true;
      requestAnimationFrame(tick);
    }
  }
  function tick(time) {
    pending = false;
    if (state.orbit && lastTime !== null) {
      state.angle = wrapAngle(state.angle + (ORBIT_SPEED * (time - lastTime)) / 1000);
    }
    lastTime = state.orbit ? time : null;
    render();
    if (state.orbit) {
      pending = true;
      requestAnimationFrame(tick);
    }
  }
  function render() {
    if (gl.isContextLost()) return;
    // e = (r sin α, 0, r cos α); V = lookAt(e, at, up)
    camera.eye[0] = EYE_DISTANCE * Math.sin(state.angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(state.angle);
    gl.uniformMatrix4fv(uV, false, lookAt(camera.eye, camera.at, camera.up, V));
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLES, 0, numVertices);
    scene.level = state.level;
    scene.vertices = numVertices;
    scene.orbit = state.orbit;
    scene.angle = state.angle;
    scene.frame++;
    publishScene(scene);
  }
  setLevel(state.level);
}

/** An angle in [0, 2π). */
function wrapAngle(a) {
  const t = a % (2 * Math.PI);
  return t < 0 ? t + 2 * Math.PI : t;
}

run(main);
