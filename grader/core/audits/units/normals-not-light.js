// The audit unit 'normals-not-light' (A lit step shows lighting, not the normal colouring of
// WP04P1): Tells WP04P1's colours (0.5·n + 0.5) from shading in a step that should be lit.
import { samples, normalColours, addedTintFit, addedClearly } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { smoothUnitNormals } from '../normals.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'normals-not-light': { title: 'A lit step shows lighting, not the normal colouring of WP04P1', slide: SLIDE.gouraud, failureTitle: 'A lit step that shows the normal colouring, not lighting', description: 'Tells WP04P1\'s colours (0.5·n + 0.5) from shading in a step that should be lit; where the page\'s own surface shows the lighting beside the colour (the colour in the material), it is lighting.', reads: ['images.judged'] },
};

/**
 * P3–P5: a lit step whose colours still decode to unit normals everywhere (WP04P1's 0.5·n + 0.5,
 * which a diffuse fit accepts: its brightness is linear in n, and it turns with the orbit) shows no
 * lighting, unless the lighting is added on top (0.5·p + 0.5·L_o decodes to unit normals where L_o
 * is near 1): then the channels show a light common to all three beside the normal colouring
 * (addedClearly), and the shading is judged with the colouring taken out; or where the fit on the
 * page's own surface (`exact`, the surface-fit unit's) finds the lighting beside the colour. Returns
 * true when it says the picture is no lighting (the shading is then not judged as lighting).
 */
export function auditNormalsNotLight({ thresholds, must, sayAs, numbers }, judged, exact = null) {
  const say = sayAs('normals-not-light');
  if (!must.has('diffuse') && !must.has('highlight')) return false;
  const pts = samples(judged.img, judged.an, thresholds);
  const nc = normalColours(pts, thresholds);
  if (!smoothUnitNormals(nc, thresholds) || Math.abs(nc.det) < thresholds.facingDeterminant) return false;
  if (addedClearly(addedTintFit(pts, thresholds), thresholds)) return false;
  // the page's own surface shows the lighting beside the normal colour (the colour alone leaves a
  // visible residual that the lighting halves: the colour kept in the material, the page's choice)
  if (exact && !exact.why && exact.lit) return false;
  numbers.normalColouring = nc;
  say('mistake', `shows the normal colouring of WP04P1, not the lighting: its colours decode to unit normals 2c − 1 all over the sphere (off by ${fmt(nc.unitError, 3)}), which is 0.5·n + 0.5, not kd·Le·max(n·w_i, 0) + ambient`);
  return true;
}

/** The unit (audits/list.js runs it in its order). */
// a lit step that shows WP04P1's colours has no shading to judge (true then): its colours are not lighting
export const UNIT = unit(META, 'normals-not-light',
  (context, results) => context.litStep && auditNormalsNotLight(context, results['judged-picture'], results['surface-fit']),
  { uses: ['judged-picture', 'surface-fit'] });
