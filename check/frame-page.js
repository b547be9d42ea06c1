// The grader's page interface (what grader/core/gather/ drives) on a same-origin iframe of the
// check page, as grader/node/run/playwright-page.js is on a Playwright page: state, snap, controls,
// click, setValue, press, tick, setNoCull, sources, errors. The frame's scripts were put in place by
// check/serve.js: window.__grade (grader/browser/instrument.js), window.__webgpuCapture
// (grader/browser/webgpu-capture.js), window.__checkClock (grader/browser/clock.js), window.__checkWatch
// (check/frame-watch.js).
import { FRAME_MS } from '../grader/core/units.js';
import { shownClip } from '../grader/core/measure/shown.js';

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
    /** The frame's canvases, and the one read from now on where it is among the largest (grader/browser/canvases.js). */
    canvases: async () => plain(g().canvases()),
    chooseCanvas: async (index) => g().chooseCanvas(index),
    /** The picture's two channels (grader/core/measure/shown.js), as far as a page can see them: see shownInFrame. */
    shown: async () => settle().then(() => shownInFrame(win(), () => g().readBack())),
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

/** A PNG data URL's pixels as { width, height, data } and the decoded image (drawn in the check page's document). */
async function decoded(url) {
  const img = new Image();
  img.src = url;
  await img.decode();
  const c = Object.assign(document.createElement('canvas'), { width: img.naturalWidth, height: img.naturalHeight });
  const ctx = c.getContext('2d', { willReadFrequently: true });
  ctx.drawImage(img, 0, 0);
  const data = new Uint8Array(ctx.getImageData(0, 0, c.width, c.height).data);
  return { img, pixels: { width: c.width, height: c.height, data } };
}

/** A canvas's picture box in the viewport, inside its border (as pixels.js's readBack gives the target's). */
const pictureBox = (c) => {
  const r = c.getBoundingClientRect();
  return { x: r.x + c.clientLeft, y: r.y + c.clientTop, width: c.clientWidth, height: c.clientHeight };
};

/** The canvases of `doc` the browser paints over the canvas whose picture box is `box`, bottom first: [{ c, b (its box) }]. */
function canvasesOver(doc, box) {
  const canvases = [...doc.querySelectorAll('canvas')];
  const same = (b) => b.x === box.x && b.y === box.y && b.width === box.width && b.height === box.height;
  const target = canvases.find((c) => same(pictureBox(c)));
  const over = [];
  for (const c of canvases) {
    const b = pictureBox(c);
    const ix0 = Math.max(b.x, box.x), iy0 = Math.max(b.y, box.y);
    const ix1 = Math.min(b.x + b.width, box.x + box.width), iy1 = Math.min(b.y + b.height, box.y + box.height);
    if (c === target || !target || ix1 <= ix0 || iy1 <= iy0) continue;
    // painted over the page's canvas where both are: before it in the elements at a point of both
    const at = doc.elementsFromPoint((ix0 + ix1) / 2, (iy0 + iy1) / 2);
    if (at.includes(c) && at.indexOf(c) < at.indexOf(target)) over.push({ c, b, depth: at.indexOf(c) });
  }
  return over.sort((p, q) => q.depth - p.depth);
}

/**
 * The picture's two channels in a frame of the check page, which cannot photograph itself as the
 * command's browser is photographed (playwright-page.js's shownChannels): the read-back, and as shown, that picture with every other canvas the browser paints over
 * it drawn on top (a 2D canvas laid over the page's WebGL canvas shows what the page read back does
 * not). An element other than a canvas laid over it, or a CSS filter, is not seen here.
 * `readBack()`: pixels.js's readBack, called where another canvas is there. { raw, shown, box, clip }
 * in the frame's CSS pixels, or { why }.
 */
async function shownInFrame(W, readBack) {
  const alone = 'no other canvas over the page\'s canvas: as far as a page can see, it shows what it reads back';
  if (W.document.querySelectorAll('canvas').length < 2) return { why: alone };
  const rb = readBack();
  if (!rb) return { why: 'no canvas read back' };
  const { box, view } = rb;
  // the clip the command's screenshot takes
  const { clip, why } = shownClip(box, view);
  if (why) return { why };
  const over = canvasesOver(W.document, box);
  if (!over.length) return { why: alone };
  const { img, pixels: raw } = await decoded(rb.png);
  const out = Object.assign(document.createElement('canvas'), { width: clip.width, height: clip.height });
  const ctx = out.getContext('2d', { willReadFrequently: true });
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(img, box.x - clip.x, box.y - clip.y, box.width, box.height);
  for (const { c, b } of over) {
    try {
      ctx.drawImage(c, b.x - clip.x, b.y - clip.y, b.width, b.height);
    } catch {
      // (a canvas that cannot be read, tainted by another site's image: not drawn)
    }
  }
  const data = new Uint8Array(ctx.getImageData(0, 0, clip.width, clip.height).data);
  const shown = { width: clip.width, height: clip.height, data };
  return { raw, shown, box, clip };
}
