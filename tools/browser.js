// Shared by the command-line tools and the browser tests: a canvas's screenshot on whole pixels,
// and the site's static server on a free loopback port. (Launching a browser: grader/node/run/chromium.js
// and grader/node/run/firefox.js, which the grader owns.)
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import net from 'node:net';
import { fileURLToPath } from 'node:url';

/** A style sheet that pins the canvas to the viewport's top-left corner, on whole pixels, while a
 * screenshot is taken (text above it may leave it at a fractional y, which would add a row). */
export const PIN_CANVAS_PATH = fileURLToPath(new URL('./pin-canvas.css', import.meta.url));
export const PIN_CANVAS = readFileSync(PIN_CANVAS_PATH, 'utf8');

/** A screenshot of a page's canvas, as PNG bytes: exactly canvas.width × canvas.height pixels. */
export async function canvasScreenshot(page) {
  const size = await page.locator('canvas').first().evaluate((c) => ({ width: c.width, height: c.height }));
  return page.screenshot({ style: PIN_CANVAS, clip: { x: 0, y: 0, ...size } });
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
