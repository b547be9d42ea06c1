// The audit unit 'term-controls' (each term of the Phong model has a control of its own): reads in
// each slider trial which of the model's terms it moved (computed/trial-reading.js: on the page's
// own surface where its pictures are the surface's view, else on the pictures), and says whether
// the ambient term can be set apart from the diffuse one ('term-controls'), and the diffuse term,
// the specular term and the shininess each apart from the others ('own-controls').
import { sliderEvent } from '../../computed/slider-event.js';
import { trialReading } from '../../computed/trial-reading.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'term-controls': { title: 'The ambient term has a control of its own', slide: SLIDE.sliders, failureTitle: 'The ambient term has no control of its own', description: 'Reads in each slider trial what it moved, on the page\'s own surface where the trial\'s pictures are its view, else on the pictures: the ambient term (the dark side) and the diffuse term (the lit side above it). A slider that moves both, where no slider moves the ambient term alone (ka or La), is a review; where the pictures cannot tell, a note says so.', reads: ['facts.sliders', 'facts.roles', 'facts.surface'] },
  'own-controls': { title: 'The diffuse term, the specular term and the shininess each have a control of their own', slide: SLIDE.sliders, failureTitle: 'A term of the Phong model has no control of its own', description: 'Reads in each slider trial what it moved, on the page\'s own surface where the trial\'s pictures are its view (each term and the shininess fitted on the same pixels before and after), else on the pictures (the lit side, and the highlight\'s height above it). The diffuse term must move without the specular one, the specular without the diffuse (its height, k_s L_e), the shininess without the diffuse or the ambient term. Sliders that move a term only together with another: a review naming them; a slider named for the term whose pictures cannot show it: a note.', reads: ['facts.sliders', 'facts.roles', 'facts.surface'] },
};

/** A slider trial in words: its role and what it is ('kd: range "Diffuse #kd"'), and the uniforms it changed where they were read. */
function trialWords(s, facts) {
  const r = Object.values(facts.roles || {}).find((x) => x.control === s.control);
  const what = r && r.what ? r.what : `slider ${s.control}`;
  const sent = s.sent && s.sent.input && s.sent.input.length ? `, which changed ${s.sent.input.join(', ')}` : '';
  return `${s.role ? `${s.role}: ` : ''}${what}${sent}`;
}

/**
 * Each slider trial that acted: { s, r } with r what it moved (computed/trial-reading.js; null where
 * its pictures show no sphere). `exact` is the judged picture's fit on the surface (the surface-fit unit's).
 */
export function readTrials(context, exact = null) {
  const { facts, thresholds } = context;
  return facts.sliders
    .filter((s) => !s.levelSlider && sliderEvent(s, thresholds) !== 'none')
    .map((s) => ({ s, r: trialReading(context, s, exact) }));
}

/**
 * The slides' P4 ("sliders for modifying the different parameters"; L_o = k_d L_i max(cos θ, 0) +
 * k_a L_a, k_a = k_d) asks that the ambient term can be set apart from the diffuse one: by ka, or
 * by La where ka is kd. Each trial that acted is read in its pictures (measure/terms.js); names
 * only break a tie where a picture cannot show the dark side (a slider named for the ambient term).
 */
export function auditTermControls(context, read = readTrials(context)) {
  const { facts, must, sayAs } = context;
  if (!must.has('sliders')) return;
  const say = sayAs('term-controls');
  // alone: the dark side moved and the lit side above it, seen, did not, nor the highlight (but for s: at 0, pow(x, 0) = 1
  // makes the specular term flat, as bright on the dark side as an ambient term); both: it moved
  // both; a trial whose picture cannot show the dark side, or the lit side where the dark side moved, is unread
  const alone = read.filter(({ s, r }) =>
    r && r.ambient === true && r.diffuse === false && r.specular !== true && s.role !== 's');
  const both = read.filter(({ r }) => r && r.ambient === true && r.diffuse === true);
  const unread = read.filter(({ r }) => !r || r.ambient === null || (r.ambient === true && r.diffuse === null));
  const byName = unread.filter(({ s }) => s.role === 'La');
  const list = (xs) => xs.map(({ s }) => trialWords(s, facts)).join('; ');
  if (alone.length) {
    say('pass', `the ambient term has a control of its own (${list(alone)}: ${onWhat(alone)})`);
  } else if (byName.length) {
    say('pass', `note: the ambient term's own control is taken from its name (${list(byName)}): its pictures cannot show it moving the dark side alone, where the ambient term alone lights the sphere`);
  } else if (both.length && !unread.length) {
    say('mistake', `${both.length === 1 ? 'one slider moves' : `${both.length} sliders each move`} the ambient and the diffuse term together (${list(both)}) and no slider moves the ambient term alone: the ambient term has no control of its own (ka, or La where ka is kd: the slides' k_a = k_d)`);
  } else if (unread.length) {
    say('pass', `note: whether the ambient term has a control of its own cannot be seen: ${unread.length} slider trial(s) cannot show the dark side (where the ambient term alone lights the sphere) apart from the lit side${both.length ? `, and ${both.length} moved the ambient and the diffuse term together` : ''}`);
  }
}

/** How a trial's reading was made, in words: where every one of `xs` was read on the surface, or on the pictures. */
function onWhat(xs) {
  if (xs.every(({ r }) => r && r.on === 'surface')) return 'read on the page\'s own surface, the ambient term moved and the diffuse term did not';
  return 'the dark side moved, the lit side above it did not';
}

/** Where all of `xs` were read on the page's own surface, in words. */
const onSurface = (xs) => (xs.every(({ r }) => r.on === 'surface') ? ', on the page\'s own surface' : '');

/** Each term the own-controls audit asks for: the terms that must not move with it, the slider named for it, in words. */
const OWN = [
  { term: 'diffuse', others: ['specular'], name: 'kd', words: 'the diffuse term', moved: 'the diffuse term moved, the specular term did not' },
  { term: 'specular', others: ['diffuse'], name: 'ks', words: 'the specular term', moved: 'the specular term\'s height moved, the diffuse term did not' },
  { term: 'shininess', others: ['diffuse', 'ambient'], name: 's', words: 'the shininess', moved: 'the shininess moved, the diffuse and the ambient term did not' },
];

/**
 * One term's trials (`read`): alone (it moved, the others did not), both (it moved with another),
 * named (a slider named for it whose reading leaves that open: the name breaks the tie), and
 * whether any other trial left it unread. The specular term's height is not set apart by a trial whose
 * shininess moved (or the s slider's): a narrower highlight than the surface's pixels hold reads as
 * a lower one. The ambient term moving with the diffuse one is the slides' k_a = k_d.
 */
function ownOf({ term, others, name }, read) {
  const rs = read.filter(({ r }) => r);
  const spread = ({ s, r }) => term === 'specular' && (r.shininess === true || s.role === 's');
  // a trial named for the term that its reading leaves open: a term unread, or both moved where
  // something was read on the pictures alone (`why`)
  const open = ({ s, r }) => s.role === name && (r[term] === null || others.some((o) => r[o] === null) ||
    (!!r.why && r[term] === true && others.some((o) => r[o] === true)));
  const alone = rs.filter((x) => x.r[term] === true && others.every((o) => x.r[o] === false) && !spread(x));
  const named = rs.filter((x) => open(x) && !alone.includes(x));
  const both = rs.filter((x) => x.r[term] === true && others.some((o) => x.r[o] === true) && !open(x));
  // (a trial that took the highlight away leaves no shininess to read: that is the specular term's, not unread)
  const gone = ({ r }) => term === 'shininess' && r.shininess === null && r.specular === true;
  const unread = read.length > rs.length || rs.some((x) => !open(x) && !gone(x) &&
    (x.r[term] === null || (x.r[term] === true && others.some((o) => x.r[o] === null))));
  return { alone, both, named, unread };
}

/**
 * The slides' P4 asks for sliders for "the different parameters" of L_o = k_a L_a + k_d L_e
 * max(n · w_i, 0) + k_s L_e max(w_r · w_o, 0)^s: each of the diffuse term, the specular term and the
 * shininess can be set apart. A term no trial moved and no slider is named for is not said here
 * (the sliders' audit notes a missing slider).
 */
export function auditOwnControls(context, read = readTrials(context)) {
  const { facts, must, sayAs } = context;
  if (!must.has('sliders')) return;
  const say = sayAs('own-controls');
  const list = (xs) => xs.map(({ s }) => trialWords(s, facts)).join('; ');
  const own = [], named = [];
  for (const t of OWN) {
    const o = ownOf(t, read);
    if (o.alone.length) own.push({ words: t.words, how: `${list(o.alone)}: ${t.moved}${onSurface(o.alone)}` });
    else if (o.named.length) named.push({ t, xs: o.named });
    else if (o.both.length && !o.unread) {
      const moves = o.both.length === 1 ? 'one slider moves' : `${o.both.length} sliders each move`;
      say('mistake', `${moves} ${t.words} only together with the ${t.others.join(' or the ')} term (${list(o.both)}) and no slider moves it apart: ${t.words} has no control of its own (${t.name})`);
    } else if (o.both.length) {
      say('pass', `note: whether ${t.words} has a control of its own cannot be seen: the sliders that move it move the ${t.others.join(' or the ')} term too (${list(o.both)}), and some trial's pictures cannot be read`);
    }
  }
  if (own.length) {
    const names = own.map((o) => o.words), how = own.map((o) => o.how).join('; ');
    say('pass', `${andList(names)} ${names.length > 1 ? 'each have a control of their own' : 'has a control of its own'} (${how})`);
  }
  if (named.length) {
    const terms = andList(named.map(({ t }) => t.words)), one = named.length === 1;
    const why = named.flatMap(({ xs }) => xs).map(({ r }) => r && r.why).find(Boolean);
    say('pass', `note: ${one ? `${terms}'s own control is` : `the own controls of ${terms} are`} taken from ${one ? 'its name' : 'their names'} (${named.map(({ xs }) => list(xs)).join('; ')}): ${one ? 'its' : 'their'} trials cannot show ${one ? 'it' : 'them'} apart from the other terms${why ? ` (${why})` : ''}`);
  }
}

/** Names in words: 'a', 'a and b', 'a, b and c'. */
const andList = (xs) => (xs.length > 1 ? `${xs.slice(0, -1).join(', ')} and ${xs[xs.length - 1]}` : xs[0]);

/** The unit (audits/list.js runs it in its order): the trials read once for both audits, on the judged view's surface fit. */
export const UNIT = unit(META, 'term-controls', (context, results) => {
  const read = context.must.has('sliders') ? readTrials(context, results['surface-fit']) : [];
  if (read.length) context.numbers.sliderTrials = trialsIn(read);
  auditTermControls(context, read);
  auditOwnControls(context, read);
}, { also: ['own-controls'], uses: ['surface-fit'] });

/** Where the trials were read, for the numbers (the benchmark counts them): { read, onSurface, why: { reason: trials } }. */
function trialsIn(read) {
  const why = {};
  for (const { r } of read) {
    const w = !r ? 'its pictures show no sphere' : r.on === 'surface' ? null : r.why;
    if (w) why[w] = (why[w] || 0) + 1;
  }
  return { read: read.length, onSurface: read.filter(({ r }) => r && r.on === 'surface').length, why };
}
