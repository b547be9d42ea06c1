// WP04P4/P5: the specular term: a highlight shows (in the judged view, a lit view along the orbit,
// or with the page's own ks and s sliders raised), and it sits at w_h, halfway between the light
// and the viewer (the slides' w_r · w_o peaks there too), not at the light.
import { highlightOffset } from '../measure.js';
import { highlightEvidence } from '../computed/evidence.js';
import { fullFit, lightAngle } from '../computed/views.js';
import { fmt } from '../format.js';
import { SLIDE } from './slides.js';
import { viewFits } from '../computed/evidence.js';
import { unit } from './unit.js';
import { PERCENT } from '../units.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  highlight: { title: 'A specular highlight', slide: SLIDE.highlight, failureTitle: 'No specular highlight', description: 'Looks for a rise above the diffuse model, with ks and s raised by the page\'s own sliders where needed.', reads: ['images.judged', 'facts.views', 'facts.raised'] },
  'highlight-place': { title: 'The highlight at w_h, halfway between the light and the viewer', slide: SLIDE.eye, failureTitle: 'The highlight is not at w_h', description: 'Measures the highlight\'s place against where n = w_h, halfway between the light and the viewer, in the judged view and farther along the orbit.', reads: ['facts.views', 'facts.raised', 'facts.placeFarther'] },
};

/**
 * Whether a highlight shows, and where it is placed. Returns the place to judge at the end (the
 * gatherer looked farther along the orbit for it), or null.
 */
export function auditHighlight(context, shading, views) {
  const { facts, images, thresholds, must, sayAs, numbers } = context;
  const say = sayAs('highlight');
  if (!must.has('highlight') || !shading.fit) return null;
  const fit = shading.judgedFit;
  const { seen, place } = highlightEvidence(shading, views, facts.raised, images, thresholds);
  numbers.highlightViews = 1 + views.length;
  if (seen) say('pass', `a specular highlight in ${seen.where} (up to ${fmt(PERCENT * seen.fit.highlightPeak, 0)}% of the way from the diffuse fit to white, ${fmt(seen.fit.highlightRise, 2)} above it)`);
  let later = null;
  if (seen && !shading.nearModel) {
    if (!place) sayAs('highlight-place')('pass', 'note: the highlight\'s place is not judged: it shows only with s lowered to 10 by the page\'s own slider, which makes it too broad to place');
    else if (facts.placeFarther) later = place;
    else judgePlace(context, place);
  }
  if (!seen) say('mistake', `no specular highlight: nothing brighter than the diffuse fit (${fmt(fit.highlightPeak)}) in ${1 + views.length} views (the judged one${views.length ? ' and the lit ones along the orbit' : ''})`);
  return later;
}

/** The highlight's place, judged in the view the gatherer found farther along the orbit, else where it was seen (`near`). */
export function auditPlaceFarther(context, near) {
  const name = context.facts.placeFarther.image;
  if (!name) return judgePlace(context, near);
  const img = context.images[name];
  context.imagesShown.highlightPlace = name;
  judgePlace(context, { fit: fullFit(img, context.thresholds), where: 'a view along the orbit' });
}

/** Says whether the highlight sits at w_h in `place` ({ fit, where }). */
function judgePlace({ thresholds, sayAs, numbers }, place) {
  const say = sayAs('highlight-place');
  const offset = highlightOffset(place.fit.highlightNormal, place.fit.light);
  if (offset === null) return;
  const light = lightAngle(place.fit);
  Object.assign(numbers, { highlightOffset: offset, highlightPlaceLight: light });
  const near = light < thresholds.highlightPlaceLightDegrees;
  const where = `in ${place.where}, the light ${fmt(light, 0)}° from the viewer`;
  const fitted = place.fit.light.map((v) => fmt(v)).join(', ');
  const ask = 'is w_o the direction from the surface to the eye, in the same space as n and w_i?';
  // w_h is half the light's angle from w_i: with the light well away from the viewer, a highlight
  // clearly nearer the light than w_h is at the light (w_o or w_r wrong), even within the bound below
  const fromLight = highlightOffset(place.fit.highlightNormal, place.fit.light, 0);
  numbers.highlightFromLight = fromLight;
  const tint = place.fit.tint;
  const atLight = !near && offset - fromLight >= thresholds.highlightAtLightDegrees;
  if (tint && !tint.sure && (atLight || offset > thresholds.highlightPlaceDegrees)) {
    // the hue turns with the normal (the P1 colour kept in the material): the fitted light is unsure
    say('pass', `note: the highlight's place is not judged: the colours are tinted by the normal (the WP04P1 colour 0.5·n + 0.5 in the material or mixed in), and with ${unsure(tint, thresholds)} the fitted light cannot place it (it is ${fmt(offset, 0)}° from the halfway normal the fit gives, ${where})`);
    return;
  }
  if (atLight) say('mistake', `the highlight sits at the light, not halfway between the light and the viewer: ${fmt(fromLight, 0)}° from the light, ${fmt(offset, 0)}° from the halfway normal (the light fitted at ${fitted}; ${where}): ${ask}`);
  else if (offset > thresholds.highlightPlaceDegrees) say('mistake', `the highlight is ${fmt(offset, 0)}° from where the model puts it (at the normal halfway between the light, fitted at ${fitted}, and the viewer; ${where}): ${ask}`);
  else say('pass', `the highlight sits where the normal is halfway between the light and the viewer (${fmt(offset, 0)}° off, ${where}${near ? `; with the light this near the viewer that halfway normal is only ${fmt(light / 2, 0)}° from the light, so a highlight at the light would pass too` : ''})`);
}

/** Why a tinted fit cannot place a highlight, in words. */
function unsure(tint, thresholds) {
  const why = [];
  if (tint.slope === null) why.push('no fit that divides the tint out');
  else {
    if (tint.slope >= thresholds.tintSlope) why.push(`an albedo whose brightness varies by ±${fmt(PERCENT * tint.slope, 0)}% over the sphere`);
    if (tint.lightShift > thresholds.tintLightDegrees) why.push(`a light that moves ${fmt(tint.lightShift, 0)}° when the tint is divided out`);
  }
  return why.length ? why.join(' and ') : `a fit of R² under ${thresholds.diffuseR2}`;
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  // the highlight read on the judged picture and on the lit views' full fits; its result (the place
  // nearer the viewer) is read again farther along (highlight-place)
  unit(META, 'highlight', (context, { shading, 'lit-views': lit }) => {
    if (!shading.shaded) return null;
    const views = viewFits(lit.map((v) => ({ img: context.images[v.image] })), context.thresholds);
    return auditHighlight(context, shading.shading, views);
  },
    { also: ['highlight-place'], uses: ['shading', 'lit-views'] }),
  unit(META, 'highlight-place', (context, { highlight }) => (highlight ? auditPlaceFarther(context, highlight) : null), { uses: ['highlight'] }),
];
