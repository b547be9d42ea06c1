// Readings several audits share, as units that say nothing: the shading read once (where the
// step is lit and shows lighting, not the normal colouring), and the lit views kept along the orbit.
import { litView } from '../computed/views.js';
import { shadingOf } from '../computed/evidence.js';
import { unit } from './unit.js';

/**
 * { shaded, shadeImg, shading }: whether the shading is judged (a lit step whose picture is not
 * the normal colouring), the picture it is read in (one that clipped to white read again with the
 * page's own sliders lowered, one too dim with its light raised: gather/visible.js), and its reading.
 */
function readShading({ facts, images, thresholds, litStep }, results) {
  const judged = results['judged-picture'];
  const shaded = litStep && !results['normals-not-light'];
  const shadeImg = facts.shadingImage ? images[facts.shadingImage] : judged.img;
  return { shaded, shadeImg, shading: shaded ? shadingOf(shadeImg, judged.an, thresholds) : null };
}

/** The lit views kept along the orbit, with their sparse fits (where the shading is judged; else none). */
function readLitViews({ facts, images, thresholds }, { shading }) {
  if (!shading.shaded) return [];
  return facts.views
    .map((v) => ({ ...litView(images[v.image], thresholds), orbiting: v.orbiting, image: v.image, camera: v.camera }))
    .filter((v) => v.lit);
}

/** This module's units (audits/list.js runs them in its order). */
export const UNITS = [
  unit({}, 'shading', readShading, { says: [], uses: ['judged-picture', 'normals-not-light'], reads: ['facts.shadingImage'] }),
  unit({}, 'lit-views', readLitViews, { says: [], uses: ['shading'], reads: ['facts.views'] }),
];
