// The level: the controls that make the silhouette finer or coarser (buttons, a slider or menu, or
// keys), found by their effect; then the ladder: down to a coarse level where one is judged (P5),
// and up until the silhouette settles. Every bound is a count (trials, clicks, levels), and a level
// whose frame is heavy work ends the climb once the sphere is nearly round.
import { effectOf, nameRole, named, trialOrder, isClickable, isValued, describe } from '../controls.js';
import { pictureChange, silhouetteChange } from '../measure.js';
import { effectWords } from './session.js';
import { orbitFoundLate } from './orbit.js';
import { readSurface } from './geometry.js';

// keys students bind to the level, tried when no control changes it: up/down arrows, + and −, page up/down
const LEVEL_KEYS = [['ArrowUp', 'ArrowDown'], ['+', '-'], ['ArrowRight', 'ArrowLeft'], ['PageUp', 'PageDown']];

/**
 * A level slider's or number input's values from its least up, `steps` steps at most: [min … max].
 * Without a max the page sets no top, and the count of steps is the only bound (an <input
 * type=range> without one runs to HTML's 100, far past any level the climb reaches).
 */
export function levelValues(c, steps) {
  const lo = Number(c.min || 0), hi = c.max === '' || c.max === undefined ? Infinity : Number(c.max);
  const values = [];
  for (let v = lo; v <= Math.min(hi, lo + steps); v++) values.push(v);
  return values;
}

/** Buttons (named for the level first); a button that did nothing at the top or bottom level is tried again once the level moved. */
async function levelButtons(session, clickables, levelBy) {
  const { thresholds, patterns } = session;
  const clickLevel = (c) => () => session.press(c, 'a control');
  const idle = [];
  for (const c of trialOrder(clickables, 'subdivide', patterns, session.taken).filter((x) => x.type !== 'checkbox')) {
    if (levelBy.subdivide && levelBy.coarsen) break;
    if (session.trialsMade >= thresholds.maxControlTrials && !named(c, 'subdivide', patterns) && !named(c, 'coarsen', patterns)) break;
    let effect = session.effects.get(c.index);
    if (effect === undefined || effect === 'none') {
      session.trialsMade++;
      const base = session.cur;
      effect = await session.tryClick(c, 'a control', { watchMotion: !session.roles.orbit && session.must.has('diffuse') });
      // a page that starts as round as pixels allow shows one level's change nowhere on the
      // outline: a few more clicks of a button that may be a level control, against the picture before
      const mayBeLevel = () => [null, 'subdivide', 'coarsen'].includes(nameRole(c, patterns));
      for (let k = 0; k < thresholds.levelClicksAgain && (effect === 'shading' || effect === 'none') && mayBeLevel(); k++) {
        if (!await session.press(c, 'again')) break;
        const now = await session.shot();
        if (!now) break;
        session.cur = now;
        effect = effectOf({ before: base, after: now, later: now, wasMoving: false }, thresholds);
        session.act(`  → ${effectWords[effect]} (against the picture before the first click)`);
      }
      session.effects.set(c.index, effect);
    }
    if (effect === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c, act: clickLevel(c) };
    else if (effect === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c, act: clickLevel(c) };
    else if (effect === 'none' || effect === 'shading') idle.push(c);
    else if (effect === 'starts') await orbitFoundLate(session, c); // an orbit control under a name not known for it
  }
  if ((levelBy.subdivide || levelBy.coarsen) && idle.length) {
    for (const d of idle) {
      if (levelBy.subdivide && levelBy.coarsen) break;
      session.trialsMade++;
      const e = await session.tryClick(d, 'a control', { watchMotion: false });
      if (e === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c: d, act: clickLevel(d) };
      else if (e === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c: d, act: clickLevel(d) };
    }
  }
}

/** A level slider, number input or menu: one that makes the silhouette rounder as it goes up (named for the level first). */
async function levelSliderByEffect(session, valued) {
  const { patterns } = session;
  for (const c of trialOrder(valued, 'levelSlider', patterns, session.taken)) {
    const values = c.type === 'select' ? (c.options || []) : levelValues(c, 1);
    if (values.length < 2 || (!named(c, 'levelSlider', patterns) && nameRole(c, patterns) !== null)) continue;
    session.trialsMade++;
    // to its least, then one up: a level control makes the silhouette rounder
    await session.page.setValue(c, values[0], ['input', 'change']);
    await session.tick(session.thresholds.actionTickMs);
    session.cur = await session.shot();
    const effect = await session.trial(
      async () => {
        await session.page.setValue(c, values[1], ['input', 'change']);
        await session.tick(session.thresholds.actionTickMs);
        return true;
      },
      { watchMotion: false },
    );
    session.act(`set ${describe(c)} from ${values[0]} to ${values[1]} → ${effectWords[effect]}`);
    if (effect === 'finer') {
      session.assign('levelSlider', c, 'rounder-up');
      return c;
    }
    await session.page.setValue(c, c.value, ['input', 'change']); // not the level: back where it was
    await session.tick(session.thresholds.actionTickMs);
    session.cur = await session.shot();
  }
  return null;
}

/** Keys: when nothing on the page changes the level, the arrow keys or + and − may. */
async function levelKeys(session, levelBy) {
  for (const [up, down] of LEVEL_KEYS) {
    const key = (k) => async () => {
      await session.page.press(k);
      session.act(`pressed ${k}`);
      await session.tick(session.thresholds.actionTickMs);
      return true;
    };
    const e1 = await session.trial(key(up), { watchMotion: false });
    session.act(`  → ${effectWords[e1]}`);
    const e2 = e1 === 'finer' || e1 === 'none' ? await session.trial(key(down), { watchMotion: false }) : 'none';
    if (e2 !== 'none') session.act(`  → ${effectWords[e2]}`);
    if (e1 !== 'finer' && e2 !== 'coarser') continue;
    if (e1 === 'finer') levelBy.subdivide = { act: key(up) };
    else if (await session.trial(key(up), { watchMotion: false }) === 'finer') levelBy.subdivide = { act: key(up) };
    if (e2 === 'coarser') levelBy.coarsen = { act: key(down) };
    if (levelBy.subdivide) session.facts.roles.subdivide = { key: up, found: 'rounder' };
    if (levelBy.coarsen) session.facts.roles.coarsen = { key: down, found: 'coarser' };
    if (levelBy.subdivide) {
      await levelBy.subdivide.act(); // back up where the down key took it
      session.cur = await session.shot();
      return;
    }
  }
}

/**
 * Buttons that change how much the page draws a frame: a subdivision draws four times the triangles
 * of the level before, a coarsening a quarter. Each click's frame is held to the frame before it
 * (the vertices it drew, session.frameVertices), so a page that never stands still, or whose mesh
 * grows a little every frame, shows its level controls all the same. Named for the level first;
 * the rubric's maxControlTrials bounds the clicks.
 */
async function levelButtonsByDraws(session, clickables, levelBy) {
  const { thresholds, patterns } = session;
  const ratio = thresholds.levelWorkRatio;
  let tried = 0;
  for (const c of trialOrder(clickables, 'subdivide', patterns, session.taken).filter((x) => x.type !== 'checkbox')) {
    if ((levelBy.subdivide && levelBy.coarsen) || tried >= thresholds.maxControlTrials) break;
    tried++;
    const before = session.frameVertices;
    if (!await session.press(c, 'a control') || !(before > 0)) continue;
    const after = session.frameVertices;
    const role = after >= ratio * before ? 'subdivide' : after * ratio <= before ? 'coarsen' : null;
    session.act(`  → the page draws ${Math.round(before)} → ${Math.round(after)} vertices a frame${role ? ` (${role === 'subdivide' ? 'finer' : 'coarser'})` : ''}`);
    if (!role || levelBy[role]) continue;
    levelBy[role] = { c, act: () => session.press(c, 'a control') };
    session.assign(role, c, role === 'subdivide' ? 'more-drawn' : 'less-drawn');
  }
}

/** Finds the level controls: session.level = { subdivide, coarsen } ({ act }) and session.levelSlider. */
export async function findLevel(session, controls) {
  const { patterns } = session;
  session.step('looking for the level controls');
  const clickables = controls.filter(isClickable), valued = controls.filter(isValued);
  const levelBy = session.level = {};
  const stopped = !session.moving;
  session.levelSlider = null;
  if (stopped) {
    await levelButtons(session, clickables, levelBy);
    for (const role of ['subdivide', 'coarsen']) if (levelBy[role]) session.assign(role, levelBy[role].c, role === 'subdivide' ? 'rounder' : 'coarser');
    if (!levelBy.subdivide) session.levelSlider = await levelSliderByEffect(session, valued);
    if (!levelBy.subdivide && !session.levelSlider) await levelKeys(session, levelBy);
  } else {
    // the picture never stood still: the level controls are found by what a click changes in the
    // page's draws, whatever the picture does, and else taken by their names (the ladder shows
    // whether the sphere gets rounder)
    await levelButtonsByDraws(session, clickables, levelBy);
    for (const c of clickables) {
      const role = nameRole(c, patterns);
      if ((role === 'subdivide' || role === 'coarsen') && !levelBy[role] && !session.taken.has(c.index)) {
        levelBy[role] = { c, act: () => session.press(c, 'a control') };
        session.assign(role, c, 'by-name');
      }
    }
    const c = levelBy.subdivide ? null : valued.find((x) => !session.taken.has(x.index) && nameRole(x, patterns) === 'levelSlider');
    if (c) {
      session.levelSlider = c;
      session.assign('levelSlider', c, 'by-name');
    }
  }
  session.facts.level = {
    subdivide: !!levelBy.subdivide,
    coarsen: !!levelBy.coarsen,
    slider: !!session.levelSlider,
    stopped,
    trials: session.trialsMade,
    valued: valued.length,
  };
}

/**
 * P5 on a still page: the surface of the first level of the ladder coarse enough to show per vertex
 * against per fragment (the level the per-fragment audit compares: coarseRoundness), read while the
 * page shows it (`s`, the ladder's level `k`), as facts.coarseSurface ({ level, surface }).
 */
async function coarseSurface(session, s, k) {
  const { facts, thresholds } = session;
  if (!session.must.has('per-fragment') || session.moving || facts.coarseSurface) return;
  if (!s || s.an.blank || !(s.an.roundness < thresholds.coarseRoundness)) return;
  const surface = await readSurface(session, 'coarse-');
  if (surface) facts.coarseSurface = { level: k, surface };
}

/**
 * The ladder: coarsen to the bottom (P5's coarse level), then subdivide until the silhouette
 * settles or is as round as pixels allow. Each level's picture is kept (level-k) with its work a
 * frame; on P5 the first level coarse enough to compare, its surface too (coarseSurface).
 */
export async function climbLevelLadder(session) {
  const { thresholds, level: levelBy } = session;
  session.step('subdividing until the sphere is round');
  const ladder = [session.cur];
  let last = session.cur;
  const step = async (how, bound, settled, up = false) => {
    const got = [];
    for (let k = 0; k < bound; k++) {
      if (!await how.act()) break;
      const s = await session.shot();
      if (!s) break;
      if (up) await coarseSurface(session, s, ladder.length + got.length);
      const isDone = settled(last, s);
      last = s;
      got.push(s);
      if (isDone) break;
      // a level whose frame is heavy work ends the climb once the sphere is nearly round: the next
      // has four times the triangles, and a click cannot be stopped once it runs
      if (
        up &&
        session.frameWork >= thresholds.heavyLevelWork &&
        !s.an.blank &&
        s.an.roundness <= thresholds.roundEnoughWhenHeavy
      ) {
        session.facts.heavyLevel = Math.round(session.frameWork);
        break;
      }
    }
    return got;
  };
  const same = (a, b) => pictureChange(a.img, b.img, thresholds) <= thresholds.pictureChanged;
  // settled: the silhouette no longer changes, or it is as round as pixels allow (a teacher stops there too)
  const settledSilhouette = (a, b) =>
    silhouetteChange(a.an, b.an) <= thresholds.silhouetteSettled ||
    (!b.an.blank && b.an.roundness <= thresholds.roundEnough);
  let coarsened = false;
  // (down first only where a coarse level is judged: P5's highlight per fragment)
  if (levelBy.coarsen && !session.moving && session.must.has('per-fragment')) {
    const down = await step(
      levelBy.coarsen,
      thresholds.maxCoarsenings,
      (a, b) => same(a, b) || b.an.blank || b.an.roundness > 2 * thresholds.coarseRoundness,
    );
    if (down.length) ladder[0] = down[down.length - 1];
    coarsened = down.length > 0;
  }
  if (levelBy.subdivide) {
    await coarseSurface(session, ladder[0], 0);
    ladder.push(
      ...(await step(
        levelBy.subdivide,
        thresholds.maxSubdivisions + (coarsened ? thresholds.maxCoarsenings : 0),
        settledSilhouette,
        true,
      )),
    );
  } else if (session.levelSlider) {
    // a level slider or <select> (which may start at level 0): stepped from its least up, as
    // Subdivide is clicked, until the silhouette settles (at most maxSubdivisions steps)
    const c = session.levelSlider;
    const values = c.type === 'select' ? (c.options || []).slice(0, thresholds.maxSubdivisions + 1)
      : levelValues(c, thresholds.maxSubdivisions);
    ladder.length = 0;
    for (const v of values) {
      await session.page.setValue(c, v, ['input', 'change']);
      await session.tick(session.thresholds.actionTickMs);
      const s = await session.shot();
      await coarseSurface(session, s, ladder.length);
      const settled = ladder.length && settledSilhouette(ladder[ladder.length - 1], s);
      ladder.push(s);
      if (settled) break;
    }
    session.act(`set the level ${c.type === 'select' ? 'menu' : 'slider'} from ${values[0]} up to ${values[ladder.length - 1]}`);
  }
  session.ladder = ladder;
  session.cur = ladder[ladder.length - 1];
}
