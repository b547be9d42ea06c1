// The page interface the grading core drives (grader/core/gather/), on a Playwright page: open a
// part with time frozen and the grader's instrumentation in, then click, step a slider, press a
// key, let frames run, capture. The driver (pageDriver) works on puppeteer's page too, which
// firefox-page.js opens in Firefox ESR. The check page has its own implementation of the same
// interface for a part in an iframe; the core knows none of them.
import { inflateSync } from 'node:zlib';
import { LRUCache } from 'lru-cache';
import { decodePng } from './png.js';
import { gradedPageScripts } from './graded-page-scripts.js';
import { serveSubmission, urlOf } from './serve-submission.js';
import { FRAME_MS } from '../../core/units.js';
import { shownClip } from '../../core/measure/shown.js';

// the pictures a part's driver remembers by their bytes (in ../shared/handins, 135 of 497 snaps
// repeat an earlier one of the same part: 129 one of the last two, 132 one of the last four)
const SNAPS_KEPT = 4;

/**
 * Opens the parts a worker grades, one after another, in one browser context and page: each part
 * is a new document at an origin of its own (`http://p<n>.<host>`: its storage apart from the
 * others', the site and so the renderer process the same), served from its own folder, with time
 * frozen anew. A new context and page cost 0.5–1 s a part on this machine. `host`: e.g.
 * 'submission.localhost'.
 * open({ root, rel, query, loadSeconds, log }) → { page, driver, why }: `why` says why the page
 * could not be opened (then there is no driver); `log` ({ errors, blocked, notes }) gets what the
 * page prints or is refused.
 * done(clean): the part is over; a part that did not end cleanly (the grader threw, or the page did
 * not finish loading) takes the context with it, and the next part gets a new one.
 * The page before is left for an empty one first (a student's page may hold on, or run its frames
 * once more).
 */
export function partOpener(browser, host, { skipUnseen = false } = {}) {
  let kept = null; // { context, page, site }
  let n = 0;
  const keep = async () => {
    const site = { root: null, origin: null, log: { errors: [], blocked: [], notes: [] }, former: new Set() };
    const context = await browser.newContext({ viewport: { width: 1000, height: 1000 }, deviceScaleFactor: 1 });
    await serveSubmission(context, site);
    for (const script of gradedPageScripts({ webgpu: true, skipUnseen })) await context.addInitScript(script);
    const page = await context.newPage();
    page.on('popup', (popup) => {
      site.log.blocked.push(`popup: ${popup.url()}`);
      popup.close().catch(() => {});
    });
    page.on('pageerror', (e) => site.log.errors.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) site.log.errors.push(`console: ${m.text()}`); });
    // (leaving a part's page for the next one: a beforeunload prompt lets it go)
    page.on('dialog', (d) => {
      if (d.type() === 'beforeunload') return d.accept().catch(() => {});
      site.log.errors.push(`dialog: ${d.message()}`);
      return d.dismiss().catch(() => {});
    });
    return { context, page, site };
  };
  const serve = (site, root, log) => {
    if (site.origin) site.former.add(site.origin);
    Object.assign(site, { root, origin: `http://p${++n}.${host}`, log });
  };
  const leave = async ({ page, site }) => {
    serve(site, null, site.log);
    return page.goto(`${site.origin}/`, { timeout: 10_000 }).then(() => true, () => false);
  };
  const drop = async () => {
    if (!kept) return;
    const { context } = kept;
    kept = null;
    await context.close().catch(() => {});
  };
  return {
    async open({ root, rel, query = '', loadSeconds, log }) {
      // the part before is left for an empty page first (its frames would run once as time is frozen
      // anew); a page that crashed, was closed or will not let go takes the context with it (its goto fails)
      if (kept && !await leave(kept)) await drop();
      kept ??= await keep();
      const { page, site } = kept;
      serve(site, root, log);
      const url = urlOf(site.origin, root, rel, query).href;
      let response;
      try {
        response = await page.goto(url, { waitUntil: 'load', timeout: loadSeconds * 1000 });
      } catch (err) {
        if (!/Timeout/i.test(err.message)) throw err;
        await drop(); // (a page whose script never returns is not kept)
        return { page, why: `it did not finish loading in ${loadSeconds} s (a script that never returns?)` };
      }
      if (!response || !response.ok()) return { page, why: `the page answered ${response ? response.status() : 'nothing'}` };
      // (no wait for the network to go quiet: drive.js waits for the first draw call, which comes after
      // any shaders or models a page fetches)
      const driver = { ...pageDriver(page, log), shown: () => shownChannels(page), unseen: () => unseenFrames(page) };
      return { page, driver };
    },
    async done(clean) {
      if (!clean) await drop();
    },
  };
}

/** The frames' draws left undone so far ({ skipped, unsafe }: grader/browser/unseen-frames.js), or null. */
const unseenFrames = (page) =>
  page.evaluate(() => {
    const u = window.__grade && window.__grade.unseen;
    return u && u.on ? { skipped: u.skipped, unsafe: u.unsafe } : null;
  });

/**
 * A picture's two channels: the canvas as the page reads it back (its alpha kept), and as the
 * browser shows it, a screenshot of the canvas's box in view taken from outside the page (the
 * protocol, not the page's own functions): { raw, shown, box, clip } in the page's CSS pixels, or
 * { why } where there is nothing to compare.
 */
async function shownChannels(page) {
  const r = await page.evaluate(async () => {
    if (window.__webgpuCapture) await window.__webgpuCapture.settled();
    return window.__grade.readBack ? window.__grade.readBack() : null;
  });
  if (!r) return { why: 'no canvas read back' };
  const { box, view } = r;
  const { clip, why } = shownClip(box, view);
  if (why) return { why };
  const png = await page.screenshot({ clip, animations: 'disabled', caret: 'hide', timeout: 10_000 });
  return { raw: decodePng(r.png), shown: decodePng(png), box, clip };
}

/**
 * The page interface over a page whose instrumentation (instrument.js) is in: a Playwright page,
 * or a puppeteer page (Firefox: firefox-page.js), which share what is used here (evaluate(fn, arg)
 * and keyboard.press(key)).
 */
export function pageDriver(page, log) {
  // the last pictures snapped, by their bytes: a picture snapped again unchanged (after a control
  // that changed nothing, of a stopped orbit) is the same picture, and what was measured of it
  // (core/computed/memo.js) is not measured again
  const snapped = new LRUCache({ max: SNAPS_KEPT });
  const driver = {
    /** What the instrumentation saw: the API, WebGPU frames, the adapter, draw calls, shader and GPU errors. */
    state: () => page.evaluate(() => window.__grade.state()),
    /** The canvas as { width, height, api, data } (RGBA bytes), after the last WebGPU frame is copied; or null. */
    async snap() {
      // (one call to the page: each costs the grader milliseconds of its own)
      const r = await page.evaluate(async () => {
        if (window.__webgpuCapture) await window.__webgpuCapture.settled();
        return window.__grade.pixels('png');
      });
      if (!r) return null;
      const key = `${r.api}|${r.png}`;
      let img = snapped.get(key);
      // (the picture keeps the browser's PNG bytes: the artifact writes them as they are, png.js)
      if (!img) snapped.set(key, (img = Object.assign(decodePng(r.png), { api: r.api })));
      return img;
    },
    controls: () => page.evaluate(() => window.__grade.controls()),
    /** The page's canvases: { index, width, height, shown, labels } (grader/browser/canvases.js). */
    canvases: () => page.evaluate(() => window.__grade.canvases()),
    /** The canvas read from now on where it is among the largest (null: the largest, the first of equals). */
    chooseCanvas: (index) => page.evaluate((i) => window.__grade.chooseCanvas(i), index),
    /** Clicks a control as a user would (window.__grade.click: the check page clicks the same way); { ok, why }. */
    click: (c) => page.evaluate((i) => window.__grade.click(i), c.index),
    setValue: (c, value, events) =>
      page.evaluate(([i, v, ev]) => window.__grade.setValue(i, v, ev), [c.index, value, events]),
    /** A key pressed and released, sent where the page listens (the focused element, else the body). */
    press: (key) => page.keyboard.press(key),
    /**
     * Lets `ms` of frozen time pass (grader/browser/clock.js): a jump (due timers and one animation
     * frame fire once), then `frames` frames at 60 Hz; the last WebGPU frame's copy awaited. Returns
     * state() as the frames left it, in the same call to the page.
     */
    tick: (ms, frames = 2) => page.evaluate(async ([jump, run]) => {
      if (jump > 0) await window.__checkClock.fastForward(jump);
      await window.__checkClock.runFor(run);
      if (window.__webgpuCapture) await window.__webgpuCapture.settled();
      return window.__grade.state();
    }, [ms > FRAME_MS * frames + FRAME_MS / 2 ? ms - FRAME_MS * frames : 0, Math.min(ms, FRAME_MS * frames)]),
    /** The grader's experiment: WebGL draws with back-face culling off (true) or as the page set it (false). */
    setNoCull: (on) => page.evaluate((v) => { window.__grade.noCull = v; }, on),
    sources: () => page.evaluate(() => ({ glsl: window.__grade.glsl, wgsl: window.__grade.wgsl })),
    /** The grader's hooks the page replaced (grader/browser/tamper.js), by name. */
    tampered: () => page.evaluate(() => (window.__tamper ? window.__tamper.read() : [])),
    /** What the page tried that would have closed or left it, kept open instead (grader/browser/stay.js). */
    stayed: () => page.evaluate(() => (window.__stay ? window.__stay.read() : [])),
    /** What the page last sent for its shaders, a digest a key (grader/browser/sent.js): uniforms, constant attributes, vertex buffers. */
    sent: () => page.evaluate(() => (window.__sent ? window.__sent.read() : null)),
    /** The geometry of the last frame drawn, summed up (grader/browser/geometry.js): triangles, winding, closed, per-face attributes. */
    geometry: (limits) => page.evaluate((l) => (window.__geometry ? window.__geometry.read(l) : { why: 'the geometry was not recorded' }), limits),
    /**
     * The surface the last frame drew, per pixel (grader/browser/surface.js): its two pictures as
     * { width, height, data }. They leave the page deflated (the browser's CompressionStream: mostly
     * background, a tenth of the bytes or less, lossless), else as they are; the whole as one JSON
     * string (handed over as values, its fit's ten thousand numbers cost the grader 60-70 ms a call).
     */
    surface: async (opts) => {
      const r = JSON.parse(await page.evaluate(async (o) => {
        if (!window.__geometry || !window.__geometry.surface) return JSON.stringify({ why: 'the geometry was not recorded' });
        const s = await window.__geometry.surface(o);
        if (s.why) return JSON.stringify(s);
        const base64 = (bytes) => {
          let text = '';
          for (let i = 0; i < bytes.length; i += 0x8000) {
            text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
          }
          return btoa(text);
        };
        const packed = async (bytes) => {
          try {
            const stream = new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate'));
            return { deflated: base64(new Uint8Array(await new Response(stream).arrayBuffer())) };
          } catch {
            return { raw: base64(bytes) };
          }
        };
        return JSON.stringify({ ...s, normals: await packed(s.normals), points: await packed(s.points) });
      }, opts));
      if (r.why) return r;
      const size = r.width * r.height * 4;
      const image = ({ deflated, raw }) => {
        let bytes;
        try {
          bytes = deflated ? inflateSync(Buffer.from(deflated, 'base64'), { maxOutputLength: size }) : Buffer.from(raw, 'base64');
        } catch {
          return null; // (more than the picture's bytes, or not deflate)
        }
        return bytes.length === size ? { width: r.width, height: r.height, data: new Uint8Array(bytes) } : null;
      };
      const [normals, points] = [image(r.normals), image(r.points)];
      if (!normals || !points) return { why: 'the surface\'s pictures did not come out of the page whole' };
      return { ...r, normals, points };
    },
    errors: () => log.errors,
  };
  return driver;
}
