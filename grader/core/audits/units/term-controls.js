// The audit unit 'term-controls' (The ambient term has a control of its own): reads in each slider
// trial's pictures which of the Phong model's terms it moved, the dark side (the ambient term
// alone) and the lit side above it (the diffuse term); a slider that moves both, where no slider
// moves the ambient term alone, leaves the ambient term with no control of its own.
import { analyse } from '../../measure.js';
import { trialTerms } from '../../measure/terms.js';
import { sliderEvent } from '../../computed/slider-event.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'term-controls': { title: 'The ambient term has a control of its own', slide: SLIDE.sliders, failureTitle: 'The ambient term has no control of its own', description: 'Reads in each slider trial\'s pictures what it moved: the dark side (the ambient term alone) and the lit side above it (the diffuse term). A slider that moves both, where no slider moves the ambient term alone (ka or La), is a review; where the pictures cannot tell, a note says so.', reads: ['facts.sliders', 'facts.roles'] },
};

/** A slider trial in words: its role and what it is ('kd: range "Diffuse #kd"'), and the uniforms it changed where they were read. */
function trialWords(s, facts) {
  const r = Object.values(facts.roles || {}).find((x) => x.control === s.control);
  const what = r && r.what ? r.what : `slider ${s.control}`;
  const sent = s.sent && s.sent.input && s.sent.input.length ? `, which changed ${s.sent.input.join(', ')}` : '';
  return `${s.role ? `${s.role}: ` : ''}${what}${sent}`;
}

/**
 * The slides' P4 ("sliders for modifying the different parameters"; L_o = k_d L_i max(cos θ, 0) +
 * k_a L_a, k_a = k_d) asks that the ambient term can be set apart from the diffuse one: by ka, or
 * by La where ka is kd. Each trial that acted is read in its pictures (measure/terms.js); names
 * only break a tie where a picture cannot show the dark side (a slider named for the ambient term).
 */
export function auditTermControls({ facts, images, thresholds, must, sayAs }) {
  if (!must.has('sliders')) return;
  const say = sayAs('term-controls');
  const read = [];
  for (const s of facts.sliders) {
    if (s.levelSlider || sliderEvent(s, thresholds) === 'none') continue;
    const before = images[s.before], after = images[s.image];
    const an = before ? analyse(before, thresholds) : null;
    const t = an && !an.blank && after
      ? trialTerms(before, after, an, s.moving ? analyse(after, thresholds) : null, thresholds, { moving: !!s.moving })
      : null;
    read.push({ s, t });
  }
  // alone: the dark side moved and the lit side above it, seen, did not (but for s: at 0, pow(x, 0) = 1
  // makes the specular term flat, as bright on the dark side as an ambient term); both: it moved
  // both; a trial whose picture cannot show the dark side, or the lit side where the dark side moved, is unread
  const alone = read.filter(({ s, t }) => t && t.ambient === true && t.diffuse === false && s.role !== 's');
  const both = read.filter(({ t }) => t && t.ambient === true && t.diffuse === true);
  const unread = read.filter(({ t }) => !t || t.ambient === null || (t.ambient === true && t.diffuse === null));
  const byName = unread.filter(({ s }) => s.role === 'La');
  const list = (xs) => xs.map(({ s }) => trialWords(s, facts)).join('; ');
  if (alone.length) {
    say('pass', `the ambient term has a control of its own (${list(alone)}: the dark side moved, the lit side above it did not)`);
  } else if (byName.length) {
    say('pass', `note: the ambient term's own control is taken from its name (${list(byName)}): its pictures cannot show it moving the dark side alone, where the ambient term alone lights the sphere`);
  } else if (both.length && !unread.length) {
    say('mistake', `${both.length === 1 ? 'one slider moves' : `${both.length} sliders each move`} the ambient and the diffuse term together (${list(both)}) and no slider moves the ambient term alone: the ambient term has no control of its own (ka, or La where ka is kd: the slides' k_a = k_d)`);
  } else if (unread.length) {
    say('pass', `note: whether the ambient term has a control of its own cannot be seen: ${unread.length} slider trial(s) cannot show the dark side (where the ambient term alone lights the sphere) apart from the lit side${both.length ? `, and ${both.length} moved the ambient and the diffuse term together` : ''}`);
  }
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'term-controls', auditTermControls);
