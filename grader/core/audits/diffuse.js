// WP04P3: the diffuse term, brightness = max(n·w_i, 0)·kd·Le + ambient for a fitted light, in the
// judged view and in every lit view along the orbit; a point light and its 1/r² fall-off.
import { nearPointLight, clearlyBetter } from '../measure.js';
import { fmt } from '../format.js';
import { SLIDE } from './slides.js';
import { unit } from './unit.js';
import { PERCENT } from '../units.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  diffuse: { title: 'Brightness follows max(n·w_i, 0)·kd·Le + ambient', slide: SLIDE.diffuse, failureTitle: 'The brightness does not follow max(n·w_i, 0)·kd·Le + ambient', description: 'Fits the slide\'s diffuse term with a light direction to the judged picture and to the lit views along the orbit.', reads: ['images.judged', 'facts.shadingImage', 'facts.views'] },
  'point-light': { title: 'A point light with the 1/r² fall-off', slide: SLIDE.pointLight, failureTitle: 'Not a point light with the 1/r² fall-off', description: 'Fits a near light with and without 1/r² where the step asks for a point light.', reads: ['images.judged'] },
  unclipped: { title: 'A picture clipped to white, read with the sliders lowered', slide: SLIDE.diffuse, failureTitle: 'The picture clipped to white', description: 'Where the picture saturates, lowers the page\'s own sliders and reads the shading there; the note says so.', reads: ['facts.unclipped'] },
  brightened: { title: 'A picture too dim, read with the light raised', slide: SLIDE.diffuse, failureTitle: 'The picture is too dim to read', description: 'Where the picture is too dark, raises the page\'s own light and reads the shading there; the note says so.', reads: ['facts.brightened'] },
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

/** The settings a gatherer made to see the shading, in words: "kd to 0.8, then Le to 0.75". */
const settings = (steps) => steps.map((x) => `${x.role} to ${x.value}`).join(', then ');

/** Where the picture clipped to white, the sliders the gatherer lowered to read its shading (facts.unclipped). */
export function auditUnclipped({ facts, sayAs, imagesShown }) {
  const say = sayAs('unclipped');
  const u = facts.unclipped;
  if (!u) return;
  imagesShown.unclipped = u.image;
  say('pass', `note: the picture clips to white over ${fmt(PERCENT * u.before, 0)}% of the sphere, which hides its shading and highlight; they were judged with the page's own slider${u.steps.length > 1 ? 's' : ''} lowered: ${settings(u.steps)} (${fmt(PERCENT * u.after, 0)}% white then)`);
}

/** Where the picture was too dim to show its shading, the slider the gatherer raised to read it (facts.brightened). */
export function auditBrightened({ facts, sayAs, imagesShown }) {
  const say = sayAs('brightened');
  const b = facts.brightened;
  if (!b) return;
  imagesShown.brightened = b.image;
  say('pass', `note: the sphere is too dim to show its shading (brightness spread ${fmt(b.before, 3)}: a dark light); it was judged with the page's own slider raised: ${settings(b.steps)} (spread ${fmt(b.after, 3)} then)`);
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  unit(META, 'unclipped', (context, { shading }) => (shading.shaded ? auditUnclipped(context) : null), { uses: ['shading'] }),
  unit(META, 'brightened', (context, { shading }) => (shading.shaded ? auditBrightened(context) : null), { uses: ['shading'] }),
  unit(META, 'diffuse', (context, { shading, 'lit-views': lit }) => (shading.shaded ? auditDiffuse(context, shading.shading, lit) : null),
    { uses: ['shading', 'lit-views'] }),
  unit(META, 'point-light', (context, { shading }) => (shading.shaded ? auditPointLight(context, shading.shading) : null),
    { uses: ['shading'] }),
];
