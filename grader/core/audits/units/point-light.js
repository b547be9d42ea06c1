// The audit unit 'point-light' (A point light with the 1/r² fall-off): Fits a near light with and
// without 1/r² where the step asks for a point light.
import { clearlyBetter } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'point-light': { title: 'A point light with the 1/r² fall-off', slide: SLIDE.pointLight, failureTitle: 'Not a point light with the 1/r² fall-off', description: 'Fits a near light with and without 1/r² where the step asks for a point light.', reads: ['images.judged'] },
};

/** A point light: with the 1/r² fall-off, or clearly without it. */
export function auditPointLight({ thresholds, sayAs }, shading) {
  const say = sayAs('point-light');
  const { pointLight } = shading;
  if (!pointLight) return;
  if (clearlyBetter(pointLight, 'none', 'falloff', thresholds)) {
    say('review', `point light without the 1/r² fall-off: brightness fits a light ${fmt(pointLight.none.distance, 1)} radii from the centre with no fall-off (R² ${fmt(pointLight.none.r2, 3)}) better than with L_i = I/‖p_ℓ − x‖² (R² ${fmt(pointLight.falloff.r2, 3)})`);
  } else if (clearlyBetter(pointLight, 'falloff', 'none', thresholds)) {
    say('pass', `a point light ${fmt(pointLight.falloff.distance, 1)} radii from the centre, with the 1/r² fall-off (R² ${fmt(pointLight.falloff.r2, 3)}; without it ${fmt(pointLight.none.r2, 3)})`);
  }
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'point-light',
  (context, { shading }) => (shading.shaded ? auditPointLight(context, shading.shading) : null), { uses: ['shading'] });
