// Page helpers shared by the exercises: URL state (parse, clamp, say what was fixed, follow the
// controls), the WebGL context, a visible message area, window.scene, and control wiring.
// Nothing here knows about a particular exercise.

const box = () => document.getElementById('messages');

function message(kind, text, details) {
  const area = box();
  const item = document.createElement('div');
  item.className = kind;
  item.textContent = text; // text only: nothing from the URL or a log is ever parsed as HTML
  if (details) {
    const pre = document.createElement('pre');
    pre.textContent = details;
    item.append(pre);
  }
  if (area) area.append(item);
  return item;
}

/** Shows a notice (something was adjusted, the page goes on). */
export function notify(text) {
  return message('notice', text);
}

/** Shows an error (the page cannot go on), with an optional listing under it. */
export function showError(err) {
  const text = err instanceof Error ? err.message : String(err);
  return message('error', text, err && err.details);
}

/**
 * Runs an exercise's main(), showing any error it throws or rejects with on the page.
 * Errors thrown later, in event handlers or animation frames, are shown too.
 */
export function run(main) {
  window.addEventListener('error', (e) => showError(e.error || e.message));
  window.addEventListener('unhandledrejection', (e) => showError(e.reason));
  Promise.resolve().then(main).catch(showError);
}

const TRUE = new Set(['1', 'true', 'on', 'yes']);
const FALSE = new Set(['0', 'false', 'off', 'no']);

function parseOne(name, raw, rule) {
  const fix = (why) => ({ value: rule.default, notice: `${name}=${raw} ${why}: using ${name}=${rule.default}.` });
  if (rule.type === 'enum') {
    return rule.values.includes(raw) ? { value: raw } : fix(`is not one of ${rule.values.join(', ')}`);
  }
  if (rule.type === 'bool') {
    const v = raw.toLowerCase();
    if (TRUE.has(v)) return { value: true };
    if (FALSE.has(v)) return { value: false };
    return fix('is not on/off (1 or 0)');
  }
  const x = raw.trim() === '' ? NaN : Number(raw);
  if (!Number.isFinite(x)) return fix('is not a number');
  let value = rule.type === 'int' ? Math.round(x) : x;
  if (value < rule.min) {
    return { value: rule.min, notice: `${name}=${raw} is below the least value ${rule.min}: using ${rule.min}.` };
  }
  if (value > rule.max) {
    return { value: rule.max, notice: `${name}=${raw} is above the largest value ${rule.max}: using ${rule.max}.` };
  }
  if (value !== x) return { value, notice: `${name}=${raw} is not a whole number: using ${value}.` };
  return { value };
}

/**
 * Reads the page's parameters from the query string.
 * @param {Object<string, {type:'int'|'number'|'bool'|'enum', default:*, min?:number, max?:number, values?:string[]}>} spec
 *   a default may be a function of the values read before it, e.g. a level chosen for the canvas size
 * @returns {{values: Object, notices: string[]}} every key of spec gets a valid value; notices say
 *   what was clamped or ignored (they are also shown on the page)
 */
export function readParams(spec, search = location.search) {
  const values = {};
  const notices = [];
  const given = new URLSearchParams(search);
  for (const name of given.keys()) {
    if (!spec[name]) notices.push(`Unknown parameter "${name}" ignored.`);
  }
  // Plain defaults first; a default given as a function of the other values comes after them.
  const names = Object.keys(spec).sort((a, b) =>
    (typeof spec[a].default === 'function') - (typeof spec[b].default === 'function'));
  for (const name of names) {
    const rule = spec[name];
    const fallback = typeof rule.default === 'function' ? rule.default(values) : rule.default;
    values[name] = fallback;
    if (!given.has(name)) continue;
    const { value, notice } = parseOne(name, given.get(name), { ...rule, default: fallback });
    values[name] = value;
    if (notice) notices.push(notice);
  }
  for (const text of notices) notify(text);
  return { values, notices };
}

let pendingParams = null;

/**
 * Puts the current values into the address bar, so a copied link reproduces the view. Written at
 * most every 100 ms: browsers throttle (or refuse) hundreds of history changes in a row.
 */
export function writeParams(values) {
  if (pendingParams) return;
  pendingParams = setTimeout(() => {
    pendingParams = null;
    const query = new URLSearchParams();
    for (const [name, value] of Object.entries(values)) {
      query.set(name, typeof value === 'boolean' ? (value ? '1' : '0') : String(value));
    }
    history.replaceState(null, '', `${location.pathname}?${query}`);
  }, 100);
}

/**
 * Keeps the page going through a lost WebGL context: says so while it is gone, and when the
 * browser restores it calls `restore()`, which must make the program, buffers and uniforms again.
 */
export function onContextLoss(canvas, restore) {
  let notice = null;
  canvas.addEventListener('webglcontextlost', (event) => {
    event.preventDefault(); // ask the browser to restore it
    notice = notify('This page lost its WebGL context (the GPU was reset or is busy elsewhere); ' +
      'it will draw again as soon as the browser restores it.');
  });
  canvas.addEventListener('webglcontextrestored', () => {
    if (notice) notice.remove();
    notice = null;
    Promise.resolve().then(restore).catch(showError);
  });
}

/**
 * Creates the WebGL context asked for: 'webgl2' (falling back to WebGL 1, with a notice) or 'webgl'.
 * Antialiasing is off, so each pixel shows what its centre sees, as the exact reference renders it.
 * @returns {{gl: WebGLRenderingContext|WebGL2RenderingContext, api: 'webgl2'|'webgl'}}
 */
export function createContext(canvas, api) {
  const attributes = { antialias: false };
  if (api === 'webgl2') {
    const gl2 = canvas.getContext('webgl2', attributes);
    if (gl2) return { gl: gl2, api: 'webgl2' };
    notify('WebGL 2 is not available in this browser: using WebGL 1 instead.');
  }
  const gl = canvas.getContext('webgl', attributes);
  if (!gl) {
    throw new Error('This browser cannot create a WebGL context, so nothing can be drawn. ' +
      'Turn on hardware acceleration or try another browser.');
  }
  return { gl, api: 'webgl' };
}

/** Publishes the page's state after a drawn frame (tests, the grader and the bench read it). */
export function publishScene(scene) {
  window.scene = scene;
}

/** Calls `handler` on every click of the button with this id. */
export function onClick(id, handler) {
  document.getElementById(id).addEventListener('click', handler);
}

/** Sets a checkbox and calls `handler(checked)` whenever it changes. */
export function checkbox(id, checked, handler) {
  const input = document.getElementById(id);
  input.checked = checked;
  input.addEventListener('change', () => handler(input.checked));
}

/** Sets a <select> and calls `handler(value)` whenever another option is chosen. */
export function select(id, value, handler) {
  const input = document.getElementById(id);
  input.value = value;
  input.addEventListener('change', () => handler(input.value));
}

/**
 * Sets a range input (and the <output for=id> beside it) and calls `handler(value)` on every
 * `input` event, i.e. continuously while the slider is dragged (slide "Exercise (WP04P4)").
 */
export function slider(id, value, handler) {
  const input = document.getElementById(id);
  const shown = document.querySelector(`output[for="${id}"]`);
  setSlider(id, value);
  input.addEventListener('input', () => {
    const v = Number(input.value);
    if (shown) shown.value = input.value;
    handler(v);
  });
}

/** Moves a slider (and the value shown beside it) without firing its handler. */
export function setSlider(id, value) {
  document.getElementById(id).value = String(value);
  const shown = document.querySelector(`output[for="${id}"]`);
  if (shown) shown.value = String(value);
}
