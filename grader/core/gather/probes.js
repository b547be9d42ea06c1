// What a part's step asks to be tried once the sphere is judged: the faces (the page's own depth,
// culling and winding controls, and a frame with culling off), the highlight (the page's own ks and
// s sliders, and a view farther along the orbit), the sliders, s at its least. Each records the
// pictures it took for the audits; the decisions read the same evidence the audits do.
import { samples, normalColours, diffuseFit, highlightSeen, pictureChange } from '../measure.js';
import { nameRole, describe, isValued } from '../controls.js';
import { lightAngle } from '../views.js';
import { searchOrbit } from './orbit.js';

const role = (S, c) => nameRole(c, S.P);
const free = (S, controls, r, pred = () => true) => controls.find((x) => !S.taken.has(x.index) && pred(x) && role(S, x) === r);

/** Do the judged picture's colours show normals facing the viewer? */
export const facesViewer = (nc, T) => !!nc && nc.det >= T.facingDeterminant && nc.residual <= T.facingResidual;

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
  let nc = normalColours(samples(img, an));
  if (nc && !facesViewer(nc, T)) {
    for (const [r, want] of [['depth', true], ['cull', true], ['clockwise', false]]) {
      const c = free(S, controls, r);
      if (!c || (c.type === 'checkbox' && c.checked === want)) continue;
      if (!await S.press(c, `the ${r === 'clockwise' ? 'clockwise-front-faces' : r} control`)) continue;
      const s = await S.shot();
      if (!s || s.an.blank) break;
      ({ img, an } = s);
      facts.facesImage = S.keep('faces', img);
      nc = normalColours(samples(img, an));
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

/**
 * P4/P5, no highlight seen: the page's own material sliders show it: ks up to its greatest, then s
 * down to 10 (a broad highlight). facts.raised: [{ role, control, value, image, seen }].
 */
export async function raiseHighlight(S, controls) {
  const { T } = S;
  const set = [];
  const s10 = (c) => Math.max(Number(c.min || 0) + 1, Math.min(10, Number(c.max || 10)));
  const raised = S.facts.raised = [];
  for (const [r, to] of [['ks', (c) => Number(c.max === '' || c.max === undefined ? 1 : c.max)], ['s', s10]]) {
    const c = free(S, controls, r, (x) => x.type === 'range' || x.type === 'number');
    if (!c || raised.some((x) => x.seen)) continue;
    await S.page.setValue(c, to(c), ['input', 'change']);
    set.push(c);
    await S.tick(100);
    const sh = await S.shot();
    const f = sh && !sh.an.blank ? diffuseFit(samples(sh.img, sh.an), T) : null;
    const seen = !!f && highlightSeen(f, T);
    raised.push({ role: r, control: c.index, value: to(c), broad: r === 's' && s10(c) < Number(c.value), image: sh ? S.keep(`raised-${r}`, sh.img) : null, seen });
    S.act(`set ${describe(c)} to ${to(c)} to look for a highlight${seen ? ': one shows' : ''}`);
  }
  for (const c of set) await S.page.setValue(c, c.value, ['input', 'change']);
  if (set.length) await S.tick(100);
}

/** P4: each slider set far from where it is, on input (else change), its picture kept; then back. */
export async function trySliders(S, controls) {
  const { T, P, facts } = S;
  S.step('trying the sliders');
  const base = S.images[facts.judged];
  const sliders = controls.filter((c) => isValued(c) && c.type !== 'select' && !S.taken.has(c.index));
  facts.slidersFound = sliders.length;
  for (const c of sliders.slice(0, T.maxSliderTrials)) {
    const k = nameRole(c, P);
    const lo = Number(c.min || 0), hi = Number(c.max === '' || c.max === undefined ? 100 : c.max);
    const target = k === 's' ? (Number(c.value) > (lo + hi) / 2 ? lo : hi) : (Number(c.value) > lo ? lo : hi); // s: far from where it is; others: to the least
    await S.page.setValue(c, target, ['input']);
    await S.tick(100);
    let after = await S.page.snap();
    let how = 'input';
    if (pictureChange(base, after) <= T.sliderChange) {
      await S.page.setValue(c, target, ['change']);
      await S.tick(100);
      after = await S.page.snap();
      how = pictureChange(base, after) > T.sliderChange ? 'change' : 'none';
    }
    const r = k && k !== 'levelSlider' ? k : null;
    S.act(`set ${describe(c)} to ${target} (${how === 'none' ? 'no visible change' : `the picture changed on the ${how} event`})`);
    if (how !== 'none' && k !== 'levelSlider') facts.roles[r || `slider ${Object.keys(facts.roles).length}`] = `${describe(c)}: changes the shading on ${how}`;
    facts.sliders.push({ control: c.index, role: r, levelSlider: k === 'levelSlider', target, how, image: S.keep(`slider-${facts.sliders.length}`, after) });
    // back to where it was (drawn with the next slider's frame, or the last one below)
    await S.page.setValue(c, c.value, ['input', 'change']);
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
  await S.page.setValue(c, c.value, ['input', 'change']);
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
  for (const x of raised) await S.page.setValue(byIndex(x.control), x.value, ['input', 'change']);
  let far = { img: null, k: 0 };
  if (await S.tryClick(orbit.start, 'the orbit control', { watchMotion: true }) === 'starts') {
    far = await searchOrbit(S, (img, an) => {
      if (an.blank || an.roundness >= T.orbitCoarseRoundness) return false;
      const f = diffuseFit(samples(img, an), T);
      return !!f && f.r2 >= T.diffuseR2 && highlightSeen(f, T) && lightAngle(f) >= T.highlightPlaceLightDegrees;
    });
    await S.tryClick(orbit.stop, 'the orbit control again', { watchMotion: true });
  }
  for (const x of raised) await S.page.setValue(byIndex(x.control), byIndex(x.control).value, ['input', 'change']);
  S.act(`sampled the orbit at ${far.k} positions for a view with the light ${T.highlightPlaceLightDegrees}° or more from the viewer${raised.length ? `, ${raised.map((x) => `${x.role} at ${x.value}`).join(' and ')}` : ''}: ${far.img ? 'one shows the highlight' : 'none shows the highlight over a clean diffuse fit'}`);
  facts.placeFarther = { image: far.img ? S.keep('highlight-place', far.img) : null };
}
