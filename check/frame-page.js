// The grader's page interface (what grader/core/gather/ drives) on a same-origin iframe of the
// check page, as grader/node/run/playwright-page.js is on a Playwright page: state, snap, controls,
// click, setValue, press, tick, setNoCull, sources, errors. The frame's scripts were put in place by
// check/serve.js: window.__grade (grader/browser/instrument.js), window.__webgpuCapture
// (grader/browser/webgpu-capture.js), window.__checkClock (grader/browser/clock.js), window.__checkWatch
// (check/frame-watch.js).
import { FRAME_MS } from '../grader/core/units.js';

/** keydown, keypress (a character), keyup of `key` at the focused element (or the body) of the frame's window `W`. */
function pressKey(W, key) {
  const doc = W.document;
  const active = doc.activeElement;
  const target = active && active !== doc.documentElement ? active : doc.body || doc.documentElement;
  const code = /^[a-z]$/i.test(key) ? `Key${key.toUpperCase()}` : /^[0-9]$/.test(key) ? `Digit${key}` : { '+': 'Equal', '-': 'Minus', ' ': 'Space' }[key] || key;
  const KEY_CODES = { ArrowLeft: 37, ArrowUp: 38, ArrowRight: 39, ArrowDown: 40, PageUp: 33, PageDown: 34,
    '+': 187, '-': 189, ' ': 32, Enter: 13, Escape: 27 };
  const keyCode = KEY_CODES[key] ?? key.toUpperCase().charCodeAt(0);
  const init = { key, code, keyCode, which: keyCode, bubbles: true, cancelable: true, composed: true, view: W };
  target.dispatchEvent(new W.KeyboardEvent('keydown', init));
  const charCode = key.charCodeAt(0);
  const press = { ...init, charCode, keyCode: charCode, which: charCode };
  if (key.length === 1) target.dispatchEvent(new W.KeyboardEvent('keypress', press));
  target.dispatchEvent(new W.KeyboardEvent('keyup', init));
}

/**
 * @param {HTMLIFrameElement} frame a part's frame, loaded
 * @param {{ errors: string[], blocked: string[], notes: string[] }} log what the check page's
 *   server and the frame report (the frame's own errors are read from window.__checkWatch)
 */
export function framePage(frame, log) {
  const win = () => frame.contentWindow;
  const g = () => win().__grade;
  // the watch's record outlives the frame (read after it is removed)
  let record = null;
  const watch = () => (record ??= (frame.contentWindow && frame.contentWindow.__checkWatch) || null)
    || { errors: [], blocked: [], hung: null };
  const plain = (x) => JSON.parse(JSON.stringify(x)); // out of the frame's realm
  /** Waits for the last WebGPU frame's copy to the canvas (grader/browser/webgpu-capture.js). */
  const settle = async () => {
    const s = win().__webgpuCapture;
    if (s) await s.settled();
  };
  /** What the frame's recorder `name` (window.__tamper, __stay, __sent) read, out of the frame's realm; `none` without it. */
  const recorded = (name, none) => {
    const r = win()[name];
    return r ? plain(r.read()) : none;
  };
  const newTask = () => { const w = watch(); if (w.newTask) w.newTask(); }; // check/frame-watch.js's loop guard

  return {
    async state() {
      return plain(g().state());
    },
    async snap() {
      await settle();
      const r = g().pixels();
      return r ? { width: r.width, height: r.height, api: r.api, data: new Uint8Array(r.data) } : null; // (a copy out of the frame's realm)
    },
    async controls() {
      return plain(g().controls());
    },
    /** A click as a user's (window.__grade.click): { ok, why }. */
    async click(c) {
      newTask();
      return plain(g().click(c.index));
    },
    async setValue(c, value, events) {
      newTask();
      g().setValue(c.index, value, events);
    },
    /** keydown, keypress (a character), keyup of `key` at the focused element (or the body). */
    async press(key) {
      newTask();
      pressKey(win(), key);
    },
    /** Frozen time advances: a jump to 16·frames before `ms`, then `frames` frames at 60 Hz; returns state() after them. */
    async tick(ms, frames = 2) {
      const clock = win().__checkClock;
      if (ms > FRAME_MS * frames + FRAME_MS / 2) await clock.fastForward(ms - FRAME_MS * frames);
      await clock.runFor(Math.min(ms, FRAME_MS * frames));
      await settle();
      return plain(g().state());
    },
    /** The grader's experiment: WebGL draws with back-face culling off (true) or as the page set it (false). */
    async setNoCull(on) {
      g().noCull = on;
    },
    /** The grader's hooks the page replaced (grader/browser/tamper.js). */
    tampered: async () => recorded('__tamper', []),
    /** What the page tried that would have closed or left it, kept open instead (grader/browser/stay.js). */
    stayed: async () => recorded('__stay', []),
    /** What the page last sent for its shaders (grader/browser/sent.js). */
    sent: async () => recorded('__sent', null),
    /** The geometry of the last frame drawn, summed up (grader/browser/geometry.js). */
    async geometry(limits) {
      const r = win().__geometry;
      return r ? plain(r.read(limits)) : { why: 'the geometry was not recorded' };
    },
    /** The surface the last frame drew, per pixel (grader/browser/surface.js): its two pictures as { width, height, data }. */
    async surface(opts) {
      return surfaceOut(win().__geometry, opts, plain);
    },
    async sources() {
      return { glsl: [...g().glsl], wgsl: [...g().wgsl] };
    },
    errors() {
      return [...log.errors, ...watch().errors];
    },
    blocked() {
      return [...log.blocked, ...watch().blocked];
    },
    /** The frame ran a loop that never returned (check/frame-watch.js stopped it): why, or null. */
    hung() {
      return watch().hung;
    },
    /** What the self-check's own instrumentation broke in the frame (check/frame-watch.js). */
    broken() {
      return [...(watch().broken || [])];
    },
  };
}

/** The frame's surface reader's answer out of its realm, its two pictures as { width, height, data }. */
async function surfaceOut(r, opts, plain) {
  const s = r && r.surface ? await r.surface(opts) : { why: 'the geometry was not recorded' };
  if (s.why) return plain(s);
  const image = (bytes) => ({ width: s.width, height: s.height, data: new Uint8Array(bytes) });
  return { ...plain({ ...s, normals: null, points: null }), normals: image(s.normals), points: image(s.points) };
}
