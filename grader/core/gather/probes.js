// What a part's step asks to be tried once the sphere is judged: the faces (the page's own depth,
// culling and winding controls, and a frame with culling off), the highlight (the page's own ks and
// s sliders, and a view farther along the orbit), the sliders, s at its least. Each records the
// pictures it took for the audits; the decisions read the same evidence the audits do.
import { samples, normalColours, facesViewer, shadeFit, highlightSeen, pictureChange } from '../measure.js';
import { nameRole, parameterGroups, describeGroup, sentChanges, sliderActed } from '../controls.js';
import { readSent } from './geometry.js';
import { lightAngle } from '../views.js';
import { highlightIn } from '../evidence.js';
import { searchOrbit } from './orbit.js';

const role = (S, c) => nameRole(c, S.P);
const free = (S, controls, r, pred = () => true) => controls.find((x) => !S.taken.has(x.index) && pred(x) && role(S, x) === r);

/**
 * P2: the page may start with the depth test off or culling on the wrong side: its own controls
 * set as the step ends, until the colours face the viewer (facts.facesImage: the picture after).
 * Then, where the colours are the normals reflected, a frame with culling off (WebGL): the same
 * picture means the nearest faces were showing (facts.noCull; its `draws`, the page's draw calls
 * meanwhile: none, and the picture tells nothing).
 */
export async function probeFaces(S, controls, judged) {
  const { T, facts } = S;
  let { img, an } = judged;
  let nc = normalColours(samples(img, an, T), T);
  if (nc && !facesViewer(nc, T)) {
    for (const [r, want] of [['depth', true], ['cull', true], ['clockwise', false]]) {
      const c = free(S, controls, r);
      if (!c || (c.type === 'checkbox' && c.checked === want)) continue;
      if (!await S.press(c, `the ${r === 'clockwise' ? 'clockwise-front-faces' : r} control`)) continue;
      const s = await S.shot();
      if (!s || s.an.blank) break;
      ({ img, an } = s);
      facts.facesImage = S.keep('faces', img);
      nc = normalColours(samples(img, an, T), T);
      if (facesViewer(nc, T)) break;
    }
  }
  if (nc && nc.det < 0 && nc.residual <= T.facingResidual && facts.api !== 'webgpu') {
    const faces = (await S.page.state()).faces || {};
    facts.noCull = { faces };
    if (faces.depthTest && faces.culling) {
      const before = (await S.page.state()).draws;
      await S.page.setNoCull(true);
      await S.tick(100);
      const s = await S.shot();
      // a page that draws only when a control asks drew nothing here: its picture tells nothing
      facts.noCull.draws = (await S.page.state()).draws - before;
      await S.page.setNoCull(false);
      await S.tick(100);
      if (s) facts.noCull.image = S.keep('no-cull', s.img);
    }
  }
}

/** P2: the depth test and culling as the page set them, its own toggles switched on where they start off. */
export async function probeDepthCulling(S, controls) {
  let faces = (await S.page.state()).faces || {};
  for (const [r, on] of [['depth', 'depthTest'], ['cull', 'culling']]) {
    const c = free(S, controls, r);
    if (faces[on] || !c) continue;
    if (await S.press(c, `the ${r} control`)) faces = (await S.page.state()).faces || {};
  }
  S.facts.faces = faces;
}

/** A slider's least and greatest values (a colour picker's: black and white). */
export const least = (c) => (c.type === 'color' ? '#000000' : Number(c.min || 0));
export const greatest = (c) => (c.type === 'color' ? '#ffffff' : Number(c.max === '' || c.max === undefined ? (c.type === 'range' ? 100 : 1) : c.max));

/** The parameters the page's free sliders set (parameterGroups: ks r, g, b as one). */
export const groupsOf = (S, controls) => parameterGroups(controls.filter((c) => !S.taken.has(c.index)), S.P);

/** Sets every slider of a parameter group (`value(c)` each), on `events`; returns the values set. */
export async function setGroup(S, g, value, events = ['input', 'change']) {
  const vs = g.controls.map(value);
  for (let k = 0; k < vs.length; k++) await S.page.setValue(g.controls[k], vs[k], events);
  return vs;
}

/** A group's entry in facts: its first control, and the others (and their values) where it has more. */
const groupFacts = (g, vs) => ({ control: g.controls[0].index, ...(g.controls.length > 1 ? { controls: g.controls.map((c) => c.index), values: vs, channels: g.channels } : {}) });

/**
 * P4/P5, no highlight seen: the page's own material sliders show it: ks up to its greatest, then s
 * down to 10 (a broad highlight). facts.raised: [{ role, control, value, image, seen }].
 */
export async function raiseHighlight(S, controls) {
  const { T } = S;
  const set = [];
  // s raised to raisedShininess, within the slider's range
  const s10 = (c) => Math.max(Number(c.min || 0) + 1, Math.min(T.raisedShininess, Number(c.max || T.raisedShininess)));
  const raised = S.facts.raised = [];
  const groups = groupsOf(S, controls).filter((g) => g.controls.every((c) => c.type === 'range' || c.type === 'number' || (g.role === 'ks' && c.type === 'color')));
  for (const [r, to] of [['ks', (c) => (c.type === 'color' ? greatest(c) : Number(c.max === '' || c.max === undefined ? 1 : c.max))], ['s', s10]]) {
    const g = groups.find((x) => x.role === r);
    if (!g || raised.some((x) => x.seen)) continue;
    const c = g.controls[0];
    const vs = await setGroup(S, g, to);
    set.push(g);
    await S.tick(100);
    const sh = await S.shot();
    const seen = !!sh && highlightIn(sh.img, T);
    raised.push({ role: r, ...groupFacts(g, vs), value: vs[0], broad: r === 's' && s10(c) < Number(S.now(c)), image: sh ? S.keep(`raised-${r}`, sh.img) : null, seen });
    S.act(`set ${describeGroup(g)} to ${vs[0]} to look for a highlight${seen ? ': one shows' : ''}`);
  }
  for (const g of set) await setGroup(S, g, (c) => S.now(c));
  if (set.length) await S.tick(100);
}

/**
 * P4: each parameter's sliders (one slider, or the three of a colour or vector: parameterGroups)
 * set far from where they are, on input (else change), its picture kept; then back.
 */
export async function trySliders(S, controls) {
  const { T, facts } = S;
  S.step('trying the sliders');
  const base = S.images[facts.shadingImage || facts.judged];
  const groups = groupsOf(S, controls);
  facts.slidersFound = groups.length;
  const animated = facts.sentAnimated, sentBefore = S.moving && animated ? await readSent(S) : null;
  for (const g of groups.slice(0, T.maxSliderTrials)) {
    const k = g.role;
    const target = (c) => {
      if (c.type === 'color') return least(c);
      const lo = Number(c.min || 0), hi = Number(c.max === '' || c.max === undefined ? 100 : c.max);
      return k === 's' ? (Number(S.now(c)) > (lo + hi) / 2 ? lo : hi) : (Number(S.now(c)) > lo ? lo : hi); // s: far from where it is; others: to the least
    };
    const vs = await setGroup(S, g, target, ['input']);
    await S.tick(100);
    let after = await S.page.snap();
    // what the page sent differently (sentChanges) decides where the picture moves by itself
    const sent = { input: sentChanges(sentBefore, await readSent(S), animated), change: null };
    // how much the picture changed on each event tried (the audit decides the event from these);
    // the change event is tried where the input event showed nothing
    const changed = { input: pictureChange(base, after, T), change: null };
    let how = 'input';
    if (!sliderActed({ moving: S.moving, picture: changed.input > T.sliderChange, sent: sent.input })) {
      await setGroup(S, g, target, ['change']);
      await S.tick(100);
      after = await S.page.snap();
      sent.change = sentChanges(sentBefore, await readSent(S), animated);
      changed.change = pictureChange(base, after, T);
      how = sliderActed({ moving: S.moving, picture: changed.change > T.sliderChange, sent: sent.change }) ? 'change' : 'none';
    }
    const r = k && k !== 'levelSlider' ? k : null;
    S.act(`set ${describeGroup(g)} to ${vs[0]} (${how === 'none' ? 'no visible change' : `the picture changed on the ${how} event`})`);
    if (how !== 'none' && k !== 'levelSlider') facts.roles[r || `slider ${Object.keys(facts.roles).length}`] = `${describeGroup(g)}: changes the shading on ${how}`;
    facts.sliders.push({ ...groupFacts(g, vs), role: r, levelSlider: k === 'levelSlider', target: vs[0], how, changed, ...(S.moving && sent.input ? { moving: true, sent } : {}), image: S.keep(`slider-${facts.sliders.length}`, after) });
    // back to where it was (drawn with the next slider's frame, or the last one below)
    await setGroup(S, g, (c) => S.now(c));
  }
  await S.tick(100);
}

/** s at its least (where that is 0 or below): one picture, in the judged view; then s back. */
export async function leastShininess(S, controls) {
  const c = free(S, controls, 's', (x) => x.type === 'range' || x.type === 'number');
  if (!c) return;
  const lo = c.min === '' || c.min === undefined || c.min === null ? 0 : Number(c.min); // a range's min defaults to 0
  if (!(lo <= 0)) return;
  await S.page.setValue(c, lo, ['input', 'change']);
  await S.tick(100);
  const after = await S.page.snap();
  await S.page.setValue(c, S.now(c), ['input', 'change']);
  await S.tick(100);
  if (after) S.facts.leastS = { value: lo, image: S.keep('least-s', after) };
}

/**
 * The highlight's place where the light is at least highlightPlaceLightDegrees from the viewer: the
 * orbit on (with the sliders as they showed the highlight), sampled until such a view shows the
 * highlight over a clean diffuse fit, or orbitSamples positions; then off again.
 */
export async function placeFarther(S, controls) {
  const { T, orbit, facts } = S;
  S.step('looking along the orbit for a view with the light away from the viewer');
  const raised = (facts.raised || []).some((x) => x.seen) ? facts.raised : []; // the sliders as they showed the highlight
  const byIndex = (i) => controls.find((c) => c.index === i);
  const each = async (value) => {
    for (const x of raised) {
      const cs = (x.controls || [x.control]).map(byIndex);
      for (let k = 0; k < cs.length; k++) await S.page.setValue(cs[k], value(x, k, cs[k]), ['input', 'change']);
    }
  };
  await each((x, k) => (x.values ? x.values[k] : x.value));
  let far = { img: null, k: 0 };
  if (await S.tryClick(orbit.start, 'the orbit control', { watchMotion: true }) === 'starts') {
    far = await searchOrbit(S, (img, an) => {
      if (an.blank || an.roundness >= T.orbitCoarseRoundness) return false;
      const f = shadeFit(samples(img, an, T), T);
      return !!f && f.r2 >= T.diffuseR2 && highlightSeen(f, T) && lightAngle(f) >= T.highlightPlaceLightDegrees;
    });
    await S.tryClick(orbit.stop, 'the orbit control again', { watchMotion: true });
  }
  await each((x, k, c) => S.now(c));
  S.act(`sampled the orbit at ${far.k} positions for a view with the light ${T.highlightPlaceLightDegrees}° or more from the viewer${raised.length ? `, ${raised.map((x) => `${x.role} at ${x.value}`).join(' and ')}` : ''}: ${far.img ? 'one shows the highlight' : 'none shows the highlight over a clean diffuse fit'}`);
  facts.placeFarther = { image: far.img ? S.keep('highlight-place', far.img) : null };
}
