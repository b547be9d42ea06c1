// The Firefox suite's fixtures: Debian's Firefox ESR (grader/node/run/firefox.js, puppeteer-core over WebDriver
// BiDi), launched once per worker, and a page per test that fixtures.js's helpers (open, scene,
// andDraw, canvasPixels, errorAgainstReference, messages) drive as they drive Chromium's: a
// puppeteer page wearing the few methods of Playwright's that they use. As in Chromium, the page
// counts its WebGL calls (fixtures.js: instrument), and a test fails on any page error, console
// error or gl.getError() other than NO_ERROR.
import { test as base, expect } from '@playwright/test';
import { launchFirefox } from '../../grader/node/run/firefox.js';
import { instrument } from './fixtures.js';

const VIEWPORT = { width: 800, height: 700 };

/** A puppeteer page in the shape of the Playwright page that fixtures.js's helpers expect. */
function playwrightShaped(page, baseURL, api) {
  const locator = (selector) => ({
    first: () => locator(selector),
    evaluate: (fn, arg) => page.$eval(selector, fn, arg),
    innerText: () => page.$eval(selector, (e) => e.innerText),
    allInnerTexts: () => page.$$eval(selector, (es) => es.map((e) => e.innerText)),
    count: () => page.$$eval(selector, (es) => es.length),
    click: () => page.click(selector),
  });
  return {
    api,
    puppeteer: page,
    goto: (url) => page.goto(new URL(url, baseURL).href),
    url: () => page.url(),
    evaluate: (fn, arg) => page.evaluate(fn, arg),
    // Playwright's order is (fn, arg, options), puppeteer's (fn, options, ...args)
    waitForFunction: (fn, arg, options = {}) => page.waitForFunction(fn, { timeout: 30_000, ...options }, arg),
    locator,
    /** Playwright's screenshot({ style, clip }): the style is added for the shot and taken away. */
    async screenshot({ style, clip } = {}) {
      const tag = style ? await page.addStyleTag({ content: style }) : null;
      try {
        return Buffer.from(await page.screenshot({ clip }));
      } finally {
        if (tag) await tag.evaluate((t) => t.remove());
      }
    },
  };
}

export const test = base.extend({
  api: ['webgl2', { option: true }],
  firefox: [async ({}, use) => { // eslint-disable-line no-empty-pattern
    const browser = await launchFirefox();
    await use(browser);
    await browser.close();
  }, { scope: 'worker', timeout: 120_000 }],
  page: async ({ firefox, api, baseURL }, use) => {
    const raw = await firefox.newPage();
    await raw.setViewport(VIEWPORT);
    const problems = [];
    raw.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    raw.on('console', (m) => {
      if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
    });
    await raw.evaluateOnNewDocument(instrument);
    const page = playwrightShaped(raw, baseURL, api);
    page.problems = problems;
    await use(page);
    const glErrors = await raw.evaluate(() => (window.__gl ? window.__gl.errors() : []));
    for (const e of glErrors) problems.push(`gl.getError() = 0x${e.toString(16)}`);
    await raw.close();
    expect(problems, 'page, console and GL errors').toEqual([]);
  },
});
export { expect };
