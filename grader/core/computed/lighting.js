// The lighting read on the page's own surface: the judged picture's pixels with the normal,
// position and w_o the page drew them with (computed/surface.js), the slide's model and its known
// misreadings fitted there (measure/surface-fit.js). Null where no surface was read (a step that
// lights nothing, an older artifact); { why } where it was read but cannot be used for this picture.
import { surfaceOf, insideShare } from './surface.js';
import { surfaceFit } from '../measure/surface-fit.js';
import { memo } from './memo.js';

/** The fit on a surface and a picture, made once: the surface-fit unit and the highlight's place read the judged view's. */
const fitOnce = memo(surfaceFit);
import { pct } from '../format.js';

/**
 * The page's surface (`surface`, as the artifact keeps it) as the picture `view` ({ img, an }) shows
 * it: computed/surface.js's samples, or { why } where it is not that picture's view (another size,
 * or too few of its pixels inside the picture's outline).
 */
export function surfaceSeen(images, view, thresholds, surface) {
  const s = surfaceOf(surface, images, thresholds);
  if (s.why) return { why: s.why };
  const { img, an } = view;
  if (s.width !== img.width || s.height !== img.height) return { why: `the page's surface (${s.width}×${s.height}) is not the picture's size (${img.width}×${img.height})` };
  // the surface is the picture's: its pixels lie inside the sphere's outline (the view did not move between them)
  const inside = insideShare(s, img, an);
  if (inside < thresholds.surfaceMatch) return { why: `the page's surface, drawn again by the grader, is not its picture: ${pct(inside)} of it lies inside the picture's outline (the view moved between them, or the page draws with something the grader's copy leaves out, such as instancing or a second program's draw)` };
  return s;
}

/**
 * The fits on the judged picture (`judged`: { img, an }) and its surface (facts.surface, or the
 * `surface` read with another picture: the highlight's place view's), or null / { why }.
 */
export function exactLighting(facts, images, judged, thresholds, surface = facts.surface) {
  if (!surface) return null;
  const s = surfaceSeen(images, judged, thresholds, surface);
  if (s.why) return s;
  const fit = fitOnce(s, judged.img, thresholds);
  return fit.why ? fit : { ...fit, camera: s.camera, normal: s.normal };
}
