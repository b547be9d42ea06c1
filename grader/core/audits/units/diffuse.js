// The audit unit 'diffuse' (Brightness follows max(n·w_i, 0)·kd·Le + ambient): Fits the slide's
// diffuse term with a light direction to the judged picture and to the lit views along the orbit.
import { nearPointLight } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  diffuse: { title: 'Brightness follows max(n·w_i, 0)·kd·Le + ambient', slide: SLIDE.diffuse, failureTitle: 'The brightness does not follow max(n·w_i, 0)·kd·Le + ambient', description: 'Fits the slide\'s diffuse term with a light direction to the judged picture and to the lit views along the orbit.', reads: ['images.judged', 'facts.shadingImage', 'facts.views'] },
};

/** The diffuse fit of the judged view (`shading`: evidence.shadingOf), with the lit views' sparse fits (`lit`). */
export function auditDiffuse({ thresholds, must, sayAs, numbers }, shading, lit) {
  const say = sayAs('diffuse');
  if (!must.has('diffuse') && !must.has('highlight')) return;
  const { fit, pointLight } = shading;
  if (pointLight) numbers.pointLight = pointLight;
  numbers.fit = fit && {
    r2: fit.r2,
    ambient: fit.ambient,
    diffuse: fit.diffuse,
    light: fit.light,
    highlightPeak: fit.highlightPeak,
    highlightRise: fit.highlightRise,
    spread: fit.spread,
  };
  const orbitFits = lit.filter((v) => v.orbiting).map((v) => v.fit);
  // lit on both sides shows where the light comes from the side: any view seen on the orbit (or
  // over all pixels: a crescent lit from behind is left out of the first fit as if a highlight; on
  // a page lit one-sided, |n·w_i| never explains all pixels better, it lights the dark side)
  const twoSided = [fit, ...lit.map((v) => v.fit)]
    .filter(Boolean)
    .find(
      (f) =>
        (f.r2TwoSided > f.r2 + thresholds.twoSidedGain && f.r2 < thresholds.twoSidedBelow) ||
        (f.r2TwoSidedAll > f.r2All + thresholds.twoSidedGainAll && f.r2TwoSidedAll >= thresholds.diffuseR2),
    );
  if (fit && fit.tint && fit.tint.added) say('pass', `note: the colour is the lighting with WP04P1's normal colouring added (about ${fmt(fit.tint.added, 2)}·n, read from how the channels differ: each follows one component of the normal, the lighting is the same in all three): the lighting is judged with it taken out`);
  if (!fit) say('mistake', 'too little of the sphere to read its shading');
  else if (fit.spread < thresholds.evenSpread) say('mistake', `the sphere is evenly bright: no diffuse shading to see (in ${1 + lit.length} views${orbitFits.length ? ' along the orbit' : ''})`);
  else if (twoSided) {
    say('mistake', `the sphere is lit on both sides: brightness follows |n·w_i| (R² ${fmt(twoSided.r2TwoSided)}), not max(n·w_i, 0) (R² ${fmt(twoSided.r2)})`);
  } else if (!must.has('highlight') && orbitFits.length && Math.min(...orbitFits.map((f) => f.r2)) < thresholds.orbitDiffuseR2) {
    const worst = orbitFits.reduce((a, b) => (b.r2 < a.r2 ? b : a));
    say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient at every orbit position (R² down to ${fmt(worst.r2)}): lit where it should be dark?`);
  } else if (fit.r2 >= thresholds.diffuseR2 && fit.diffuse >= thresholds.diffuseMin) {
    say('pass', `brightness follows max(n·w_i, 0)·kd·Le + ambient (R² ${fmt(fit.r2)}, fitted light ${fit.light.map((v) => fmt(v)).join(', ')})`);
  } else if (nearPointLight(pointLight, thresholds) && fit.diffuse >= thresholds.diffuseMin) {
    const f = pointLight[nearPointLight(pointLight, thresholds)];
    say('pass', `brightness follows max(n·w_i, 0)·kd·L_i + ambient for a point light ${fmt(f.distance, 1)} radii from the centre (R² ${fmt(f.r2)})`);
  } else say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient for any light direction (R² ${fmt(fit.r2)})`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'diffuse',
  (context, { shading, 'lit-views': lit }) => (shading.shaded ? auditDiffuse(context, shading.shading, lit) : null),
  { uses: ['shading', 'lit-views'] });
