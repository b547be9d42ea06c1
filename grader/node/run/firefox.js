// The machine's Firefox (find-browser.js: Debian's Firefox ESR on this one), driven by
// puppeteer-core over WebDriver BiDi (Playwright cannot drive a stock Firefox): how to launch it so
// that headless WebGL works on a machine without a GPU (Mesa's llvmpipe through EGL, in the content
// process). Never downloads a browser.
import { findHere } from './find-browser.js';

const FOUND = findHere('firefox');
/** The Firefox to drive, or null when the machine has none (FIREFOX_MISSING says what to run). */
export const FIREFOX = FOUND.found ? FOUND.path : null;
/** Why there is no FIREFOX, with the one command that installs it on this OS (null when there is one). */
export const FIREFOX_MISSING = FOUND.found ? null : FOUND.message;
/** The one command that installs Firefox on this OS. */
export const FIREFOX_INSTALL = FOUND.install.line;

// Headless Firefox has no compositor GPU: EGL on Mesa's software rasteriser gives it WebGL 1 and 2
const FIREFOX_ENV = { MOZ_WEBGL_FORCE_EGL: '1', LIBGL_ALWAYS_SOFTWARE: '1' };
const FIREFOX_PREFS = {
  'webgl.out-of-process': false, // no GPU process to run WebGL in
  'webgl.force-enabled': true, // llvmpipe is on the blocklist of a GPU-less machine
  'browser.shell.checkDefaultBrowser': false,
  'datareporting.policy.dataSubmissionEnabled': false,
  'app.update.enabled': false,
};

/**
 * Launches Firefox ESR headless over WebDriver BiDi with WebGL enabled, or throws an Error that
 * says how to install it.
 * @param {object} [options] more puppeteer.launch options (env and prefs are merged)
 * @returns {Promise<import('puppeteer-core').Browser>}
 */
export async function launchFirefox(options = {}) {
  if (!FIREFOX) throw new Error(FIREFOX_MISSING);
  const { env, extraPrefsFirefox, ...rest } = options;
  // (loaded here, not at the top: a command that launches no Firefox does not wait for puppeteer)
  const { default: puppeteer } = await import('puppeteer-core');
  return puppeteer.launch({
    browser: 'firefox',
    executablePath: FIREFOX,
    headless: true,
    protocol: 'webDriverBiDi',
    env: { ...process.env, ...FIREFOX_ENV, ...env },
    extraPrefsFirefox: { ...FIREFOX_PREFS, ...extraPrefsFirefox },
    ...rest,
  });
}
