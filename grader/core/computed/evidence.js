// Readings of the judged picture that gatherers and audits share: the sphere's outline (fitted to
// the lit edge where the unlit side merges with the background), the diffuse fit and point-light
// fit of its shading, and where a highlight shows. Pure: a gatherer that acts on one of these (to
// raise ks, or look farther along the orbit) and the audit that judges it read the same numbers.
import { analyse, samples, shadeFit, pointLightFit, perspectiveSamples, highlightSeen, clearlyNearFalloff } from '../measure.js';
import { fullFit, lightAngle } from './views.js';
import { memo } from './memo.js';

/**
 * The judged picture's analysis: `an`, with a dark unlit side on a dark background read as the
 * lit edge's circle (`circleArc`, the degrees of circle it fits) when the outline is not round.
 */
export function sphereView(img, thresholds) {
  let an = analyse(img, thresholds);
  let circleArc = null;
  const circ = an.circle;
  if (
    !an.blank &&
    !(an.roundness <= thresholds.roundness && an.fill >= thresholds.fill) &&
    circ &&
    circ.roundness <= thresholds.roundness &&
    circ.arc >= thresholds.litEdgeArcDegrees &&
    !an.touches
  ) {
    an = { ...an, cx: circ.cx, cy: circ.cy, radius: circ.r, roundness: circ.roundness, fill: 1 };
    circleArc = circ.arc;
  }
  return { an, circleArc };
}

/**
 * The shading of a picture (its analysis `an`): the diffuse fit over all samples, a point-light
 * fit where the picture is lit, and `nearModel`, the near point light with 1/r² fall-off where it
 * fits clearly better (then the highlight is what rises above it, in `fit`'s highlight fields).
 * Read once for the same picture, analysis and thresholds: gathering acts on it, the audit judges it.
 */
export const shadingOf = memo((img, an, thresholds) => {
  const fit = shadeFit(samples(img, an, thresholds), thresholds);
  let pointLight = null;
  if (fit && fit.spread >= thresholds.litSpread) {
    pointLight = pointLightFit(
      perspectiveSamples(img, an, thresholds, { max: thresholds.fitSamples }),
      thresholds,
      fit.light,
    );
  }
  const nearModel = clearlyNearFalloff(pointLight, thresholds) ? pointLight.falloff.model : null;
  const judgedFit =
    fit && nearModel
      ? { ...fit, highlightPeak: pointLight.falloff.highlightPeak, highlightRise: pointLight.falloff.highlightRise }
      : fit;
  return { img, fit, judgedFit, pointLight, nearModel };
});

/**
 * Whether the lit view `v` (facts.views') was taken at a coarser level than the judged one: the
 * judged level draws levelWorkRatio times its vertices or more (the page's draws: a view along the
 * orbit sampled before the ladder). { vertices, judged } then, else null.
 */
export function coarserView(v, facts, thresholds) {
  const judged = facts.judgedVertices;
  const coarser = v.vertices > 0 && judged > 0 && judged >= thresholds.levelWorkRatio * v.vertices;
  return coarser ? { vertices: v.vertices, judged } : null;
}

/** The lit views `views` (facts.views' entries) with their pictures from `images`, their full fits and whether each is coarser. */
export function litViewFits(views, facts, images, thresholds) {
  return viewFits(views.map((v) => ({ img: images[v.image], coarser: coarserView(v, facts, thresholds) })), thresholds);
}

/** The kept views' full fits (the lit views along the orbit), in the order kept. */
export function viewFits(views, thresholds) {
  return views.map((v) => ({ ...v, fit: fullFit(v.img, thresholds) }));
}

/**
 * Where the highlight shows without touching the page: the judged view, else one of the lit views
 * along the orbit (not with a near point light: its 1/r² spot is read against its own model).
 * { fit, where } or null; in the judged view, with its picture (`img`) and `atJudged`.
 */
export function highlightShown(shading, views, thresholds) {
  if (highlightSeen(shading.judgedFit, thresholds)) {
    return { fit: shading.judgedFit, where: 'the judged view', img: shading.img, atJudged: true };
  }
  if (shading.nearModel) return null;
  // (one at the judged level first: a coarser one's highlight shows, but its place is not read there)
  const shows = (v) => v.fit && highlightSeen(v.fit, thresholds);
  const other = views.find((v) => shows(v) && !v.coarser) || views.find(shows);
  if (!other) return null;
  return { fit: other.fit, where: `one of ${views.length} lit views along the orbit`, coarser: other.coarser || null };
}

/**
 * The view to place the highlight in: the one that tells w_h from w_i best, of those that show the
 * highlight over a clean diffuse fit, the light farthest from the viewer; not where only a
 * broadened highlight (s lowered to 10) shows, nor in a view at a coarser level than the judged one
 * (per vertex, a coarse mesh moves a highlight: the slides' Gouraud shading needs many triangles,
 * for highlights in particular). { fit, where } or null.
 */
export function placeView(seen, views, thresholds) {
  const clean = (f) => f.r2 >= thresholds.diffuseR2;
  let place = seen.broad || seen.coarser ? null : seen;
  for (const v of views) {
    const f = v.fit;
    const shows = f && !v.coarser && highlightSeen(f, thresholds) && clean(f);
    if (shows && (!place || !clean(place.fit) || lightAngle(f) > lightAngle(place.fit))) {
      place = { fit: f, where: 'a lit view along the orbit' };
    }
  }
  return place;
}

/** Does a picture show a highlight over its own diffuse fit? (The gatherer raising ks acts on it; the audit reads it again.) */
export const highlightIn = (img, thresholds) => {
  const f = img && fullFit(img, thresholds);
  return !!f && highlightSeen(f, thresholds);
};

/**
 * The highlight as the page's own sliders showed it once raised (`raised`: [{ role, image, broad }]
 * in the order set; each picture read again here): { fit, broad, where, img, atJudged } or null.
 */
export function raisedSeen(raised, images, thresholds) {
  const k = raised.findIndex((x) => x.image && highlightIn(images[x.image], thresholds));
  if (k < 0) return null;
  const x = raised[k];
  const img = images[x.image];
  const set = raised.slice(0, k + 1).map((r) => r.role);
  return { fit: fullFit(img, thresholds), broad: x.broad, img, atJudged: true,
    where: `the judged view with ${set.join(' and ')} set by the page's own slider${set.length > 1 ? 's' : ''}` };
}

/**
 * The highlight's evidence, as the gatherer acts on it and the audit judges it: where it shows (the
 * judged view, a lit view along the orbit, else with the page's sliders raised: `raised`, absent
 * before they are tried) and the view to place it in (none with a near point light). `farther`:
 * the light in that view is too near the viewer to tell w_h from w_i, or (`coarse`) the highlight
 * showed only in views at a coarser level than the judged one, so the place is better judged
 * farther along the orbit. { seen, place, coarse, farther }.
 */
export function highlightEvidence(shading, views, raised, images, thresholds) {
  let seen = highlightShown(shading, views, thresholds);
  if (!seen && !shading.nearModel && raised) seen = raisedSeen(raised, images, thresholds);
  const place = seen && !shading.nearModel ? placeView(seen, views, thresholds) : null;
  // seen only in views at a coarser level: its place is looked for along the orbit at the judged level
  const coarse = !!seen && !shading.nearModel && !place && !seen.broad && !!seen.coarser;
  const near = !!place && lightAngle(place.fit) < thresholds.highlightPlaceLightDegrees;
  return { seen, place, coarse, farther: coarse || near };
}
