// The audit unit 'diffuse' (Brightness follows max(n·w_i, 0)·kd·Le + ambient): Reads the judged
// view's diffuse term on the page's own surface where the slide's model explains it there, else
// fits it with a light direction to the judged picture; the lit views along the orbit on their pictures.
import { nearPointLight } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  diffuse: { title: 'Brightness follows max(n·w_i, 0)·kd·Le + ambient', slide: SLIDE.diffuse, failureTitle: 'The brightness does not follow max(n·w_i, 0)·kd·Le + ambient', description: 'Reads the judged view\'s diffuse term on the page\'s own surface where the slide\'s model explains it there (its k_d L_e), else fits it with a light direction to the judged picture; the picture\'s spread (evenly bright) and the lit views along the orbit (lit on both sides, dark where lit) on the pictures.', reads: ['images.judged', 'facts.shadingImage', 'facts.views', 'facts.surface'] },
};

/**
 * The diffuse term on the judged view's own surface (`exact`: the surface-fit unit's fit), where
 * the slide's model explains the picture there: { d: k_d L_e (the channels' mean), rms }; { why }
 * where it cannot be read there; null where no surface was read.
 */
export function diffuseOnSurface({ thresholds }, exact) {
  if (!exact) return null;
  if (exact.why) return { why: exact.why };
  if (exact.best.rms > thresholds.surfaceResidual) return { why: `the slide's model leaves a residual of ${fmt(exact.best.rms, 3)} on the page's own surface` };
  const d = exact.best.coef.reduce((sum, c) => sum + c[1], 0) / exact.best.coef.length;
  return { d, rms: exact.best.rms };
}

/** The diffuse fit of the judged view (`shading`: evidence.shadingOf), with the lit views' sparse fits (`lit`), and the judged view's own surface (`exact`). */
export function auditDiffuse(context, shading, lit, exact = null) {
  const { thresholds, must, sayAs, numbers } = context;
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
  // whether the judged view follows the slide's diffuse term: on its own surface where the slide's
  // model explains it there; the picture's own spread, and the views along the orbit (lit on both
  // sides, or dark where lit) on the pictures
  const surface = diffuseOnSurface(context, exact);
  if (surface) numbers.diffuseOnSurface = surface;
  const read = surface && !surface.why, why = surface && surface.why ? ` (on the pictures: the page's own surface cannot say: ${surface.why})` : '';
  if (!fit) say('mistake', 'too little of the sphere to read its shading');
  else if (fit.spread < thresholds.evenSpread) say('mistake', `the sphere is evenly bright: no diffuse shading to see (in ${1 + lit.length} views${orbitFits.length ? ' along the orbit' : ''})`);
  else if (twoSided) {
    say('mistake', `the sphere is lit on both sides: brightness follows |n·w_i| (R² ${fmt(twoSided.r2TwoSided)}), not max(n·w_i, 0) (R² ${fmt(twoSided.r2)})`);
  } else if (!must.has('highlight') && orbitFits.length && Math.min(...orbitFits.map((f) => f.r2)) < thresholds.orbitDiffuseR2) {
    const worst = orbitFits.reduce((a, b) => (b.r2 < a.r2 ? b : a));
    say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient at every orbit position (R² down to ${fmt(worst.r2)}): lit where it should be dark?`);
  } else if (read) {
    const words = `on the page's own surface (its normals and positions as it drew them), the slide's model explains the picture with a residual of ${fmt(surface.rms, 3)}, k_d L_e ${fmt(surface.d, 2)}`;
    if (surface.d >= thresholds.diffuseMin) say('pass', `brightness follows max(n·w_i, 0)·kd·Le + ambient, read ${words}`);
    else say('mistake', `no diffuse term to see: ${words}, under ${thresholds.diffuseMin}`);
  } else if (fit.r2 >= thresholds.diffuseR2 && fit.diffuse >= thresholds.diffuseMin) {
    say('pass', `brightness follows max(n·w_i, 0)·kd·Le + ambient (R² ${fmt(fit.r2)}, fitted light ${fit.light.map((v) => fmt(v)).join(', ')})${why}`);
  } else if (nearPointLight(pointLight, thresholds) && fit.diffuse >= thresholds.diffuseMin) {
    const f = pointLight[nearPointLight(pointLight, thresholds)];
    say('pass', `brightness follows max(n·w_i, 0)·kd·L_i + ambient for a point light ${fmt(f.distance, 1)} radii from the centre (R² ${fmt(f.r2)})${why}`);
  } else say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient for any light direction (R² ${fmt(fit.r2)})${why}`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'diffuse',
  (context, { shading, 'lit-views': lit, 'surface-fit': exact }) =>
    (shading.shaded ? auditDiffuse(context, shading.shading, lit, exact) : null),
  { uses: ['shading', 'lit-views', 'surface-fit'] });
