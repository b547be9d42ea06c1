// The audit unit 'shading', a reading several audits share and that says nothing: the shading read
// once, where the step is lit and shows lighting, not the normal colouring.
import { shadingOf } from '../../computed/evidence.js';
import { unit } from '../unit.js';

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

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit({}, 'shading', readShading, { says: [], uses: ['judged-picture', 'normals-not-light'], reads: ['facts.shadingImage'] });
