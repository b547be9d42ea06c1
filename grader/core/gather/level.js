// The level: the controls that make the silhouette finer or coarser (buttons, a slider or menu, or
// keys), found by their effect; then the ladder: down to a coarse level where one is judged (P5),
// and up until the silhouette settles. Every bound is a count (trials, clicks, levels), and a level
// whose frame is heavy work ends the climb once the sphere is nearly round.
import { effectOf, nameRole, named, trialOrder, isClickable, isValued, describe } from '../controls.js';
import { pictureChange, silhouetteChange } from '../measure.js';
import { effectWords } from './session.js';
import { orbitFoundLate } from './orbit.js';

// keys students bind to the level, tried when no control changes it: up/down arrows, + and −, page up/down
const LEVEL_KEYS = [['ArrowUp', 'ArrowDown'], ['+', '-'], ['ArrowRight', 'ArrowLeft'], ['PageUp', 'PageDown']];

/** Buttons (named for the level first); a button that did nothing at the top or bottom level is tried again once the level moved. */
async function levelButtons(S, clickables, levelBy) {
  const { T, P } = S;
  const clickLevel = (c) => () => S.press(c, 'a control');
  const idle = [];
  for (const c of trialOrder(clickables, 'subdivide', P, S.taken).filter((x) => x.type !== 'checkbox')) {
    if (levelBy.subdivide && levelBy.coarsen) break;
    if (S.trialsMade >= T.maxControlTrials && !named(c, 'subdivide', P) && !named(c, 'coarsen', P)) break;
    let effect = S.effects.get(c.index);
    if (effect === undefined || effect === 'none') {
      S.trialsMade++;
      const base = S.cur;
      effect = await S.tryClick(c, 'a control', { watchMotion: !S.R.orbit && S.must.has('diffuse') });
      // a page that starts as round as pixels allow shows one level's change nowhere on the
      // outline: a few more clicks of a button that may be a level control, against the picture before
      for (let k = 0; k < T.levelClicksAgain && (effect === 'shading' || effect === 'none') && [null, 'subdivide', 'coarsen'].includes(nameRole(c, P)); k++) {
        if (!await S.press(c, 'again')) break;
        const now = await S.shot();
        if (!now) break;
        S.cur = now;
        effect = effectOf({ before: base, after: now, later: now, wasMoving: false }, T);
        S.act(`  → ${effectWords[effect]} (against the picture before the first click)`);
      }
      S.effects.set(c.index, effect);
    }
    if (effect === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c, act: clickLevel(c) };
    else if (effect === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c, act: clickLevel(c) };
    else if (effect === 'none' || effect === 'shading') idle.push(c);
    else if (effect === 'starts') await orbitFoundLate(S, c); // an orbit control under a name not known for it
  }
  if ((levelBy.subdivide || levelBy.coarsen) && idle.length) {
    for (const d of idle) {
      if (levelBy.subdivide && levelBy.coarsen) break;
      S.trialsMade++;
      const e = await S.tryClick(d, 'a control', { watchMotion: false });
      if (e === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c: d, act: clickLevel(d) };
      else if (e === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c: d, act: clickLevel(d) };
    }
  }
}

/** A level slider, number input or menu: one that makes the silhouette rounder as it goes up (named for the level first). */
async function levelSliderByEffect(S, valued) {
  const { P } = S;
  for (const c of trialOrder(valued, 'levelSlider', P, S.taken)) {
    const lo = c.type === 'select' ? null : Number(c.min || 0), hi = c.type === 'select' ? null : (c.max === '' || c.max === undefined ? lo + 8 : Number(c.max));
    const values = c.type === 'select' ? (c.options || []) : [lo, Math.min(hi, lo + 1), Math.min(hi, lo + 2)];
    if (values.length < 2 || (!named(c, 'levelSlider', P) && nameRole(c, P) !== null)) continue;
    S.trialsMade++;
    // to its least, then one up: a level control makes the silhouette rounder
    await S.page.setValue(c, values[0], ['input', 'change']);
    await S.tick(S.T.actionTickMs);
    S.cur = await S.shot();
    const effect = await S.trial(async () => { await S.page.setValue(c, values[1], ['input', 'change']); await S.tick(S.T.actionTickMs); return true; }, { watchMotion: false });
    S.act(`set ${describe(c)} from ${values[0]} to ${values[1]} → ${effectWords[effect]}`);
    if (effect === 'finer') {
      S.assign('levelSlider', c, 'rounder-up');
      return c;
    }
    await S.page.setValue(c, c.value, ['input', 'change']); // not the level: back where it was
    await S.tick(S.T.actionTickMs);
    S.cur = await S.shot();
  }
  return null;
}

/** Keys: when nothing on the page changes the level, the arrow keys or + and − may. */
async function levelKeys(S, levelBy) {
  for (const [up, down] of LEVEL_KEYS) {
    const key = (k) => async () => { await S.page.press(k); S.act(`pressed ${k}`); await S.tick(S.T.actionTickMs); return true; };
    const e1 = await S.trial(key(up), { watchMotion: false });
    S.act(`  → ${effectWords[e1]}`);
    const e2 = e1 === 'finer' || e1 === 'none' ? await S.trial(key(down), { watchMotion: false }) : 'none';
    if (e2 !== 'none') S.act(`  → ${effectWords[e2]}`);
    if (e1 !== 'finer' && e2 !== 'coarser') continue;
    if (e1 === 'finer') levelBy.subdivide = { act: key(up) };
    else if (await S.trial(key(up), { watchMotion: false }) === 'finer') levelBy.subdivide = { act: key(up) };
    if (e2 === 'coarser') levelBy.coarsen = { act: key(down) };
    if (levelBy.subdivide) S.facts.roles.subdivide = { key: up, found: 'rounder' };
    if (levelBy.coarsen) S.facts.roles.coarsen = { key: down, found: 'coarser' };
    if (levelBy.subdivide) {
      await levelBy.subdivide.act(); // back up where the down key took it
      S.cur = await S.shot();
      return;
    }
  }
}

/** Finds the level controls: S.level = { subdivide, coarsen } ({ act }) and S.levelSlider. */
export async function findLevel(S, controls) {
  const { P } = S;
  S.step('looking for the level controls');
  const clickables = controls.filter(isClickable), valued = controls.filter(isValued);
  const levelBy = S.level = {};
  const stopped = !S.moving;
  S.levelSlider = null;
  if (stopped) {
    await levelButtons(S, clickables, levelBy);
    for (const role of ['subdivide', 'coarsen']) if (levelBy[role]) S.assign(role, levelBy[role].c, role === 'subdivide' ? 'rounder' : 'coarser');
    if (!levelBy.subdivide) S.levelSlider = await levelSliderByEffect(S, valued);
    if (!levelBy.subdivide && !S.levelSlider) await levelKeys(S, levelBy);
  } else {
    // the picture never stood still: the level controls are taken by their names (the ladder
    // shows whether the sphere gets rounder)
    for (const c of clickables) {
      const role = nameRole(c, P);
      if ((role === 'subdivide' || role === 'coarsen') && !levelBy[role] && !S.taken.has(c.index)) levelBy[role] = { c, act: () => S.press(c, 'a control') };
    }
    for (const role of ['subdivide', 'coarsen']) if (levelBy[role]) S.assign(role, levelBy[role].c, 'by-name');
    const c = levelBy.subdivide ? null : valued.find((x) => !S.taken.has(x.index) && nameRole(x, P) === 'levelSlider');
    if (c) {
      S.levelSlider = c;
      S.assign('levelSlider', c, 'by-name');
    }
  }
  S.facts.level = { subdivide: !!levelBy.subdivide, coarsen: !!levelBy.coarsen, slider: !!S.levelSlider, stopped, trials: S.trialsMade, valued: valued.length };
}

/**
 * The ladder: coarsen to the bottom (P5's coarse level), then subdivide until the silhouette
 * settles or is as round as pixels allow. Each level's picture is kept (level-k) with its work a frame.
 */
export async function climb(S) {
  const { T, level: levelBy } = S;
  S.step('subdividing until the sphere is round');
  const ladder = [S.cur];
  let last = S.cur;
  const step = async (how, bound, settled, up = false) => {
    const got = [];
    for (let k = 0; k < bound; k++) {
      if (!await how.act()) break;
      const s = await S.shot();
      if (!s) break;
      const isDone = settled(last, s);
      last = s;
      got.push(s);
      if (isDone) break;
      // a level whose frame is heavy work ends the climb once the sphere is nearly round: the next
      // has four times the triangles, and a click cannot be stopped once it runs
      if (up && S.frameWork >= T.heavyLevelWork && !s.an.blank && s.an.roundness <= T.roundEnoughWhenHeavy) {
        S.facts.heavyLevel = Math.round(S.frameWork);
        break;
      }
    }
    return got;
  };
  const same = (a, b) => pictureChange(a.img, b.img, T) <= T.pictureChanged;
  // settled: the silhouette no longer changes, or it is as round as pixels allow (a teacher stops there too)
  const settledSilhouette = (a, b) => silhouetteChange(a.an, b.an) <= T.silhouetteSettled || (!b.an.blank && b.an.roundness <= T.roundEnough);
  let coarsened = false;
  // (down first only where a coarse level is judged: P5's highlight per fragment)
  if (levelBy.coarsen && !S.moving && S.must.has('per-fragment')) {
    const down = await step(levelBy.coarsen, T.maxCoarsenings, (a, b) => same(a, b) || b.an.blank || b.an.roundness > 2 * T.coarseRoundness);
    if (down.length) ladder[0] = down[down.length - 1];
    coarsened = down.length > 0;
  }
  if (levelBy.subdivide) {
    ladder.push(...await step(levelBy.subdivide, T.maxSubdivisions + (coarsened ? T.maxCoarsenings : 0), settledSilhouette, true));
  } else if (S.levelSlider) {
    // a level slider or <select> (which may start at level 0): stepped from its least up, as
    // Subdivide is clicked, until the silhouette settles (at most maxSubdivisions steps)
    const c = S.levelSlider;
    const values = [];
    if (c.type === 'select') values.push(...(c.options || []).slice(0, T.maxSubdivisions + 1));
    else {
      const lo = Number(c.min || 0), hi = Math.min(c.max === '' || c.max === undefined ? 8 : Number(c.max), lo + T.maxSubdivisions);
      for (let v = lo; v <= hi; v++) values.push(v);
    }
    ladder.length = 0;
    for (const v of values) {
      await S.page.setValue(c, v, ['input', 'change']);
      await S.tick(S.T.actionTickMs);
      const s = await S.shot();
      const settled = ladder.length && settledSilhouette(ladder[ladder.length - 1], s);
      ladder.push(s);
      if (settled) break;
    }
    S.act(`set the level ${c.type === 'select' ? 'menu' : 'slider'} from ${values[0]} up to ${values[ladder.length - 1]}`);
  }
  S.ladder = ladder;
  S.cur = ladder[ladder.length - 1];
}
