// Our reference part drawn beside a student's: at the student's canvas size, lit from the light
// the judge fitted to the student's picture. Plain data: the query for our page and what
// report.json says of the state it was drawn at.
import { nearPointLight } from './measure/point-light.js';
import { fmt } from './format.js';
import { FRAME_MS, MS_PER_SECOND } from './units.js';

/** A real wait between looks at our own reference page: our page, never a bound on a student's. */
const LOOK_MS = 100;

/**
 * Our reference's light, as the judge fitted the student's (P3–P5): the fitted direction toward the
 * light is in view space, and our page at angle 0 has view = world (eye on +z), so a directional
 * light shines along −l; a near point light with 1/r² sits at d·l (our sphere is a unit sphere,
 * as the fit's). The level stays ours for the canvas size: a student's own level is not known.
 */
export function referenceLight(numbers, thresholds) {
  const fit = numbers && numbers.fit;
  if (!fit || !fit.light) return {};
  const pl = numbers.pointLight;
  const xyz = (v) => ({ lx: fmt(v[0], 3), ly: fmt(v[1], 3), lz: fmt(v[2], 3) });
  if (pl && nearPointLight(pl, thresholds) === 'falloff') {
    return { light: 'point', ...xyz(pl.falloff.light.map((v) => v * pl.falloff.distance)) };
  }
  return { light: 'directional', ...xyz(fit.light.map((v) => -v)) };
}

/** The query our part is opened with: the student's canvas size, no orbit, the fitted light, and the rubric's own extras. */
export function referenceQuery({ width, height }, numbers, thresholds, extra = {}) {
  const fitted = referenceLight(numbers, thresholds);
  return new URLSearchParams({
    api: 'webgl2',
    size: width,
    height,
    orbit: 0,
    ...(fitted.light ? { angle: 0 } : {}),
    ...fitted,
    ...extra,
  });
}

/** The state our reference was drawn at, for report.json: its light (and where it came from) and level. */
export function referenceStateOf(query, scene) {
  const q = Object.fromEntries(query.entries());
  return {
    level: scene && Number.isFinite(scene.level) ? scene.level : null,
    levelFrom: 'ours: the least level that looks round and shades within tolerance at this canvas size (the student\'s level is not known)',
    light: q.light ? { kind: q.light, xyz: [q.lx, q.ly, q.lz].map(Number) } : null,
    lightFrom: q.light ? 'the light direction (or near point light) the judge fitted to the judged picture, in our view at angle 0' : 'none (no lit step)',
    query: query.toString(),
  };
}

/** How long our reference runs before its picture is taken: the jump, then frames at 60 Hz (our own page, not a bound on a student's). */
const SETTLE = { ms: 500, frames: 30 };

/**
 * Waits until our reference shows a drawn frame (`shows()`: our pages publish window.scene after each
 * frame), a frame of frozen time at a time, within `seconds` of the wall clock: a loaded machine
 * takes longer to fetch our shaders, and a picture taken before the first frame is blank. Our page,
 * not a bound on a student's. Returns whether it shows one.
 */
export async function untilDrawn(shows, driver, seconds) {
  for (const until = Date.now() + MS_PER_SECOND * seconds; !(await shows()) && Date.now() < until;) {
    await new Promise((resolve) => setTimeout(resolve, LOOK_MS));
    await driver.tick(FRAME_MS);
  }
  return shows();
}

/**
 * Our reference's picture, drawn as the grader and the check page both draw it (opened by the
 * caller with referenceQuery's settings, through the page interface `driver`): run SETTLE, wait for
 * `drawn` (the check page polls our page's window.scene there), then read back. { img, why }: img
 * null where nothing comparable was drawn, `why` then says so where it is worth a note.
 */
export async function referencePicture(driver, judged, drawn = async () => true) {
  await driver.tick(SETTLE.ms, SETTLE.frames);
  if (!(await drawn())) return { img: null, why: null };
  const img = await driver.snap();
  if (img && (img.width !== judged.width || img.height !== judged.height)) {
    return { img: null, why: `our reference drew ${img.width}×${img.height}, not ${judged.width}×${judged.height}: not compared` };
  }
  return { img: img || null, why: null };
}
