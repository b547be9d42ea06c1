#!/usr/bin/env node
// npm run thumbnails: the front page's picture of each step, the step's own render. Each step is
// opened in Chromium (WebGL 2, orbit stopped, the THUMBNAIL query below), its canvas captured as
// a PNG into the step's folder (WP04P1/thumbnail.png, ...). With --check nothing is written: the
// renders are compared with the PNGs there, exit code 1 if one differs (a step drew something
// new: run the command again, look at the pictures, commit them).
import { existsSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import { canvasScreenshot, startServer } from './browser.js';
import { launchChromium } from '../grader/node/run/chromium.js';
import { isMainScript, parseOptions, progressLine, runCommand } from './cli.js';
import { readPNG } from './reference/png.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const STEPS = ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5'];
/** The view every thumbnail shows: small, WebGL 2, the orbit stopped (a step's pixels are then deterministic). */
export const THUMBNAIL = 'api=webgl2&size=160&orbit=0';
export const thumbnailPath = (step) => path.join(repo, step, 'thumbnail.png');

const HELP = `usage: npm run thumbnails [-- --check]
Draws each step (${STEPS.join(', ')}) at ?${THUMBNAIL} in Chromium and writes its canvas to
<step>/thumbnail.png, the pictures on the front page.
  --check   write nothing: compare the renders with the PNGs there; exit 1 if one differs
  --help    this text
exit codes: 0 done (or all current), 1 failed (or a picture differs), 2 bad usage`;

/** Largest difference of one channel between two RGBA pictures (0..255), or Infinity if their sizes differ. */
export function maxDifference(a, b) {
  if (a.width !== b.width || a.height !== b.height) return Infinity;
  let max = 0;
  for (let k = 0; k < a.data.length; k++) max = Math.max(max, Math.abs(a.data[k] - b.data[k]));
  return max;
}

/** Each step's render at THUMBNAIL, as PNG bytes: { WP04P1: Buffer, ... }. `page` is a Playwright page, `base` the site's URL. */
export async function renderThumbnails(page, base, progress = () => {}) {
  const out = {};
  for (const step of STEPS) {
    progress(`drawing ${step}`);
    await page.goto(`${base}/${step}/?${THUMBNAIL}`);
    await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
    out[step] = await canvasScreenshot(page);
  }
  return out;
}

async function thumbnails(opt) {
  const progress = progressLine('thumbnails');
  const server = await startServer();
  const browser = await launchChromium();
  try {
    const page = await browser.newPage({ viewport: { width: 800, height: 700 }, deviceScaleFactor: 1 });
    const shots = await renderThumbnails(page, server.url, progress);
    let differ = 0;
    for (const [step, png] of Object.entries(shots)) {
      const file = thumbnailPath(step);
      if (opt.check) {
        const d = existsSync(file) ? maxDifference(PNG.sync.read(png), readPNG(file)) : Infinity;
        if (d > 2) { differ++; console.error(`thumbnails: ${path.relative(repo, file)} ${d === Infinity ? 'is missing or another size' : `differs from the step's render (by up to ${d}/255)`}`); }
      } else {
        writeFileSync(file, png);
      }
    }
    process.stderr.write('\n');
    console.log(opt.check ? (differ ? `${differ} thumbnail(s) out of date: run npm run thumbnails` : 'thumbnails: all current')
      : `thumbnails: wrote ${STEPS.map((s) => `${s}/thumbnail.png`).join(', ')}`);
    return differ ? 1 : 0;
  } finally {
    await browser.close();
    server.stop();
  }
}

if (isMainScript(import.meta.url)) {
  runCommand({ name: 'thumbnails', help: HELP, readOptions: (argv) => parseOptions(argv, { check: { type: 'boolean' } }), run: thumbnails });
}
