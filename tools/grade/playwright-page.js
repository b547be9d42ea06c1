// The page interface the grading core drives (drive.js), on a Playwright page: open a part with
// time frozen and the grader's instrumentation in, then click, step a slider, press a key, let
// frames run, capture. The check page has its own implementation of the same interface for a
// part in an iframe; drive.js knows neither.
import { PNG } from 'pngjs';
import { webgpuCaptureScript, readWebGPUFrame } from '../webgpu-capture.js';
import { instrumentScript } from './instrument.js';
import { serveSubmission } from './serve-submission.js';

// the time the page sees: frozen, moving only when the grader lets frames run
const FROZEN = new Date('2026-01-05T09:00:00Z');

/**
 * Opens `rel` (a path inside `root`) at `origin` in a new context of `browser`. `log` ({ errors,
 * blocked, notes }) gets what the page prints or is refused. Returns { context, page, driver, why }:
 * `why` says why the page could not be opened (then there is no driver).
 */
export async function openPart(browser, { root, rel, origin, query = '', loadSeconds = 20, log }) {
  const context = await browser.newContext({ viewport: { width: 1000, height: 1000 }, deviceScaleFactor: 1 });
  await serveSubmission(context, root, origin, log);
  await context.addInitScript(webgpuCaptureScript);
  await context.addInitScript(instrumentScript);
  const page = await context.newPage();
  page.on('popup', (popup) => {
    log.blocked.push(`popup: ${popup.url()}`);
    popup.close().catch(() => {});
  });
  page.on('pageerror', (e) => log.errors.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) log.errors.push(`console: ${m.text()}`); });
  page.on('dialog', (d) => { log.errors.push(`dialog: ${d.message()}`); d.dismiss().catch(() => {}); });
  await page.clock.install({ time: FROZEN });
  await page.clock.pauseAt(new Date(FROZEN.getTime() + 2000)); // from here time moves only when we say so
  const url = `${origin}/${rel.split(/[\\/]/).map(encodeURIComponent).join('/')}${query ? `?${query}` : ''}`;
  let response;
  try {
    response = await page.goto(url, { waitUntil: 'load', timeout: loadSeconds * 1000 });
  } catch (err) {
    if (!/Timeout/i.test(err.message)) throw err;
    return { context, page, why: `it did not finish loading in ${loadSeconds} s (a script that never returns?)` };
  }
  if (!response || !response.ok()) return { context, page, why: `the page answered ${response ? response.status() : 'nothing'}` };
  // (no wait for the network to go quiet: drive.js waits for the first draw call, which comes after
  // any shaders or models a page fetches)
  return { context, page, driver: playwrightDriver(page, log) };
}

/** The page interface over a Playwright page whose instrumentation (instrument.js) is in. */
export function playwrightDriver(page, log) {
  const driver = {
    /** What the instrumentation saw: the API, WebGPU frames, the adapter, draw calls, shader and GPU errors. */
    state: () => page.evaluate(() => window.__grade.state()),
    /** The canvas as { width, height, api, data } (RGBA bytes), after the last WebGPU frame is copied; or null. */
    async snap() {
      await readWebGPUFrame(page);
      const r = await page.evaluate(() => window.__grade.pixels('png'));
      if (!r) return null;
      const { data } = PNG.sync.read(Buffer.from(r.png.slice(r.png.indexOf(',') + 1), 'base64'));
      return { width: r.width, height: r.height, api: r.api, data: new Uint8Array(data.buffer, data.byteOffset, data.length) };
    },
    controls: () => page.evaluate(() => window.__grade.controls()),
    /** Clicks a control as a user would (window.__grade.click: the check page clicks the same way); { ok, why }. */
    click: (c) => page.evaluate((i) => window.__grade.click(i), c.index),
    setValue: (c, value, events) => page.evaluate(([i, v, ev]) => window.__grade.setValue(i, v, ev), [c.index, value, events]),
    /** A key pressed and released, sent where the page listens (the focused element, else the body). */
    press: (key) => page.keyboard.press(key),
    /** Lets `ms` of frozen time pass: a jump (due timers and one animation frame fire once), then `frames` frames at 60 Hz. */
    async tick(ms, frames = 2) {
      if (ms > 16 * frames + 8) await page.clock.fastForward(ms - 16 * frames);
      await page.clock.runFor(Math.min(ms, 16 * frames));
      await readWebGPUFrame(page);
    },
    /** The grader's experiment: WebGL draws with back-face culling off (true) or as the page set it (false). */
    setNoCull: (on) => page.evaluate((v) => { window.__grade.noCull = v; }, on),
    sources: () => page.evaluate(() => ({ glsl: window.__grade.glsl, wgsl: window.__grade.wgsl })),
    errors: () => log.errors,
  };
  return driver;
}
