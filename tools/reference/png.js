// The reference as a picture: 8-bit RGBA as a canvas stores it, and PNG files in and out.
import { readFileSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { toRGBA8 } from '../../common/exact-render.js';

export { toRGBA8 };

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
