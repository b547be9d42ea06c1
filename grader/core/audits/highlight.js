// What the highlight audits share (units/highlight.js, highlight-place.js): whether the highlight
// sits at w_h, halfway between the light and the viewer (the slides' w_r · w_o peaks there too),
// not at the light, in a view where that can be told.
import { highlightOffset } from '../measure.js';
import { lightAngle } from '../computed/views.js';
import { fmt } from '../format.js';
import { PERCENT } from '../units.js';

/** Says whether the highlight sits at w_h in `place` ({ fit, where }). */
export function judgePlace({ thresholds, sayAs, numbers }, place) {
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
export function unsure(tint, thresholds) {
  const why = [];
  if (tint.slope === null) why.push('no fit that divides the tint out');
  else {
    if (tint.slope >= thresholds.tintSlope) why.push(`an albedo whose brightness varies by ±${fmt(PERCENT * tint.slope, 0)}% over the sphere`);
    if (tint.lightShift > thresholds.tintLightDegrees) why.push(`a light that moves ${fmt(tint.lightShift, 0)}° when the tint is divided out`);
  }
  return why.length ? why.join(' and ') : `a fit of R² under ${thresholds.diffuseR2}`;
}
