// A picture's PNG bytes, encoded once. A picture the browser handed over as a PNG (the page's
// read-back, a screenshot) keeps those bytes beside its pixels: written as they are, they decode to
// the same pixels, and encoding them again in JavaScript (pngjs) was a tenth of what grading a
// class cost in CPU. A picture made here (a diff, the surface's pictures) is encoded by pngjs.
import { PNG } from 'pngjs';

/**
 * A PNG (bytes, or a data: URL as the page's toDataURL gives it) decoded as { width, height, data },
 * its bytes kept as the picture's `png` (not enumerable: a copy of the picture made by spreading it
 * does not carry them, and is encoded afresh).
 */
export function decodePng(png) {
  const bytes = typeof png === 'string' ? Buffer.from(png.slice(png.indexOf(',') + 1), 'base64') : Buffer.from(png);
  const { width, height, data } = PNG.sync.read(bytes);
  const img = { width, height, data: new Uint8Array(data.buffer, data.byteOffset, data.length) };
  Object.defineProperty(img, 'png', { value: bytes });
  return img;
}

/** `img` ({ width, height, data }) as PNG bytes: its own where it came as a PNG, else encoded (RGB where every pixel is opaque, else RGBA). */
export function pngBytes(img) {
  if (img.png) return img.png;
  const p = new PNG({ width: img.width, height: img.height });
  p.data.set(img.data);
  let opaque = true;
  for (let k = 3; k < img.data.length && opaque; k += 4) opaque = img.data[k] === 255;
  return PNG.sync.write(p, opaque ? { colorType: 2, inputHasAlpha: true } : { colorType: 6 });
}
