// The audit unit 'sliders' (Sliders for the material and light parameters): Finds the sliders for
// kd, ks, s, Le and La by what they change, and sets each far from where it is, against the picture
// just before it.
import { analyse, perspectiveSamples, highlightAbove } from '../../measure.js';
import { clippedShare } from '../../measure/samples.js';
import { PERCENT } from '../../units.js';
import { fullFit, litView } from '../../computed/views.js';
import { sliderEvent } from '../../computed/slider-event.js';
import { trialReading } from '../../computed/trial-reading.js';
import { showsSpecular } from '../../measure/surface-terms.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  sliders: { title: 'Sliders for the material and light parameters', slide: SLIDE.sliders, failureTitle: 'Sliders for the material and light parameters are missing or do nothing', description: 'Finds the sliders for kd, ks, s, Le and La by what they change (where none shows, after a control named for showing the settings), and sets each far from where it is, against the picture just before it.', reads: ['facts.sliders', 'facts.slidersFound', 'facts.frameDraws', 'facts.stopped', 'facts.slidersShownBy'] },
  'input-event': { title: 'Sliders that act on the input event', slide: SLIDE.inputEvent, failureTitle: 'A slider acts on the change event, not on input', description: 'Sets each slider on the input event first, and on the change event only where input showed nothing.', reads: ['facts.sliders'] },
  'ks-used': { title: 'ks used in the specular term', slide: SLIDE.sliders, failureTitle: 'ks is not used in the specular term', description: 'Sets the ks sliders to their least and checks that the specular term changes: on the page\'s own surface where the trial\'s pictures are its view (the term fitted before and after on the same pixels), else in the highlight above the diffuse fit.', reads: ['facts.sliders', 'images.judged', 'facts.surface'] },
};

const SLIDERS = ['kd', 'ks', 's', 'Le', 'La'];

/** The page drew no frame of its own with its orbit stopped, when the gathering ended (facts.frameDraws: the page's draw calls a frame). */
const drawsOnlyMoving = (facts) =>
  !!facts.stopped && !!facts.frameDraws && !!facts.frameDraws.last && facts.frameDraws.last.draws === 0;

/** The sliders tried (facts.sliders), against the judged view (`judged`: { an }) and its shading. */
export function auditSliders(context, judged, shading, exact = null) {
  const { facts, images, thresholds, must, sayAs, rubric, part } = context;
  if (!must.has('sliders')) return;
  const say = sayAs('sliders'), sayEvent = sayAs('input-event');
  const looked = (rubric.parts[part] || {}).sliders || SLIDERS;
  const required = (rubric.parts[part] || {}).requiredSliders || [];
  const baseFit = shading && shading.judgedFit;
  const nearModel = shading && shading.nearModel;
  let inputOk = 0, changeOnly = 0, dead = 0;
  const found = {};
  const together = {}; // role → how its sliders moved together (ks r, g, b: one parameter)
  // the trials whose putting back left the page in another state: the trials after the first were
  // read against the picture just before each (gather/sliders.js), and so is ks's highlight
  const putBack = [];
  const hidden = []; // the trials that showed nothing from a picture with no shading to read: { role, why }
  for (const s of facts.sliders) {
    const { role } = s;
    const how = sliderEvent(s, thresholds);
    // (a state the grader's own putting back left: a trial that showed nothing there may act elsewhere)
    const why = how === 'none' && putBack.length && s.before ? hiddenIn(images[s.before], thresholds) : null;
    if (why) hidden.push({ role, why });
    else if (how !== 'none' && !s.levelSlider) {
      if (role && !found[role]) found[role] = true;
      if (role && s.controls) together[role] = `${s.controls.length} sliders (${s.channels}) moved together`;
      if (how === 'input') inputOk++;
      else changeOnly++;
    } else if (how === 'none') dead++;
    if (role === 'ks' && how !== 'none') {
      // (ks's highlight is read against the picture before its trial once the page has been left elsewhere)
      const base = putBack.length && s.before && !nearModel ? fullFit(images[s.before], thresholds) : baseFit;
      ksUsed(context, s, { base, nearModel, judged, exact });
    }
    if (restoredElsewhere(s, thresholds)) putBack.push(s);
  }
  if (putBack.length === 1) {
    const [moved] = putBack;
    say('pass', `note: putting ${moved.role ? `the ${moved.role} slider` : 'a slider'} back to ${moved.restored.to} (its value on the page) changed the picture: the page starts with another value than its slider shows (each slider after it was tried from the picture just before it)`);
  } else if (putBack.length > 1) {
    const which = putBack.map((x) => `${x.role || 'a slider'} to ${x.restored.to}`).join(', ');
    say('pass', `note: putting ${putBack.length} sliders back to their values on the page (${which}) changed the picture: the page starts with other values than its sliders show (each slider was tried from the picture just before it)`);
  }
  const named = Object.keys(found).map((k) => (together[k] ? `${k}: ${together[k]}` : k));
  const unseen = hidden.filter((h) => h.role && !found[h.role]).map((h) => h.role);
  if (hidden.length) {
    say('pass', `note: ${hidden.length} slider(s)${unseen.length ? ` (${unseen.join(', ')})` : ''} showed no change from a picture that ${hidden[0].why}: whether they act cannot be seen there`);
  }
  const missing = looked.filter((k) => !found[k] && !unseen.includes(k));
  const changeOnlyWords = `${changeOnly} slider(s) update the picture only on the change event, not while sliding (the slide asks for the input event)`;
  if (inputOk) say('pass', `${inputOk} slider(s) change the material or light on the input event${named.length ? ` (${named.join(', ')})` : ''}`);
  else if (changeOnly) sayEvent('review', changeOnlyWords);
  else if (drawsOnlyMoving(facts)) {
    say('review', `no slider changes the picture: the page draws no frame of its own once its orbit is stopped (0 draw calls a frame), so a slider whose value shows only in the next frame drawn shows nothing there (${facts.slidersFound} tried; the slides: "use the input event for the sliders to get immediate response while sliding")`);
  } else say('review', `no slider changes the material or light (${facts.slidersFound} tried; the slide asks for sliders for the parameters)`);
  if (inputOk && changeOnly) sayEvent('review', changeOnlyWords);
  const requiredMissing = required.filter((k) => !found[k]);
  if (requiredMissing.length) say('review', `no slider found for ${requiredMissing.join(', ')} (this rubric asks for each)`);
  else if (missing.length && inputOk) say('pass', `note: no slider found for ${missing.join(', ')}`);
  if (must.has('sliders') && dead) say('pass', `note: ${dead} slider(s) change nothing in the picture`);
}

/** Why `img` hides what a slider does (washed out to white over clippedShare of the sphere or more, or no lit sphere), in words; null where it shows its shading. */
function hiddenIn(img, thresholds) {
  if (!img) return null;
  const { an, lit } = litView(img, thresholds);
  if (an.blank) return 'shows no sphere';
  const share = clippedShare(img, an, thresholds);
  if (share >= thresholds.clippedShare) return `clips to white over ${Math.round(PERCENT * share)}% of the sphere`;
  return lit ? null : 'shows no lit sphere';
}

/**
 * ks at its least (trial `s`): does the specular term change? Read on the page's own surface where it
 * can be (the term fitted before and after on the same pixels): that decides; else the highlight in
 * the pictures, above `base` (the picture before: its directional fit, or its near point-light model
 * `nearModel`, whose 1/r² spot stays and is no highlight).
 */
function ksUsed(context, s, { base, nearModel, judged, exact }) {
  const { images, thresholds, sayAs } = context, sayKs = sayAs('ks-used');
  const { target } = s, its = s.controls ? ` (its ${s.controls.length} sliders)` : '';
  const surface = ksOnSurface(context, s, exact);
  if (surface) {
    if (surface.left) sayKs('review', `ks${its} at ${target} leaves the specular term as it was on the page's own surface (k_s L_e ${surface.before} before, ${surface.after} after): is ks used in the specular term?`);
    return;
  }
  if (!base) return;
  const after = images[s.image];
  const a = analyse(after, thresholds);
  const near = () => {
    const pts = perspectiveSamples(after, judged.an, thresholds, { max: thresholds.fitSamples });
    return { highlightPeak: highlightAbove(pts, nearModel, thresholds) };
  };
  const f = a.blank ? null : nearModel ? near() : fullFit(after, thresholds);
  // (a picture clipped to white over much of the sphere, ks at 0 or not, reads as a highlight
  // that stays: the clipped pixels are no evidence of one, and whether it stayed cannot be told)
  const clips = f && !a.blank ? clippedShare(after, a, thresholds) : 0;
  // as it was: as far toward white, and as high above the diffuse fit (a diffuse term that reaches
  // white at its peak leaves a sliver over the fit that is far toward white, and is no highlight)
  const risen = (x) => Number.isFinite(x.highlightRise);
  const left = f && f.highlightPeak >= base.highlightPeak * thresholds.ksLeftShare &&
    f.highlightPeak >= thresholds.highlightPeak &&
    (!risen(f) || !risen(base) || f.highlightRise >= base.highlightRise * thresholds.ksLeftShare);
  if (left && clips >= thresholds.clippedShare) {
    sayKs('pass', `note: ks at ${target} is not judged: the picture clips to white over ${Math.round(PERCENT * clips)}% of the sphere (the material and light saturate it), so whether the highlight stayed cannot be told there`);
  } else if (left) {
    sayKs('review', `ks${its} at ${target} leaves the highlight as it was (${fmt(f.highlightPeak)}): is ks used in the specular term?`);
  }
}

/**
 * The ks trial `s` read on the page's own surface (computed/trial-reading.js): { left (the specular
 * term as it was), before, after (k_s L_e a channel, in words) }, or null where it was not read there
 * or the surface shows no specular term before it.
 */
function ksOnSurface(context, s, exact) {
  const r = trialReading(context, s, exact);
  if (!r || r.on !== 'surface' || r.why || r.specular === null) return null;
  if (!showsSpecular(r.terms.before, context.thresholds)) return null;
  const colour = (k) => k.map((v) => fmt(v)).join(', ');
  return { left: r.specular === false, before: colour(r.terms.before.k), after: colour(r.terms.after.k) };
}

/** Did putting slider trial `s` back leave the page in another state than before it (its picture, or where the picture moves by itself, what the page sent)? */
export function restoredElsewhere(s, thresholds) {
  const r = s.restored;
  if (!r) return false;
  return r.sent ? r.sent.length > 0 : r.changed > thresholds.sliderChange;
}

/** Where the page's sliders showed only once a control was clicked (gather/reveal.js): a note naming it. */
function sayShownBy({ facts, must, sayAs }) {
  if (must.has('sliders') && facts.slidersShownBy) sayAs('sliders')('pass', `note: the sliders show only once ${facts.slidersShownBy} is clicked; the grader clicked it, as a teacher looking for them would`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'sliders', (context, results) => {
  sayShownBy(context);
  return auditSliders(context, results['judged-picture'], results.shading.shading, results['surface-fit']);
},
  { also: ['input-event', 'ks-used'], uses: ['judged-picture', 'shading', 'surface-fit'] });
