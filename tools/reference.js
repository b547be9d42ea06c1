#!/usr/bin/env node
// node tools/reference.js: the exact reference of a saved window.scene as a PNG, and optionally its
// comparison with a canvas screenshot. The renderer is common/exact-render.js, the error
// measures tools/reference/measure.js, the PNG files tools/reference/png.js.
import { readFileSync } from 'node:fs';
import { renderReference } from '../common/exact-render.js';
import { compareToReference } from './reference/measure.js';
import { readPNG, writePNG } from './reference/png.js';
import { UsageError, isMainScript, parseOptions, runCommand, wholeNumber } from './cli.js';

const HELP = `usage: node tools/reference.js --scene scene.json [--width N --height N] --out ref.png [--compare shot.png]

Renders the exact picture of a page's window.scene (saved as JSON): the unit sphere ray-cast per
pixel centre in double precision, shaded with the slides' reflection model, written as a PNG.

  --scene FILE       the scene, as JSON (copy(JSON.stringify(window.scene)) in the page's console)
  --width N          the picture's width in pixels (default: scene.canvas.width)
  --height N         the picture's height in pixels (default: scene.canvas.height)
  --out FILE         where to write the PNG (may be left out when --compare is given)
  --compare FILE     a PNG screenshot of the canvas, same size: prints the comparison as JSON
                     (rmse and maxError in units of 0..1, so 1/255 is one 8-bit step)
  --help             this text

exit codes: 0 done, 1 it failed (the message says why), 2 bad usage`;

const OPTIONS = {
  scene: { type: 'string' }, width: { type: 'string' }, height: { type: 'string' },
  out: { type: 'string' }, compare: { type: 'string' },
};

/** The options, checked; throws a UsageError. */
function readOptions(argv) {
  const opt = parseOptions(argv, OPTIONS);
  if (opt.help) return opt;
  if (!opt.scene) throw new UsageError('--scene is required');
  if (!opt.out && !opt.compare) throw new UsageError('give --out, --compare or both');
  for (const name of ['width', 'height']) {
    if (opt[name] !== undefined) opt[name] = wholeNumber(opt[name], `--${name}`, 1, 16384);
  }
  return opt;
}

function readScene(path) {
  let text;
  try {
    text = readFileSync(path, 'utf8');
  } catch (err) {
    throw new Error(`cannot read the scene ${path}: ${err.code === 'ENOENT' ? 'no such file' : err.message}`, { cause: err });
  }
  try {
    return JSON.parse(text);
  } catch (err) {
    throw new Error(`the scene ${path} is not JSON: ${err.message}`, { cause: err });
  }
}

/** Renders (and compares) with the options read; returns the exit code. */
function reference(opt) {
  const scene = readScene(opt.scene);
  const shot = opt.compare ? readPNG(opt.compare) : null;
  const width = opt.width ?? scene?.canvas?.width ?? shot?.width;
  const height = opt.height ?? scene?.canvas?.height ?? shot?.height;
  if (width === undefined || height === undefined) {
    console.error('reference: the scene has no canvas size: give --width and --height');
    return 2;
  }
  const ref = renderReference(scene, width, height);
  if (opt.out) {
    writePNG(opt.out, ref);
    const covered = ref.coverage.reduce((a, v) => a + v, 0);
    console.error(`reference: wrote ${opt.out} (${width}×${height}, the sphere covers ${covered} pixels)`);
  }
  if (shot) console.log(JSON.stringify(compareToReference(shot, ref), null, 2));
  return 0;
}

if (isMainScript(import.meta.url)) runCommand({ name: 'reference', help: HELP, readOptions, run: reference });
