// The page machinery every step shares, so that a step's main.js holds the lesson only:
// the URL parameters (read, clamped, said, and written back as the controls move), the canvas and
// its WebGL context, the controls, the frame loop (the orbit's clock), the WebGL context's loss
// and restoration, and window.scene, published after every frame (the page contract, DESIGN.md).
//
//   const page = await openStep(STEPS.WP04P1);     // its entry in common/steps.js
//   const { gl, canvas, state, camera } = page;
//   ... set-up ...
//   page.start({ init, setLevel, draw });
//
// A step's WebGPU twin (webgpu.js) opens with openStep(STEPS.WP04P1, { webgpu: true }) and gets
// page.gpu (device, context, format) instead of page.gl; a lost device is its lost context:
// init(gpu) runs again on a new one.
import { EYE_DISTANCE, FOVY, ORBIT_SPEED } from './course.js';
import { makeControls, showLevel, showValue } from './controls.js';
import { requestGPU } from './gpu.js';
import { createContext, notify, onContextLoss, showError, writeQuery } from './page.js';
import { PARAMETERS, defaultOf, readParams, wrapAngle } from './params.js';
import { cameraOf, describeScene } from './scene.js';
import { MAX_LEVEL, chooseLevel } from './sphere.js';
import { paramNames } from './steps.js';

/**
 * Reads the step's parameters from the URL, sizes the canvas and creates its context.
 * @param {object} step the step's entry in common/steps.js
 * @param {string} step.exercise e.g. 'WP04P3'
 * @param {string[]} step.params the parameters it has besides api, size and msaa (common/params.js)
 * @param {'normals'|'gouraud'|'phong'} step.shading as window.scene says it
 * @param {null|'diffuse'|'gouraud'|'phong'} step.rmse which shading errors chooseLevel weighs
 *   (common/sphere.js shadingRmse, at the material's shininess); null: the silhouette alone sets the level
 * @param {object} [how]
 * @param {boolean} [how.webgpu] the step's WebGPU script: a device instead of a WebGL context
 * @returns {Promise<{gl: WebGLRenderingContext|WebGL2RenderingContext|null, gpu: object|null,
 *   api: string, canvas: HTMLCanvasElement, state: Object, camera: Object, scene: Object, start: Function}>}
 */
export async function openStep(step, { webgpu = false } = {}) {
  const { exercise, shading, rmse } = step;
  const { values: state, notices } = readParams(paramNames(step), location.search, { shading: rmse });
  for (const text of notices) notify(text);

  const canvas = document.getElementById('gl-canvas');
  canvas.width = state.size;
  canvas.height = state.height ?? state.size;
  let gl = null, gpu = null, api = 'webgpu';
  if (webgpu) {
    gpu = await requestGPU(canvas);
    reportGPUErrors(gpu.device);
  } else {
    ({ gl, api } = createContext(canvas, state.api === 'webgpu' ? 'webgl2' : state.api, { antialias: Number(state.msaa) > 1 }));
  }
  apiLinks(api);

  // The camera looks at the centre from e = (r sin α, 0, r cos α); a step that orbits moves e
  const camera = cameraOf(state, canvas.width / canvas.height);
  const scene = describeScene({ exercise, api, level: 0, vertices: 0, frame: 0, camera, shading }, state);

  /**
   * Hands the step's GL code to the machinery and draws the first frame.
   * @param {object} lesson
   * @param {(gpu: object) => void|Promise<void>} lesson.init makes the program or pipelines, buffers and state
   *   (again after a lost context or device; WebGPU: on the new device, `gpu`)
   * @param {(level: number) => number} lesson.setLevel fills the one buffer; returns the vertex count
   * @param {() => void} lesson.draw draws one frame from `state`
   */
  async function start({ init, setLevel, draw }) {
    function applyLevel() {
      scene.vertices = setLevel(state.level);
      showNeeds();
    }
    // Model no more than the scene needs: which level this size (and material) needs, beside the
    // level; a hint only, the level stays the one chosen
    function showNeeds() {
      const needs = chooseLevel(canvas.height, FOVY, EYE_DISTANCE, { shading: rmse, shininess: state.s });
      const px = `${canvas.height} px`, material = 's' in state ? `s = ${state.s}` : 'diffuse light';
      let note = '';
      if (state.level === needs.level && needs.limit !== 'max') note = `the least level that looks round at ${px}${rmse ? ' and shades within 1/255' : ''}`;
      else if (rmse && needs.rmse > 1) note = `no level shades s = ${state.s} within 1/255 at ${px}: level ${MAX_LEVEL} is ${needs.rmse.toFixed(1)}/255 off`;
      else if (rmse && state.level < needs.level && needs.limit === 'silhouette') note = `level ${needs.level} is the least that looks round at ${px}`;
      else if (rmse && state.level < needs.level) note = `${material} needs level ${needs.level} at ${px} to shade within 1/255`;
      else if (rmse) note = `level ${needs.level} is enough for ${material} at ${px}`;
      showLevel(state.level, scene.vertices, note);
    }

    // A control changed a value: into the state, the URL, the scene, and a new frame
    const remembered = {}; // per light kind, the light's xyz last used with it
    function onInput(name, value) {
      for (const follower of followers(name)) {
        (remembered[state[name]] ??= {})[follower] = state[follower];
        state[follower] = remembered[value]?.[follower] ?? defaultOf(follower, { ...state, [name]: value });
        showValue(follower, state[follower], PARAMETERS[follower]);
      }
      state[name] = value;
      if (name === 'level') applyLevel();
      if (name === 's') showNeeds();
      changed();
    }
    makeControls(PARAMETERS, state, onInput);

    // Frames: a still step draws at once on a change; an orbiting one in its animation frame
    let pending = false;
    let lastTime = null;
    function changed() {
      writeQuery(state);
      if (!('orbit' in state)) frame();
      else if (!pending) {
        pending = true;
        requestAnimationFrame(tick);
      }
    }
    function tick(time) {
      pending = false;
      if (state.orbit && lastTime !== null) state.angle = wrapAngle(state.angle + (ORBIT_SPEED * (time - lastTime)) / 1000);
      lastTime = state.orbit ? time : null;
      frame();
      if (state.orbit) {
        pending = true;
        requestAnimationFrame(tick);
      }
    }
    function frame() {
      if (gl ? gl.isContextLost() : lost) return;
      describeScene(scene, state);
      draw();
      scene.frame++;
      window.scene = scene;
    }

    let lost = false;
    const restore = async (fresh) => {
      await init(fresh);
      lost = false;
      applyLevel();
      changed();
    };
    await init(gpu);
    applyLevel();
    if (gl) onContextLoss(canvas, restore);
    else watchDevice(gpu.device, canvas, () => { lost = true; }, restore);
    changed();
  }

  return { gl, gpu, api, canvas, state, camera, scene, start };
}

/**
 * A lost WebGPU device (the GPU was reset, or the page destroyed it) is WebGPU's lost context:
 * say so, ask the adapter for a new device, and hand it to `restore`.
 */
function watchDevice(device, canvas, onLost, restore) {
  device.lost.then(async (info) => {
    onLost();
    const notice = notify(`This page lost its WebGPU device (${info.message || info.reason || 'no reason given'}); ` +
      'it is asking for a new one.');
    const gpu = await requestGPU(canvas);
    reportGPUErrors(gpu.device);
    watchDevice(gpu.device, canvas, onLost, restore);
    await restore(gpu);
    notice.remove();
  });
}

/** Links in the page's <nav> to the same view in each API (the address as it is when clicked). */
function apiLinks(current) {
  const nav = document.querySelector('nav');
  if (!nav) return;
  nav.append(' · the same view in ');
  for (const [api, text] of Object.entries(PARAMETERS.api.options)) {
    const a = document.createElement('a');
    a.textContent = text;
    if (api === current) a.setAttribute('aria-current', 'page');
    a.href = '?';
    a.addEventListener('click', () => {
      const query = new URLSearchParams(location.search);
      query.set('api', api);
      a.href = `?${query}`;
    });
    nav.append(a, api === 'webgpu' ? '' : ' · ');
  }
}

/** WebGPU validation errors go to the console as warnings only: show them, as errors. */
function reportGPUErrors(device) {
  device.addEventListener('uncapturederror', (event) => {
    console.error(`WebGPU: ${event.error.message}`);
    showError(new Error(`WebGPU error: ${event.error.message}`));
  });
}

/** The parameters whose value follows `name`'s choice (the light's xyz follows its kind). */
function followers(name) {
  return Object.keys(PARAMETERS).filter((p) => PARAMETERS[p].follows === name);
}
