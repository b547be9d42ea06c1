// Debian's Firefox ESR, driven by puppeteer-core over WebDriver BiDi (Playwright cannot drive
// Debian's Firefox): where it is, the one line that installs it, and how to launch it so that
// headless WebGL works on a machine without a GPU (Mesa's llvmpipe through EGL, in the content
// process). Never downloads a browser.
import { existsSync } from 'node:fs';
import puppeteer from 'puppeteer-core';

export const FIREFOX = process.env.FIREFOX_PATH || '/usr/bin/firefox-esr';

/** The line that installs Debian's Firefox ESR (tools/setup.js runs it as root, or prints it). */
export const FIREFOX_INSTALL = 'apt-get update && apt-get install -y firefox-esr';

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
  if (!existsSync(FIREFOX)) {
    throw new Error(`Firefox is missing at ${FIREFOX}: run "sudo ${FIREFOX_INSTALL}" (or set FIREFOX_PATH)`);
  }
  const { env, extraPrefsFirefox, ...rest } = options;
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
