// What the highlight audits share (units/highlight.js, highlight-place.js): whether the highlight
// sits at w_h, halfway between the light and the viewer (the slides' w_r · w_o peaks there too),
// not at the light, in a view where that can be told.
import { highlightOffset, analyse } from '../measure.js';
import { exactLighting } from '../computed/lighting.js';
import { VIEW_WORDS, misread } from './units/surface-fit.js';
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

/**
 * The highlight's place not judged: it showed only in views along the orbit at a coarser level than
 * the judged one (`coarser`: { vertices, judged }, the vertices a frame drew), and no view at the
 * judged level was found.
 */
export function sayCoarse({ sayAs }, coarser) {
  sayAs('highlight-place')('pass', `note: the highlight's place is not judged: it showed only in views along the orbit at a coarser level than the judged one (${coarser.vertices} vertices a frame, against ${coarser.judged}), and per vertex a coarse mesh moves a highlight (the slides: Gouraud shading needs many triangles, for highlights in particular)`);
}

/**
 * Says whether the highlight sits at w_h in `place` ({ fit, where, img }): on the page's own
 * `surface` where it was read with that picture (placeOnSurface), else on the picture's fit.
 */
export function judgePlaceOn(context, place, surface) {
  const { facts, images, thresholds } = context;
  const exact = surface && place.img
    ? exactLighting(facts, images, { img: place.img, an: analyse(place.img, thresholds) }, thresholds, surface)
    : null;
  if (!placeOnSurface(context, exact, place.where)) judgePlace(context, place);
}

/**
 * The highlight's place read on the page's own surface in that view (its normals and positions as
 * it drew them: the light and the highlight fitted there, computed/lighting.js): a w_o misread that
 * explains the picture better by the rubric's margin is a mistake; the slide's w_o explaining it
 * within surfaceResidual (Phong or Blinn-Phong, the normal colour in the material or not) places
 * the highlight where the slide puts it. Says it and returns true; false where the surface decides
 * nothing (not read, or no fit explains the picture: the picture's fit decides, as on the outline).
 */
function placeOnSurface({ sayAs, numbers, thresholds }, exact, where) {
  if (!exact || exact.why || !exact.slide) return false;
  const { best } = exact;
  numbers.placeSurfaceFit = { slide: exact.slide, best: { name: best.name, rms: best.rms } };
  const say = sayAs('highlight-place');
  const tint = best.tint ? ', with the normal colour in the material' : '';
  if (misread(best)) {
    say('mistake', `the highlight is not where the slide puts it: on the page's own surface in ${where}, the picture is explained with a residual of ${best.rms.toFixed(3)} (the slide's formula: ${exact.slide.rms.toFixed(3)}) where ${VIEW_WORDS[best.view]}${tint}: is w_o the direction from the surface to the eye, in the same space as n and w_i?`);
    return true;
  }
  if (best.rms > thresholds.surfaceResidual || !best.form) return false;
  say('pass', `the highlight sits where the slide's ${best.form === 'phong' ? 'Phong' : 'Blinn-Phong'} model with w_o = normalize(e − p) puts it, read on the page's own surface in ${where} (its normals and positions as it drew them): a residual of ${best.rms.toFixed(3)}${tint}`);
  return true;
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
