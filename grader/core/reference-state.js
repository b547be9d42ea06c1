// Our reference part beside a student's: at the student's canvas size, lit from the light the judge
// fitted to the student's picture. The query our page would be opened with, the scene it would
// show, that scene rendered exactly, and what report.json says of it. Pure: the grader (in Node)
// and the check page (in the student's browser) draw the same reference.
import { nearPointLight } from './measure/point-light.js';
import { fmt } from './format.js';
import { readParams } from '../../common/params.js';
import { cameraOf, describeScene } from '../../common/scene.js';
import { EYE_DISTANCE } from '../../common/course.js';
import { renderReference, toRGBA8 } from '../../common/exact-render.js';
import { renderMeshInOrder } from '../../common/mesh-render.js';
import { sphereMesh, MAX_LEVEL } from '../../common/sphere.js';
import { STEPS, paramNames } from '../../common/steps.js';

/** Our step for `part` (common/steps.js), or null. */
const stepOf = (part) => (Object.hasOwn(STEPS, part) ? STEPS[part] : null);

/**
 * The level of our sphere with as many triangles as the page sent at its judged level (numbers.geometry,
 * from its calls: 4·4^level), as { level }; {} where its mesh is not one of ours.
 */
export function meshLevel(numbers) {
  const triangles = numbers && numbers.geometry ? numbers.geometry.triangles : null;
  for (let level = 0; level <= MAX_LEVEL; level++) if (triangles === 4 * 4 ** level) return { level };
  return {};
}

/**
 * Our reference's light, as the judge fitted the student's (P3–P5): the fitted direction toward the
 * light is in view space, and our page at angle 0 has view = world (eye on +z), so a directional
 * light shines along −l; a near point light with 1/r² sits at d·l (our sphere is a unit sphere,
 * as the fit's).
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

/**
 * The query our part is opened with: the student's canvas size, no orbit, the fitted light, for a
 * step drawn in order (WP04P1) the level of the page's own mesh, and the rubric's own extras.
 */
export function referenceQuery({ width, height }, numbers, thresholds, extra = {}, part = null) {
  const fitted = referenceLight(numbers, thresholds);
  const step = stepOf(part);
  return new URLSearchParams({
    api: 'webgl2',
    size: width,
    height,
    orbit: 0,
    ...(fitted.light ? { angle: 0 } : {}),
    ...fitted,
    ...(step && step.inOrder ? meshLevel(numbers) : {}),
    ...extra,
  });
}

/**
 * The window.scene our page for `part` publishes when opened with `query` (a URLSearchParams or
 * its string): its parameters (common/steps.js) read and clamped (common/params.js), the same fields
 * (common/scene.js), the eye at (r sin α, 0, r cos α) as the orbiting steps put it. null for a
 * part we have no step for.
 */
export function referenceScene(part, query) {
  const step = stepOf(part);
  if (!step) return null;
  const { values } = readParams(paramNames(step), `?${query}`, { shading: step.rmse });
  const camera = cameraOf(values, values.size / (values.height ?? values.size));
  if ('angle' in values) {
    camera.eye[0] = EYE_DISTANCE * Math.sin(values.angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(values.angle);
  }
  const scene = describeScene({ exercise: part, api: values.api, level: 0, camera, shading: step.shading }, values);
  return { scene, width: values.size, height: values.height ?? values.size };
}

/**
 * Our reference for `part` beside the judged picture: the exact render of the scene our page
 * shows for `query` (common/exact-render.js: the unit sphere hit per pixel centre, the slide's
 * formula evaluated there; our pages agree with it within tests/browser/bounds.js's tolerances),
 * or, for a step drawn with neither the depth test nor culling (WP04P1), our mesh at the query's
 * level drawn in order, as the browser draws it (common/mesh-render.js).
 * The same in the grader and on the check page, in any browser or none. { img, scene, why }: img
 * null where nothing comparable is drawn, `why` then says so.
 */
export function referencePicture(part, query, judged) {
  const made = referenceScene(part, query);
  if (!made) return { img: null, scene: null, why: `we have no step ${part} to draw beside it` };
  const { scene, width, height } = made;
  if (width !== judged.width || height !== judged.height) {
    return { img: null, scene, why: `our ${part} draws ${width}×${height} for this canvas, not ${judged.width}×${judged.height}: not compared` };
  }
  const ref = stepOf(part).inOrder
    ? renderMeshInOrder(scene, sphereMesh(scene.level), width, height) : renderReference(scene, width, height);
  return { img: { width, height, data: toRGBA8(ref) }, scene, why: null };
}

/**
 * The state our reference was drawn at, for report.json: its light (and where it came from); no
 * level where the sphere is exact, else the level of the mesh drawn in order (`scene`'s).
 */
export function referenceStateOf(query, scene = null) {
  const q = Object.fromEntries(query.entries());
  const inOrder = scene && stepOf(scene.exercise) && stepOf(scene.exercise).inOrder;
  return {
    level: inOrder ? scene.level : null,
    levelFrom: inOrder
      ? `our mesh drawn in order with no depth test, as our ${scene.exercise} draws it, at ${q.level !== undefined ? 'the level of the page\'s own mesh (the triangles it sent)' : 'our page\'s own level for this size'}`
      : 'none: the exact sphere, the slide\'s formula evaluated at each pixel (no mesh)',
    light: q.light ? { kind: q.light, xyz: [q.lx, q.ly, q.lz].map(Number) } : null,
    lightFrom: q.light ? 'the light direction (or near point light) the judge fitted to the judged picture, in our view at angle 0' : 'none (no lit step)',
    query: query.toString(),
  };
}
