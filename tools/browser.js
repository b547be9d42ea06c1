// Shared by the command-line tools: the machine's Chromium (grader/node/find-browser.js: Debian's
// on this one) with the flags a machine without a GPU needs, and the site's static server on a free
// loopback port.
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import net from 'node:net';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { findHere } from '../grader/node/find-browser.js';

const FOUND = findHere('chromium');
/** The Chromium (or Chrome, or Edge) to drive, or null when the machine has none (CHROMIUM_MISSING says what to run). */
export const CHROMIUM = FOUND.found ? FOUND.path : null;
/** Why there is no CHROMIUM, with the one command that installs one on this OS (null when there is one). */
export const CHROMIUM_MISSING = FOUND.found ? null : FOUND.message;
/** The one command that installs a Chromium (or Chrome) on this OS. */
export const CHROMIUM_INSTALL = FOUND.install.line;
/** Which rule found CHROMIUM (CHROMIUM_PATH, PATH, the usual install, Playwright's cache). */
export const CHROMIUM_HOW = FOUND.found ? FOUND.how : null;
// (--disable-gpu-compositing: the page is composited on the CPU, not through SwiftShader's GL; the
// canvases still draw with SwiftShader, the screenshots and captures are the same pixels, and each
// frame costs less: foundation and lighting specs 3m11 → 2m34, a class graded 2m57 → 2m35)
export const CHROMIUM_ARGS = [
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--no-first-run', '--disable-quic', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-compositing',
];

/** A style sheet that pins the canvas to the viewport's top-left corner, on whole pixels, while a
 * screenshot is taken (text above it may leave it at a fractional y, which would add a row). */
export const PIN_CANVAS_PATH = fileURLToPath(new URL('./pin-canvas.css', import.meta.url));
export const PIN_CANVAS = readFileSync(PIN_CANVAS_PATH, 'utf8');

/** A screenshot of a page's canvas, as PNG bytes: exactly canvas.width × canvas.height pixels. */
export async function canvasScreenshot(page) {
  const size = await page.locator('canvas').first().evaluate((c) => ({ width: c.width, height: c.height }));
  return page.screenshot({ style: PIN_CANVAS, clip: { x: 0, y: 0, ...size } });
}

/** Launches Chromium, or throws an Error saying how to install it. */
export async function launchChromium(options = {}) {
  if (!CHROMIUM) throw new Error(CHROMIUM_MISSING);
  return chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, ...options });
}

function freePort() {
  return new Promise((resolve, reject) => {
    const srv = net.createServer();
    srv.on('error', reject);
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => resolve(port));
    });
  });
}

/**
 * Starts tools/serve.js on a free port for `root` (default: the repository).
 * @returns {Promise<{url: string, stop: () => void}>}
 */
export async function startServer(root) {
  const port = await freePort();
  const args = [fileURLToPath(new URL('./serve.js', import.meta.url)), '--port', String(port)];
  if (root) args.push('--root', root);
  const child = spawn(process.execPath, args, { stdio: ['ignore', 'pipe', 'inherit'] });
  await new Promise((resolve, reject) => {
    child.on('exit', (code) => reject(new Error(`the static server exited (${code})`)));
    child.stdout.on('data', (chunk) => { if (String(chunk).includes('http://')) resolve(); });
  });
  return { url: `http://127.0.0.1:${port}`, stop: () => child.kill() };
}
