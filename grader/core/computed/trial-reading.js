// P4: what each slider trial moved of the slide's reflection model, read where it can be read best.
// On the page's own surface (computed/surface.js) where the trial's pictures are the surface's view
// (a still page, the sphere's outline around the surface's pixels) and the judged picture's fit
// found the light: the ambient, the diffuse and the specular term and the shininess, each apart
// (measure/surface-terms.js). Else on the pictures alone: the dark side and the lit side
// (measure/terms.js) and the highlight's height above the diffuse fit; the shininess not at all.
import { analyse } from '../measure.js';
import { clippedShare } from '../measure/samples.js';
import { trialTerms, highlightMoved } from '../measure/terms.js';
import { termsOnSurface, surfaceTrial, showsSpecular } from '../measure/surface-terms.js';
import { fullFit } from './views.js';
import { surfaceSeen } from './lighting.js';
import { memo } from './memo.js';

/** The surface's samples where `img` (its analysis `an`) is the surface's view: all but a few inside its outline. */
function surfaceSeenIn(facts, images, thresholds, img, an) {
  const s = surfaceSeen(images, { img, an }, thresholds, facts.surface);
  return s.why ? null : s;
}

/**
 * Slider trial `s` read: { ambient, diffuse, specular, shininess } (true, false, null: not seen),
 * `on` ('surface' or 'picture'), `terms` (on the surface: termsOnSurface's readings before and
 * after) and `why` (in words, where something was read on the pictures alone), or null where its
 * pictures show no sphere. `exact` is the judged picture's fit on the surface (computed/lighting.js:
 * null or { why } where there is none), read only where it explains that picture (within
 * surfaceResidual). A highlight that the picture shows and the surface's pixels miss before the
 * trial (a small one clipped to white) is read on the picture, its shininess not at all.
 */
export const trialReading = ({ facts, images, thresholds }, s, exact) =>
  readOnce(s, facts, images, thresholds, exact || NO_FIT);

/** The judged picture's fit where there is none (a key for the memo). */
const NO_FIT = { why: 'the page\'s surface was not read' };

/** One trial's reading, made once for each trial, artifact, rubric and judged fit (the sliders' and the terms' audits read it). */
const readOnce = memo((s, facts, images, thresholds, exact) => readTrial({ facts, images, thresholds }, s, exact));

/** The reading itself (trialReading's). */
function readTrial({ facts, images, thresholds }, s, exact) {
  const before = images[s.before], after = images[s.image];
  const an = before ? analyse(before, thresholds) : null;
  if (!an || an.blank || !after) return null;
  // the highlight's height on the pictures, where it is needed (a picture clipped to white over much
  // of the sphere hides its highlight: its height is not read there)
  const clips = (img) => clippedShare(img, analyse(img, thresholds), thresholds) >= thresholds.clippedShare;
  const height = () => (clips(before) || clips(after)
    ? null
    : highlightMoved(fullFit(before, thresholds), fullFit(after, thresholds), thresholds));
  const read = onSurface({ facts, images, thresholds }, s, exact, before, an);
  if (read.r) {
    const pictured = !showsSpecular(read.b, thresholds);
    const why = 'the page\'s surface shows no highlight before the trial, one smaller than its pixels or clipped to white, so its height was read on the pictures';
    return { ...read.r, ...(pictured ? { specular: height(), shininess: null, why } : {}), on: 'surface', terms: read.terms };
  }
  const anAfter = s.moving ? analyse(after, thresholds) : null;
  const t = trialTerms(before, after, an, anAfter, thresholds, { moving: !!s.moving });
  return {
    ambient: t ? t.ambient : null, diffuse: t ? t.diffuse : null, specular: height(), shininess: null,
    on: 'picture', why: read.why,
  };
}

/** Trial `s` read on the surface: { r, b, terms } (surfaceTrial's, the reading before, both readings), or { why } it could not be, in words. */
function onSurface({ facts, images, thresholds }, s, exact, before, an) {
  if (s.moving) return { why: 'the picture moves by itself while a slider is tried' };
  if (!exact || exact.why) return { why: exact ? exact.why : 'the page\'s surface was not read' };
  // (the judged picture's fit must explain it: a model that leaves a visible residual reads its terms wrong)
  if (exact.best.rms > thresholds.surfaceResidual) {
    return { why: `the slide's model leaves a residual of ${exact.best.rms.toFixed(3)} on the page's own surface` };
  }
  const surface = surfaceSeenIn(facts, images, thresholds, before, an);
  if (!surface) return { why: 'the trials\' pictures are not the view the surface was read in' };
  const b = termsOnSurface(surface, before, exact.best, thresholds);
  const a = termsOnSurface(surface, images[s.image], exact.best, thresholds);
  const r = surfaceTrial(b, a, thresholds);
  return r ? { r, b, terms: { before: b, after: a } } : { why: 'a trial turned the light or the view: the model no longer explains its picture' };
}
