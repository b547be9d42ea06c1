// A picture's two channels: the canvas as the page's own read-back gives it (its alpha kept), and as
// the browser shows it (a screenshot of the canvas's box, taken outside the page). Where the canvas
// is opaque they agree, but for the engine's rounding and the blur of a canvas placed at a fraction
// of a pixel or shown scaled; a canvas or an element laid over it, or a CSS filter on it, shows
// something else than what is read back.
import { CHANNEL_MAX } from '../units.js';

/**
 * Of the shown picture's pixels whose canvas pixel is opaque, how many differ from it by more than
 * `limit` in a channel, with the shown picture read (dx, dy) pixels on: { opaque, differ }. Each
 * shown pixel is matched to the canvas pixel under its centre (`box`: the canvas's picture on the
 * page, `clip`: the screenshot's, both in CSS pixels; `step`: every step-th row and column).
 */
function differing(raw, shown, box, clip, dx, dy, limit, step) {
  const kx = raw.width / box.width, ky = raw.height / box.height;
  let opaque = 0, differ = 0;
  for (let v = 0; v < shown.height; v += step) {
    const ry = Math.floor((clip.y + v + 0.5 + dy - box.y) * ky);
    if (ry < 0 || ry >= raw.height) continue;
    for (let u = 0; u < shown.width; u += step) {
      const rx = Math.floor((clip.x + u + 0.5 + dx - box.x) * kx);
      if (rx < 0 || rx >= raw.width) continue;
      const o = 4 * (ry * raw.width + rx);
      if (raw.data[o + 3] !== CHANNEL_MAX) continue;
      const s = 4 * (v * shown.width + u);
      opaque++;
      if (
        Math.max(
          Math.abs(raw.data[o] - shown.data[s]),
          Math.abs(raw.data[o + 1] - shown.data[s + 1]),
          Math.abs(raw.data[o + 2] - shown.data[s + 2]),
        ) > limit
      ) {
        differ++;
      }
    }
  }
  return { opaque, differ };
}

/**
 * How far the two channels of one picture agree ({ raw, shown, box, clip }: playwright-page.js's
 * shownChannels): { compared: true, opaque, share } (share: of the canvas's opaque pixels in view,
 * those shown otherwise by more than shownPixelDiff in a channel), where they fit best within
 * shownShift pixels; or { compared: false, why }.
 */
export function shownDifference(two, thresholds) {
  if (!two || two.why) return { compared: false, why: two ? two.why : 'not read' };
  const { raw, shown, box, clip } = two;
  // a large picture is read at every other row and column (a quarter of the work; the share alike)
  const step = shown.width * shown.height > thresholds.shownFullPixels ? 2 : 1;
  let best = null;
  // (the first shift that matches every pixel is the best: none after it can do better)
  for (let dy = -thresholds.shownShift; dy <= thresholds.shownShift && !(best && best.differ === 0); dy++) {
    for (let dx = -thresholds.shownShift; dx <= thresholds.shownShift && !(best && best.differ === 0); dx++) {
      const r = differing(raw, shown, box, clip, dx, dy, thresholds.shownPixelDiff, step);
      if (r.opaque && (!best || r.differ / r.opaque < best.differ / best.opaque)) best = r;
    }
  }
  if (!best) return { compared: false, why: 'no opaque pixel of the canvas is in view' };
  return { compared: true, opaque: best.opaque, share: best.differ / best.opaque };
}

/**
 * The screenshot's clip for a canvas whose picture lies at `box` in a viewport `view` (CSS pixels):
 * the box in view, on whole pixels, a pixel more on each side (a canvas at a fractional place);
 * { clip } or { why } (no size, mostly out of view). The command's screenshot and the check page's
 * composite (check/frame-page.js) take the same.
 */
export function shownClip(box, view) {
  if (!(box.width >= 1 && box.height >= 1)) return { why: 'the canvas has no size on the page' };
  const x0 = Math.max(view.x, Math.floor(box.x) - 1), y0 = Math.max(view.y, Math.floor(box.y) - 1);
  const x1 = Math.min(view.x + view.width, Math.ceil(box.x + box.width) + 1),
    y1 = Math.min(view.y + view.height, Math.ceil(box.y + box.height) + 1);
  if (x1 - x0 < box.width / 2 || y1 - y0 < box.height / 2) return { why: 'the canvas is mostly out of view' };
  return { clip: { x: x0, y: y0, width: x1 - x0, height: y1 - y0 } };
}
