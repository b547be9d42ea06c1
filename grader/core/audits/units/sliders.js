// The audit unit 'sliders' (Sliders for the material and light parameters): Finds the sliders for
// kd, ks, s, Le and La by what they change, and sets each far from where it is.
import { analyse, perspectiveSamples, highlightAbove } from '../../measure.js';
import { fullFit } from '../../computed/views.js';
import { sliderEvent } from '../../computed/slider-event.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  sliders: { title: 'Sliders for the material and light parameters', slide: SLIDE.sliders, failureTitle: 'Sliders for the material and light parameters are missing or do nothing', description: 'Finds the sliders for kd, ks, s, Le and La by what they change, and sets each far from where it is.', reads: ['facts.sliders', 'facts.slidersFound'] },
  'input-event': { title: 'Sliders that act on the input event', slide: SLIDE.inputEvent, failureTitle: 'A slider acts on the change event, not on input', description: 'Sets each slider on the input event first, and on the change event only where input showed nothing.', reads: ['facts.sliders'] },
  'ks-used': { title: 'ks used in the specular term', slide: SLIDE.sliders, failureTitle: 'ks is not used in the specular term', description: 'Sets the ks sliders to their least and checks that the highlight changes.', reads: ['facts.sliders', 'images.judged'] },
};

const SLIDERS = ['kd', 'ks', 's', 'Le', 'La'];

/** The sliders tried (facts.sliders), against the judged view (`judged`: { an }) and its shading. */
export function auditSliders({ facts, images, thresholds, must, sayAs, rubric, part }, judged, shading) {
  if (!must.has('sliders')) return;
  const say = sayAs('sliders'), sayEvent = sayAs('input-event'), sayKs = sayAs('ks-used');
  const looked = (rubric.parts[part] || {}).sliders || SLIDERS;
  const required = (rubric.parts[part] || {}).requiredSliders || [];
  const baseFit = shading && shading.judgedFit;
  const nearModel = shading && shading.nearModel;
  let inputOk = 0, changeOnly = 0, dead = 0;
  const found = {};
  const together = {}; // role → how its sliders moved together (ks r, g, b: one parameter)
  for (const s of facts.sliders) {
    const { role, target } = s;
    const how = sliderEvent(s, thresholds);
    if (how !== 'none' && !s.levelSlider) {
      if (role && !found[role]) found[role] = true;
      if (role && s.controls) together[role] = `${s.controls.length} sliders (${s.channels}) moved together`;
      if (how === 'input') inputOk++;
      else changeOnly++;
    } else if (how === 'none') dead++;
    if (how !== 'none' && baseFit && role === 'ks') {
      // the highlight left with ks at its least: above the base picture's near point-light model (its
      // 1/r² spot stays and is no highlight), or above the after picture's own directional fit
      const after = images[s.image];
      const a = analyse(after, thresholds);
      const f = a.blank
        ? null
        : nearModel
          ? {
              highlightPeak: highlightAbove(
                perspectiveSamples(after, judged.an, thresholds, { max: thresholds.fitSamples }),
                nearModel,
                thresholds,
              ),
            }
          : fullFit(after, thresholds);
      if (
        f &&
        f.highlightPeak >= baseFit.highlightPeak * thresholds.ksLeftShare &&
        f.highlightPeak >= thresholds.highlightPeak
      ) {
        sayKs(
          'review',
          `ks${s.controls ? ` (its ${s.controls.length} sliders)` : ''} at ${target} leaves the highlight as it was (${fmt(f.highlightPeak)}): is ks used in the specular term?`,
        );
      }
    }
  }
  const named = Object.keys(found).map((k) => (together[k] ? `${k}: ${together[k]}` : k));
  const missing = looked.filter((k) => !found[k]);
  const changeOnlyWords = `${changeOnly} slider(s) update the picture only on the change event, not while sliding (the slide asks for the input event)`;
  if (inputOk) say('pass', `${inputOk} slider(s) change the material or light on the input event${named.length ? ` (${named.join(', ')})` : ''}`);
  else if (changeOnly) sayEvent('review', changeOnlyWords);
  else say('review', `no slider changes the material or light (${facts.slidersFound} tried; the slide asks for sliders for the parameters)`);
  if (inputOk && changeOnly) sayEvent('review', changeOnlyWords);
  const requiredMissing = required.filter((k) => !found[k]);
  if (requiredMissing.length) say('review', `no slider found for ${requiredMissing.join(', ')} (this rubric asks for each)`);
  else if (missing.length && inputOk) say('pass', `note: no slider found for ${missing.join(', ')}`);
  if (must.has('sliders') && dead) say('pass', `note: ${dead} slider(s) change nothing in the picture`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'sliders', (context, results) => auditSliders(context, results['judged-picture'], results.shading.shading),
  { also: ['input-event', 'ks-used'], uses: ['judged-picture', 'shading'] });
