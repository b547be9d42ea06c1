// The page interface in Debian's Firefox ESR (firefox.js: puppeteer-core over WebDriver
// BiDi, WebGL on Mesa's llvmpipe): a part opened as playwright-page.js opens one in Chromium, with
// the same init scripts (grader/browser/instrument.js, then clock.js at the same frozen start) and
// the same serving rules (serve-submission.js's submissionAnswers: only the submission's files,
// stand-ins said, other hosts blocked and listed), driven by the same pageDriver. This Firefox has
// no WebGPU, so there is no WebGPU capture: a WebGPU part is not graded here (audits/first-frame.js).
import { gradedPageScripts } from './graded-page-scripts.js';
import { submissionAnswers, urlOf } from './serve-submission.js';
import { pageDriver } from './playwright-page.js';

/**
 * Whether a "page error" Firefox reports is its own notice about the document, not an error of the
 * page's scripts: its HTML parser's word on a document that declares no character encoding (Chromium
 * says nothing of it, and the check page's frames never see it), so that it never becomes a reason.
 */
export const isEngineNotice = (message) => /^The character encoding of the (HTML |plain text )?document was not declared/.test(String(message));

/**
 * Opens the parts a worker grades, one after another, in `browser` (a puppeteer Browser of Firefox):
 * each part in a browser context of its own (its storage apart from the others'), at an origin of
 * its own (`http://p<n>.<host>`), with time frozen anew. The same shape as playwright-page.js's
 * partOpener: open({ root, rel, query, loadSeconds, log }) → { page, driver, why }; done(clean).
 */
export function firefoxOpener(browser, host) {
  let n = 0;
  let context = null;
  const drop = async () => {
    const c = context;
    context = null;
    if (c) await c.close().catch(() => {});
  };
  return {
    async open({ root, rel, query = '', loadSeconds, log }) {
      await drop();
      context = await browser.createBrowserContext();
      const page = await context.newPage();
      await page.setViewport({ width: 1000, height: 1000, deviceScaleFactor: 1 });
      const site = { root, origin: `http://p${++n}.${host}`, log };
      const answer = submissionAnswers(site);
      await page.setRequestInterception(true);
      page.on('request', (request) => {
        if (request.isInterceptResolutionHandled()) return;
        // (a data: or blob: URL is the page's own bytes: Chromium's routing never sees one)
        if (/^(data|blob):/.test(request.url())) return request.continue().catch(() => {});
        const a = answer(request.url(), request.isNavigationRequest());
        (a.abort ? request.abort('blockedbyclient') : request.respond(a)).catch(() => {});
      });
      // a popup is listed with where it went (its requests refused: nothing but the grader's serving
      // reaches out), then closed; a popup that asked for nothing in 200 ms is listed by its address then
      page.on('popup', async (popup) => {
        if (!popup) return;
        let first = null;
        try {
          await popup.setRequestInterception(true);
          popup.on('request', (r) => { first ??= r.url(); r.abort('blockedbyclient').catch(() => {}); });
          await new Promise((resolve) => setTimeout(resolve, 200));
        } catch { /* (closed meanwhile) */ }
        log.blocked.push(`popup: ${first || popup.url()}`);
        popup.close().catch(() => {});
      });
      page.on('pageerror', (e) => { if (!isEngineNotice(e.message)) log.errors.push(`page error: ${e.message}`); });
      page.on('console', (m) => { if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) log.errors.push(`console: ${m.text()}`); });
      page.on('dialog', (d) => {
        log.errors.push(`dialog: ${d.message()}`);
        d.dismiss().catch(() => {});
      });
      for (const script of gradedPageScripts({ webgpu: false })) await page.evaluateOnNewDocument(script);
      const url = urlOf(site.origin, root, rel, query).href;
      let response;
      try {
        response = await page.goto(url, { waitUntil: 'load', timeout: loadSeconds * 1000 });
      } catch (err) {
        if (!/Timeout|timed out/i.test(err.message)) throw err;
        await drop(); // (a page whose script never returns is not kept)
        return { page, why: `it did not finish loading in ${loadSeconds} s (a script that never returns?)` };
      }
      if (!response || !response.ok()) return { page, why: `the page answered ${response ? response.status() : 'nothing'}` };
      return { page, driver: pageDriver(page, log) };
    },
    /** The part is over: its context goes with it. */
    async done() {
      await drop();
    },
  };
}
