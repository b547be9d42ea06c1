// The audit unit 'lit-views', a reading several audits share and that says nothing: the lit views
// kept along the orbit, with their sparse fits.
import { litView } from '../../computed/views.js';
import { unit } from '../unit.js';

/** The lit views kept along the orbit, with their sparse fits (where the shading is judged; else none). */
function readLitViews({ facts, images, thresholds }, { shading }) {
  if (!shading.shaded) return [];
  return facts.views
    .map((v) => ({ ...litView(images[v.image], thresholds), orbiting: v.orbiting, image: v.image, camera: v.camera,
      vertices: v.vertices }))
    .filter((v) => v.lit);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit({}, 'lit-views', readLitViews, { says: [], uses: ['shading'], reads: ['facts.views'] });
