// The reference as a picture: 8-bit RGBA as a canvas stores it, and PNG files in and out.
import { readFileSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';

/**
 * The reference as 8-bit RGBA, row 0 at the top, as a canvas stores it: round(v · 255), alpha 255.
 * @returns {Uint8ClampedArray}
 */
export function toRGBA8(ref) {
  const n = ref.width * ref.height;
  const out = new Uint8ClampedArray(4 * n);
  for (let p = 0; p < n; p++) {
    out[4 * p] = Math.round(ref.rgb[3 * p] * 255);
    out[4 * p + 1] = Math.round(ref.rgb[3 * p + 1] * 255);
    out[4 * p + 2] = Math.round(ref.rgb[3 * p + 2] * 255);
    out[4 * p + 3] = 255;
  }
  return out;
}

/** Writes the reference to `path` as an 8-bit RGBA PNG. */
export function writePNG(path, ref) {
  const png = new PNG({ width: ref.width, height: ref.height });
  png.data = Buffer.from(toRGBA8(ref).buffer);
  writeFileSync(path, PNG.sync.write(png));
}

/**
 * Reads a PNG file (a canvas screenshot) as pngjs decodes it.
 * @returns {{width: number, height: number, data: Buffer}} RGBA, row 0 at the top
 * @throws {Error} saying whether the file is missing or is not a PNG
 */
export function readPNG(path) {
  let bytes;
  try {
    bytes = readFileSync(path);
  } catch (err) {
    throw new Error(`cannot read the screenshot ${path}: ${err.code === 'ENOENT' ? 'no such file' : err.message}`, { cause: err });
  }
  try {
    return PNG.sync.read(bytes);
  } catch (err) {
    throw new Error(`the screenshot ${path} is not a PNG: ${err.message}`, { cause: err });
  }
}
