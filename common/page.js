// Page helpers shared by the exercises and the lab: a visible message area (notices and errors,
// never a blank page), the WebGL context and its loss, and the address bar that follows the view.
// Nothing here knows about a particular exercise.
import { queryString } from './params.js';

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

/**
 * Shows an error (the page cannot go on), with an optional listing under it (`err.details`) and an
 * optional way on (`err.link`: {href, text}).
 */
export function showError(err) {
  const text = err instanceof Error ? err.message : String(err);
  const item = message('error', text, err && err.details);
  if (err && err.link) {
    const a = document.createElement('a');
    a.href = err.link.href;
    a.textContent = err.link.text;
    item.append(' ', a);
  }
  return item;
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

let pendingParams = null;

/**
 * Puts the current values into the address bar, so a copied link reproduces the view. Written at
 * most every 100 ms: browsers throttle (or refuse) hundreds of history changes in a row.
 */
export function writeQuery(values) {
  if (pendingParams) return;
  pendingParams = setTimeout(() => {
    pendingParams = null;
    history.replaceState(null, '', `${location.pathname}?${queryString(values)}`);
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
 * Antialiasing is off unless asked for, so each pixel shows what its centre sees, as the exact
 * reference renders it.
 * @returns {{gl: WebGLRenderingContext|WebGL2RenderingContext, api: 'webgl2'|'webgl'}}
 */
export function createContext(canvas, api, { antialias = false } = {}) {
  const attributes = { antialias };
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
