// Bringing a part to a state and judging it, as a teacher does by hand: wait for its first
// frame, find its controls by what they do (controls.js), stop or sample the orbit, coarsen and
// subdivide until the sphere is round, try the sliders, then judge the pictures by what the
// slide's step asks (judge.js) and say each finding (verdict.js). It drives the page only through
// the page interface (playwright-page.js for the grader, the check page's frame driver):
//   state(), snap(), controls(), click(c), setValue(c, v, events), press(key), tick(ms, frames),
//   sources(), errors()
// and runs in Node and in a browser alike (no Node modules; images are { width, height, data }).
import { analyse, samples, normalColours, diffuseFit, silhouetteChange, shadingChange, pictureChange, pointLightFit, perspectiveSamples, darkSpots,
  highlightAbove, highlightSeen, highlightOffset, nearPointLight, clearlyBetter, clearlyNearFalloff } from './measure.js';
import { describe, nameRole, named, effectOf, trialOrder, isClickable, isValued } from './controls.js';
import { checkList } from './verdict.js';

const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));
const SLIDERS = ['kd', 'ks', 's', 'Le', 'La'];
// keys students bind to the level, tried when no control changes it: up/down arrows, + and −, page up/down
const LEVEL_KEYS = [['ArrowUp', 'ArrowDown'], ['+', '-'], ['ArrowRight', 'ArrowLeft'], ['PageUp', 'PageDown']];

/**
 * Grades one opened part. `page` is the page interface; `rubric` the grader's rubric; `part`
 * WP04P1 … WP04P5. Returns { fail, checks, actions, controls, numbers, images, api, canvas, timing, busy }:
 * `fail` (a reason) when the part cannot be judged at all (nothing drawn, no canvas), `checks` the
 * findings ({ level, reason }), `images` the pictures taken (first, judged, coarse, leastS),
 * `timing` where the time went (`timing`, filled as it goes when given), `busy` the milliseconds
 * spent letting the page draw. `progress(text)` hears what is being tried.
 */
export async function gradePart(page, { part, rubric, progress = () => {}, deadline = Infinity, timing = {} }) {
  const T = rubric.thresholds;
  const must = new Set((rubric.parts[part] || {}).must || []);
  const { checks, say } = checkList(rubric);
  const out = { fail: null, checks, actions: [], controls: {}, numbers: {}, images: {}, api: null, canvas: null, timing,
    get busy() { return timing.tick ? timing.tick.ms : 0; } };
  page = timed(page, timing);
  const actions = out.actions;
  let frameMs = 16; // what a frame of this page costs here, from the last frames run
  // a jump: the frame it fires draws a change made in a click or input handler (on a software
  // renderer a frame can cost a second: a page that draws each triangle on its own); `frames` more
  // at 60 Hz where motion is watched
  const tick = async (ms, frames = 0) => {
    const t0 = Date.now();
    await page.tick(ms, frames);
    const took = Date.now() - t0;
    frameMs = Math.max(1, took / (frames + 1));
  };
  const shot = async () => {
    const img = await page.snap();
    return img && { img, an: analyse(img, T) };
  };
  const done = (fail) => Object.assign(out, { fail });
  // a slow page gets the rubric's time: past `deadline` the optional looking stops, and the part is
  // judged on what was seen, with what was left out said
  const started = Date.now();
  // `share`: the part of the time this looking may use (the orbit's samples leave time for the controls)
  const late = (what, share = 1) => {
    if (Date.now() <= started + share * (deadline - started)) return false;
    if (!out.cutShort.includes(what)) out.cutShort.push(what);
    return true;
  };
  out.cutShort = [];

  // ---- the first frame ----
  progress('waiting for the first frame');
  await tick(1000, 1);
  // a page may start drawing only after promises that take real time (shaders fetched, a WebGPU
  // adapter and device): wait for its first draw call, within firstFrameSeconds
  const waitUntil = Date.now() + (rubric.firstFrameSeconds ?? 10) * 1000;
  for (let k = 0; Date.now() < waitUntil; k++) {
    const s = await page.state();
    if (s.draws > 0 && (s.api !== 'webgpu' || s.frames > 0)) break;
    if (s.adapter === null || s.shaderErrors.length || (!s.api && k >= 20)) break;
    if (k >= 10 && page.errors().some((e) => /^(page error|dialog)/.test(e))) break; // it threw or alerted: no need to wait longer
    await new Promise((resolve) => setTimeout(resolve, 100));
    await tick(16); // one frame: the orbit's phase should depend on the machine's load as little as can be
  }
  const g = await page.state();
  out.api = g.api;
  const firstShot = await shot();
  if (!firstShot) return done('no canvas on the page');
  const first = firstShot.img;
  out.canvas = { width: first.width, height: first.height };
  out.images.first = first;
  for (const e of g.shaderErrors) say('fail', e);
  if (g.api === 'webgpu' && g.adapter === null) say('fail', 'no WebGPU adapter: the page could not start WebGPU');
  const firstAn = firstShot.an;
  if (firstAn.blank) {
    const why = g.shaderErrors[0] || g.gpuErrors[0] || page.errors().find((e) => /page error|dialog/.test(e));
    if (!g.api) return done(`drew nothing: the page never got a WebGL or WebGPU context${why ? ` (${why})` : ''}`);
    if (!g.draws) return done(`drew nothing: the canvas is one colour, no draw call${why ? ` (${why})` : ''}`);
    return done(`drew nothing visible: the canvas is one colour${why ? ` (${why})` : ''}`);
  }

  // ---- the controls: found by what they do, names only order the trials and name them ----
  const controls = await page.controls();
  const P = rubric.controls;
  const R = {}; // role → control (or a key pair for the level)
  const effects = new Map(); // control index → the effect seen when it was tried
  const taken = new Set();
  const assign = (role, c, how) => {
    if (R[role]) return;
    R[role] = c;
    taken.add(c.index);
    out.controls[role] = `${describe(c)}${c.events && c.events.length ? ` (listens: ${c.events.join(', ')})` : ''}: ${how}`;
  };
  let cur = firstShot; // the picture as it is now
  let moving = false; // does the picture move by itself now?
  const press = async (c, what) => {
    const r = await page.click(c);
    if (!r.ok) {
      actions.push(`could not click ${what} ${describe(c)}: ${r.why}`);
      return false;
    }
    actions.push(`clicked ${what} ${describe(c)}`);
    await tick(100);
    return true;
  };
  /** Tries one action from the state as it is and says what it did to the picture. */
  const trial = async (act, { watchMotion = true } = {}) => {
    const before = cur;
    if (!await act()) return 'unclickable';
    const after = await shot();
    if (!after) return 'none';
    let later = after;
    if (watchMotion || moving) {
      await tick(400, 2); // three frames: an orbit a small step a frame shows it moved
      later = await shot();
    }
    const effect = effectOf({ before, after, later, wasMoving: moving }, T);
    cur = later;
    if (effect === 'starts') moving = true;
    if (effect === 'stops') moving = false;
    return effect;
  };
  const tryClick = async (c, what, opts) => {
    const effect = await trial(() => press(c, what), opts);
    if (effect !== 'unclickable') effects.set(c.index, effect);
    if (effect !== 'unclickable') actions.push(`  → ${effectWords[effect]}`);
    return effect;
  };
  const clickables = controls.filter(isClickable);
  const valued = controls.filter(isValued);
  const shadedPart = must.has('diffuse');
  const maxTrials = T.maxControlTrials ?? 12;
  let trials = 0;

  // ---- the orbit: is the picture moving? sample it where lit, then stop it; or start it ----
  await tick(500, 2); // three frames, as above
  const second = await shot();
  moving = pictureChange(cur.img, second.img) > 0.001;
  cur = second;
  const movedAtFirst = moving;
  let orbitToggles = false;
  const orbitFits = []; // the diffuse fit at each lit orbit position seen
  const viewFits = []; // ... and at every lit view seen (the first one too)
  const views = []; // every lit view: { img, an, fit }, to look for the highlight in
  const look = (im, orbiting = true, keep = true) => { // is the view lit? lit views' fits are kept
    const a = analyse(im, T);
    if (a.blank) return false;
    const fit = diffuseFit(samples(im, a, { max: 1500 }), T);
    // lit: a clear spread of brightness, or a clean diffuse fit with a clear diffuse term (a light
    // from the eye's side spreads brightness little over the disc: n·w_i from 0.5 to 1 in the samples)
    const lit = fit && a.roundness < T.orbitCoarseRoundness && (fit.spread >= T.litSpread * 1.5 ||
      (fit.spread >= T.litSpread / 2 && fit.r2 >= T.diffuseR2 && fit.diffuse >= T.diffuseMin));
    if (lit && keep) {
      viewFits.push(fit);
      views.push({ img: im, an: a, fit });
      if (orbiting) orbitFits.push(fit);
    }
    return !!lit;
  };
  if (shadedPart) look(first, false);
  let orbitLater = false; // the orbit is sampled after the level ladder
  let orbitStart = null, orbitStop = null; // the controls that start and stop it, where found
  // the k-th orbit sample's time, in frames as the page can afford them: a page that takes a second a frame gets a few
  const tickOrbit = (k) => tick(T.orbitSampleSeconds * 1000,
    Math.max(2, Math.min(8 << k, Math.round(60 * T.orbitSampleSeconds), Math.floor((T.orbitSampleBudgetSeconds ?? 3) * 1000 / frameMs))));
  const sampleOrbit = async (afterLadder = false) => {
    // the light may be behind the sphere at first: look along the orbit (a few positions at least)
    // to see the lit side turn with the orbit (a light fixed in the world); many pages turn the
    // camera a fixed step per frame, or per setInterval tick: each sample runs more frames as the
    // search goes on, so such an orbit gets round too
    // a silhouette too coarse to read the shading from (a tetrahedron at level 0) shows nothing lit
    // anywhere on the orbit: looked at once the sphere is round, after the level ladder
    if (!afterLadder && cur.an.roundness >= T.orbitCoarseRoundness) {
      orbitLater = true;
      return;
    }
    progress('sampling the orbit');
    let k = 0, im = cur.img;
    for (; k < T.orbitSamples && (!look(im) || k < 2) && !late('more orbit positions', 0.4); k++) {
      await tickOrbit(k);
      im = await page.snap();
    }
    cur = { img: im, an: analyse(im, T) };
    actions.push(`sampled the orbit at ${k} positions ${fmt(T.orbitSampleSeconds, 1)} s apart (${orbitFits.length} lit)`);
  };
  if (moving) {
    actions.push('the picture moves by itself (an orbit or animation)');
    if (shadedPart) await sampleOrbit();
    // the control that stops it: named for the orbit first, then the others
    progress('looking for the control that stops the orbit');
    for (const c of trialOrder(clickables, 'orbit', P, taken).slice(0, maxTrials)) {
      if (late('more controls for the orbit')) break;
      trials++;
      const effect = await tryClick(c, 'a control', { watchMotion: true });
      if (effect === 'stops') {
        assign('orbit', c, 'the picture stopped moving');
        orbitToggles = true;
        orbitStart = orbitStop = c;
        break;
      }
    }
  } else if (shadedPart) {
    // the orbit may be off at first: a control that starts it (named for it first; a start and a stop button)
    progress('looking for the control that starts the orbit');
    const named_ = trialOrder(clickables, 'orbit', P, taken).filter((c) => named(c, 'orbit', P));
    for (const c of named_) {
      trials++;
      const effect = await tryClick(c, 'a control', { watchMotion: true });
      if (effect === 'starts') {
        await sampleOrbit();
        // the same control (a toggle) or another (a stop button) stops it
        for (const s of [c, ...named_.filter((x) => x !== c)]) {
          const e = await tryClick(s, 'a control', { watchMotion: true });
          if (e === 'stops') {
            assign('orbit', c, s === c ? 'starts and stops the picture moving' : `starts the picture moving (${describe(s)} stops it)`);
            orbitToggles = true;
            orbitStart = c;
            orbitStop = s;
            break;
          }
        }
        if (!orbitToggles) assign('orbit', c, 'starts the picture moving; nothing found stops it');
        break;
      }
    }
  }
  const stopped = !moving;

  // ---- the level: controls that make the silhouette finer or coarser ----
  progress('looking for the level controls');
  const levelBy = {}; // 'subdivide' | 'coarsen' → { act, name }
  const clickLevel = (c) => async () => press(c, 'a control');
  if (stopped) {
    // buttons (named for the level first); a button that did nothing at the top or bottom level is tried again once the level moved
    const order = [...trialOrder(clickables, 'subdivide', P, taken)].filter((c) => c.type !== 'checkbox');
    const idle = [];
    for (const c of order) {
      if (levelBy.subdivide && levelBy.coarsen) break;
      if (late('more controls for the level')) break;
      if (trials >= maxTrials && !named(c, 'subdivide', P) && !named(c, 'coarsen', P)) break;
      let effect = effects.get(c.index);
      if (effect === undefined || effect === 'none') {
        trials++;
        const base = cur;
        effect = await tryClick(c, 'a control', { watchMotion: !R.orbit && shadedPart });
        // a page that starts as round as pixels allow shows one level's change nowhere on the
        // outline: a few more clicks of a button that may be a level control, against the picture before
        for (let k = 0; k < 3 && (effect === 'shading' || effect === 'none') && [null, 'subdivide', 'coarsen'].includes(nameRole(c, P)) && !late('more clicks for the level'); k++) {
          if (!await press(c, 'again')) break;
          const now = await shot();
          if (!now) break;
          cur = now;
          effect = effectOf({ before: base, after: now, later: now, wasMoving: false }, T);
          actions.push(`  → ${effectWords[effect]} (against the picture before the first click)`);
        }
        effects.set(c.index, effect);
      }
      if (effect === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c, act: clickLevel(c) };
      else if (effect === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c, act: clickLevel(c) };
      else if (effect === 'none' || effect === 'shading') idle.push(c);
      else if (effect === 'starts') { // an orbit control found here, under a name not known for it: sampled, then stopped again
        if (shadedPart && !R.orbit) await sampleOrbit();
        const again = await tryClick(c, 'a control', { watchMotion: true });
        if (!R.orbit) {
          assign('orbit', c, again === 'stops' ? 'starts and stops the picture moving' : 'starts the picture moving; nothing found stops it');
          orbitToggles = again === 'stops';
          if (orbitToggles) orbitStart = orbitStop = c;
        }
      }
      if ((levelBy.subdivide || levelBy.coarsen) && idle.length) {
        for (const d of idle.splice(0)) {
          if (levelBy.subdivide && levelBy.coarsen) break;
          trials++;
          const e = await tryClick(d, 'a control', { watchMotion: false });
          if (e === 'finer' && !levelBy.subdivide) levelBy.subdivide = { c: d, act: clickLevel(d) };
          else if (e === 'coarser' && !levelBy.coarsen) levelBy.coarsen = { c: d, act: clickLevel(d) };
        }
      }
    }
    for (const role of ['subdivide', 'coarsen']) if (levelBy[role]) assign(role, levelBy[role].c, `the silhouette got ${role === 'subdivide' ? 'rounder' : 'coarser'}`);
  }
  // the picture never stood still: the level controls are taken by their names (the ladder below
  // shows whether the sphere gets rounder)
  if (!stopped) {
    for (const c of clickables) {
      const role = nameRole(c, P);
      if ((role === 'subdivide' || role === 'coarsen') && !levelBy[role] && !taken.has(c.index)) levelBy[role] = { c, act: clickLevel(c) };
    }
    for (const role of ['subdivide', 'coarsen']) if (levelBy[role]) assign(role, levelBy[role].c, 'by its name (the picture kept moving)');
  }
  // a level slider, number input or menu: one that changes the silhouette (named for the level first)
  let levelSlider = null;
  if (!stopped && !levelBy.subdivide) {
    const c = valued.find((x) => !taken.has(x.index) && nameRole(x, P) === 'levelSlider');
    if (c) {
      levelSlider = c;
      assign('levelSlider', c, 'by its name (the picture kept moving)');
    }
  }
  if (stopped && !levelBy.subdivide) {
    for (const c of trialOrder(valued, 'levelSlider', P, taken)) {
      const lo = c.type === 'select' ? null : Number(c.min || 0), hi = c.type === 'select' ? null : (c.max === '' || c.max === undefined ? lo + 8 : Number(c.max));
      const values = c.type === 'select' ? (c.options || []) : [lo, Math.min(hi, lo + 1), Math.min(hi, lo + 2)];
      if (values.length < 2 || (!named(c, 'levelSlider', P) && nameRole(c, P) !== null)) continue;
      trials++;
      // to its least, then one up: a level control makes the silhouette rounder
      await page.setValue(c, values[0], ['input', 'change']);
      await tick(100);
      cur = await shot();
      const effect = await trial(async () => { await page.setValue(c, values[1], ['input', 'change']); await tick(100); return true; }, { watchMotion: false });
      actions.push(`set ${describe(c)} from ${values[0]} to ${values[1]} → ${effectWords[effect]}`);
      if (effect === 'finer') {
        levelSlider = c;
        assign('levelSlider', c, 'the silhouette got rounder as it went up');
        break;
      }
      await page.setValue(c, c.value, ['input', 'change']); // not the level: back where it was
      await tick(100);
      cur = await shot();
    }
  }
  // keys: when nothing on the page changes the level, the arrow keys or + and − may
  if (stopped && !levelBy.subdivide && !levelSlider) {
    for (const [up, down] of LEVEL_KEYS) {
      const key = (k) => async () => { await page.press(k); actions.push(`pressed ${k}`); await tick(100); return true; };
      const e1 = await trial(key(up), { watchMotion: false });
      actions.push(`  → ${effectWords[e1]}`);
      const e2 = e1 === 'finer' || e1 === 'none' ? await trial(key(down), { watchMotion: false }) : 'none';
      if (e2 !== 'none') actions.push(`  → ${effectWords[e2]}`);
      if (e1 === 'finer' || e2 === 'coarser') {
        if (e1 === 'finer') levelBy.subdivide = { act: key(up) };
        else if (e2 === 'coarser') {
          const e3 = await trial(key(up), { watchMotion: false });
          if (e3 === 'finer') levelBy.subdivide = { act: key(up) };
        }
        if (e2 === 'coarser') levelBy.coarsen = { act: key(down) };
        if (levelBy.subdivide) out.controls.subdivide = `the ${up} key: the silhouette got rounder`;
        if (levelBy.coarsen) out.controls.coarsen = `the ${down} key: the silhouette got coarser`;
        if (levelBy.subdivide) {
          if (levelBy.subdivide) await levelBy.subdivide.act(); // back up where the down key took it
          cur = await shot();
          break;
        }
      }
    }
  }

  // ---- the level ladder: coarsen to the bottom (P5), then subdivide until the silhouette settles ----
  progress('subdividing until the sphere is round');
  let last = cur;
  // A level that took seconds to draw ends the climb once the sphere is nearly round: the next has
  // four times the triangles, and a click cannot be stopped once it runs (a page that builds its
  // arrays by concat took 7 s at level 5, minutes at level 6)
  let slowLevel = null;
  const step = async (how, bound, settled, up = false) => {
    const got = [];
    for (let k = 0; k < bound; k++) {
      if (late('more levels')) break;
      const t0 = Date.now();
      if (!await how.act()) break;
      const took = (Date.now() - t0) / 1000;
      const s = await shot();
      if (!s) break;
      const isDone = settled(last, s);
      last = s;
      got.push(last);
      if (isDone) break;
      if (up && took >= T.slowLevelSeconds && !s.an.blank && s.an.roundness <= T.roundEnoughWhenSlow) {
        slowLevel = took;
        break;
      }
    }
    return got;
  };
  const same = (a, b) => pictureChange(a.img, b.img) <= 0.0005;
  // settled: the silhouette no longer changes, or it is already as round as pixels allow (a
  // teacher stops there too; the levels above cost seconds a click on slow pages)
  const settledSilhouette = (a, b) => silhouetteChange(a.an, b.an) <= T.silhouetteSettled || (!b.an.blank && b.an.roundness <= T.roundEnough);
  let ladder = [last];
  let coarsened = false;
  // (down first only where a coarse level is judged: P5's highlight per fragment)
  if (levelBy.coarsen && stopped && must.has('perFragment')) {
    const down = await step(levelBy.coarsen, T.maxCoarsenings, (a, b) => same(a, b) || b.an.blank || b.an.roundness > 2 * T.coarseRoundness);
    ladder = [down.length ? down[down.length - 1] : last];
    coarsened = down.length > 0;
  }
  if (levelBy.subdivide) {
    ladder.push(...await step(levelBy.subdivide, T.maxSubdivisions + (coarsened ? T.maxCoarsenings : 0), settledSilhouette, true));
    if (slowLevel) say('pass', `note: slow: the last level reached took ${fmt(slowLevel, 1)} s to draw; with the sphere round to ${fmt(100 * last.an.roundness, 1)}% there, no finer level was tried (each has four times the triangles)`);
  } else if (levelSlider) {
    // a level slider or <select> (which may start at level 0): stepped from its least up, as
    // Subdivide is clicked, until the silhouette settles (at most maxSubdivisions steps)
    const c = levelSlider;
    const values = [];
    if (c.type === 'select') values.push(...(c.options || []).slice(0, T.maxSubdivisions + 1));
    else {
      const lo = Number(c.min || 0), hi = Math.min(c.max === '' || c.max === undefined ? 8 : Number(c.max), lo + T.maxSubdivisions);
      for (let v = lo; v <= hi; v++) values.push(v);
    }
    ladder = [];
    for (const v of values) {
      if (ladder.length && late('more levels')) break;
      await page.setValue(c, v, ['input', 'change']);
      await tick(100);
      const s = await shot();
      const settled = ladder.length && settledSilhouette(ladder[ladder.length - 1], s);
      ladder.push(s);
      if (settled) break;
    }
    actions.push(`set the level ${c.type === 'select' ? 'menu' : 'slider'} from ${values[0]} up to ${values[ladder.length - 1]}`);
  }
  // the orbit looked at where the shading can be read: on again, sampled, off again; the view it
  // stops at is judged (the same level)
  // Only where it buys evidence: the judged view is unlit, or the step asks for the orbit (P3: the
  // lit side turning with it). Elsewhere the judged view stays, so that the sliders and a coarse
  // level are compared with it in the same view.
  let viewMoved = false;
  if (orbitLater && shadedPart && (must.has('orbitToggle') || !look(ladder[ladder.length - 1].img, false, false)) && !late('the orbit at the finest level', 0.5)) {
    const at = ladder.length - 1;
    if (!stopped) {
      await sampleOrbit(true);
      ladder[at] = cur;
      viewMoved = true;
    } else if (orbitStart && orbitStop && await tryClick(orbitStart, 'the orbit control again', { watchMotion: true }) === 'starts') {
      viewMoved = true;
      await sampleOrbit(true);
      if (await tryClick(orbitStop, 'the orbit control again', { watchMotion: true }) === 'stops') ladder[at] = cur;
      else say('review', 'the orbit did not stop again: the pictures were judged as it moves');
    }
  }
  // a page that goes blank at a higher level (a buffer too small, an index type too narrow) is
  // judged at the last level it drew, and the blank level is a mistake
  let judged = ladder[ladder.length - 1];
  if (judged.an.blank) {
    const drawn = ladder.filter((x) => !x.an.blank);
    if (drawn.length) {
      judged = drawn[drawn.length - 1];
      say('mistake', 'the picture goes blank at a higher level: judged at the last level that drew');
    }
  }
  let img = judged.img;
  let an = judged.an;
  out.images.judged = img;
  const hasLevel = !!(levelBy.subdivide || levelSlider);
  if (must.has('subdivideControls')) {
    if (hasLevel) say('pass', `has controls to subdivide (${out.controls.subdivide || out.controls.levelSlider})`);
    else if (!stopped) say('review', 'the level controls could not be looked for: the picture never stood still');
    else say('review', `nothing found that makes the sphere finer: ${trials} controls tried${valued.length ? ', sliders and menus stepped' : ''}, and the arrow, + and − keys pressed (the slide asks for Subdivide and Coarsen buttons)`);
    if (levelBy.subdivide && !levelBy.coarsen && !levelSlider) say('review', 'nothing found that makes the sphere coarser (the slide asks for a Coarsen button too)');
  }

  // ---- the sphere ----
  if (an.blank) return done('the picture went blank after the controls were used');
  Object.assign(out.numbers, { radius: an.radius, roundness: an.roundness, fill: an.fill, coverage: an.coverage, firstRoundness: firstAn.roundness,
    levelsSeen: ladder.length });
  // a dark unlit side on a dark background: the outline is the lit edge's circle
  const circ = an.circle;
  if (!(an.roundness <= T.roundness && an.fill >= T.fill) && circ && circ.roundness <= T.roundness && circ.arc >= 180 && !an.touches) {
    an = { ...an, cx: circ.cx, cy: circ.cy, radius: circ.r, roundness: circ.roundness, fill: 1 };
    say('pass', `part of the sphere is as dark as the background: its outline was fitted to the lit edge (${circ.arc}° of a circle)`);
  }
  if (an.radius < T.minRadiusPixels) say('review', `the sphere is very small on screen (${fmt(an.radius, 0)} px radius): hard to judge`);
  else if (an.roundness <= T.roundness && an.fill >= T.fill) {
    say('pass', `a round closed sphere (radius ${fmt(an.radius, 0)} px, roundness ${fmt(an.roundness, 3)})`);
  } else if (an.touches) say('review', 'the object touches the canvas edge: its silhouette cannot be judged');
  else say('mistake', `the object is not a round closed sphere (roundness ${fmt(an.roundness, 3)}, fill ${fmt(an.fill)}${ladder.length > 1 ? ', after subdividing' : ''})`);
  if (ladder.length > 2) {
    const rs = ladder.map((s) => s.an.roundness).filter((r) => Number.isFinite(r));
    if (rs[0] > rs[rs.length - 1] + 0.02) say('pass', `rounder with each level (roundness ${fmt(rs[0], 3)} → ${fmt(rs[rs.length - 1], 3)})`);
  }

  // ---- P1/P2: the normals as colours ----
  if (must.has('normalColours') || must.has('frontFaces')) {
    let nc = normalColours(samples(img, an));
    const judgeFaces = () => nc && nc.det >= T.facingDeterminant && nc.residual <= T.facingResidual;
    if (must.has('frontFaces') && nc && !judgeFaces()) {
      // the page may start with the depth test off or culling on the wrong side: set them as the step ends
      for (const [role, want] of [['depth', true], ['cull', true], ['clockwise', false]]) {
        const c = controls.find((x) => !taken.has(x.index) && nameRole(x, P) === role);
        if (!c || (c.type === 'checkbox' && c.checked === want)) continue;
        if (!await press(c, `the ${role === 'clockwise' ? 'clockwise-front-faces' : role} control`)) continue;
        const s = await shot();
        if (!s || s.an.blank) break;
        ({ img, an } = s);
        nc = normalColours(samples(img, an));
        out.images.judged = img;
        if (judgeFaces()) break;
      }
    }
    // a reflection of the sphere's normals is the inside of the far side (the front faces culled), or
    // the faces nearest a viewer who looks along +z (clip space, no view matrix): the depth order
    // tells. With the depth test on and culling off the nearest faces show: if the picture stays,
    // they were what showed
    let nearest = null;
    if (must.has('frontFaces') && nc && nc.det < 0 && nc.residual <= T.facingResidual && g.api !== 'webgpu') {
      const faces = (await page.state()).faces || {};
      if (faces.depthTest && faces.culling) {
        await page.setNoCull(true);
        await tick(100);
        const s = await shot();
        await page.setNoCull(false);
        await tick(100);
        const nc2 = s && !s.an.blank ? normalColours(samples(s.img, s.an)) : null;
        nearest = nc2 ? nc2.det < 0 && pictureChange(s.img, img) <= 0.01 : null;
        actions.push(`drew a frame with back-face culling off (depth test on): ${nearest ? 'the same picture' : 'another picture'}`);
      } else if (faces.depthTest) nearest = true;
    }
    out.numbers.normals = nc;
    if (!nc) say('mistake', 'too little of the sphere to read its colours');
    else if (nc.spread < T.normalsSpread) say('mistake', 'the sphere is one colour: the normals are not used for the colour (0.5·n + 0.5)');
    else if (nc.unitError > T.normalsUnitError) {
      say('mistake', `the colours are not 0.5·n + 0.5: 2c − 1 is not a unit vector (off by ${fmt(nc.unitError)} on average)`);
    } else say('pass', `colours decode to unit normals 2c − 1 (off by ${fmt(nc.unitError, 3)})`);
    if (must.has('frontFaces') && nc && nc.spread >= T.normalsSpread) {
      if (judgeFaces()) say('pass', 'the visible colours are the normals facing the viewer: front faces only');
      else if (nearest) say('pass', 'the visible faces are the nearest ones (the depth test is on, and culling off draws the same picture): the view looks along +z (clip space without a view matrix?), so their normals point away from +z');
      else if (nc.det < 0 && nc.residual <= T.facingResidual) say('mistake', 'the inside of the far side shows (the normals face away from the viewer): the front faces are culled, or the depth test is off and the far side is drawn last');
      else say('mistake', `back faces show through the front (normals do not vary smoothly across the picture, misfit ${fmt(nc.residual)}): depth test or culling missing`);
    }
  }

  // ---- P2: the depth test and back-face culling enabled (the slide: "no visible effect of the back face culling") ----
  if (must.has('depthCulling')) {
    let faces = (await page.state()).faces || {};
    // a page may offer them as toggles that start off: switched on as the step ends
    for (const [role, on] of [['depth', 'depthTest'], ['cull', 'culling']]) {
      const c = controls.find((x) => !taken.has(x.index) && nameRole(x, P) === role);
      if (faces[on] || !c) continue;
      if (await press(c, `the ${role} control`)) faces = (await page.state()).faces || {};
    }
    const api = g.api === 'webgpu' ? { depth: 'depthStencil with a depthCompare', cull: "cullMode: 'back'" } : { depth: 'gl.enable(gl.DEPTH_TEST)', cull: 'gl.enable(gl.CULL_FACE)' };
    out.numbers.faces = faces;
    if (faces.depthTest) say('pass', `the depth test is enabled (${api.depth})`);
    else say('mistake', `the depth test is never enabled (${api.depth}): the slide asks for it`);
    if (faces.culling) say('pass', `back-face culling is enabled (${api.cull}${faces.cullMode && faces.cullMode !== 'back' ? `, culling ${faces.cullMode} faces` : ''})`);
    else say('mistake', `back-face culling is never enabled (${api.cull}): the slide asks for it, though it shows no visible effect`);
  }

  // ---- P3–P5: the reflection model ----
  let fit = null, pointLight = null;
  if (must.has('diffuse') || must.has('highlight')) {
    fit = diffuseFit(samples(img, an), T);
    if (fit && fit.spread >= T.litSpread) {
      pointLight = pointLightFit(perspectiveSamples(img, an, T.pointLightFovy, { max: 1500 }), { ...T, around: fit.light });
      if (pointLight) out.numbers.pointLight = pointLight;
    }
    out.numbers.fit = fit && { r2: fit.r2, ambient: fit.ambient, diffuse: fit.diffuse, light: fit.light, highlightPeak: fit.highlightPeak, highlightRise: fit.highlightRise, spread: fit.spread };
    // lit on both sides shows where the light comes from the side: any view seen on the orbit
    // (or over all pixels: a crescent lit from behind is left out of the first fit as if a highlight; on
    // a page lit one-sided, |n·w_i| never explains all pixels better, it lights the dark side)
    const twoSided = [fit, ...viewFits].filter(Boolean).find((f) => (f.r2TwoSided > f.r2 + 0.03 && f.r2 < 0.97) ||
      (f.r2TwoSidedAll > f.r2All + 0.015 && f.r2TwoSidedAll >= T.diffuseR2));
    if (!fit) say('mistake', 'too little of the sphere to read its shading');
    else if (fit.spread < T.litSpread / 2) say('mistake', `the sphere is evenly bright: no diffuse shading to see (in ${1 + viewFits.length} views${orbitFits.length ? ' along the orbit' : ''})`);
    else if (twoSided) {
      say('mistake', `the sphere is lit on both sides: brightness follows |n·w_i| (R² ${fmt(twoSided.r2TwoSided)}), not max(n·w_i, 0) (R² ${fmt(twoSided.r2)})`);
    } else if (!must.has('highlight') && orbitFits.length && Math.min(...orbitFits.map((f) => f.r2)) < T.diffuseR2 - 0.1) {
      const worst = orbitFits.reduce((a, b) => (b.r2 < a.r2 ? b : a));
      say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient at every orbit position (R² down to ${fmt(worst.r2)}): lit where it should be dark?`);
    } else if (fit.r2 >= T.diffuseR2 && fit.diffuse >= T.diffuseMin) {
      say('pass', `brightness follows max(n·w_i, 0)·kd·Le + ambient (R² ${fmt(fit.r2)}, fitted light ${fit.light.map((v) => fmt(v)).join(', ')})`);
    } else if (nearPointLight(pointLight, T) && fit.diffuse >= T.diffuseMin) {
      const f = pointLight[nearPointLight(pointLight, T)];
      say('pass', `brightness follows max(n·w_i, 0)·kd·L_i + ambient for a point light ${fmt(f.distance, 1)} radii from the centre (R² ${fmt(f.r2)})`);
    } else say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient for any light direction (R² ${fmt(fit.r2)})`);
  }
  if (shadedPart && orbitFits.length >= 2) {
    const angle = (a, b) => (180 / Math.PI) * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
    let turn = 0;
    for (let i = 1; i < orbitFits.length; i++) turn = Math.max(turn, angle(orbitFits[0].light, orbitFits[i].light));
    out.numbers.lightTurn = turn;
    // on a sphere only the shading shows the orbit: where the step asks for the orbit (P3) a light that
    // moves with the camera hides it; elsewhere the slides leave the light's space to the student
    if (turn < T.lightTurnDegrees) {
      say(must.has('orbitToggle') ? 'review' : 'pass', `${must.has('orbitToggle') ? 'the orbit does not show in the shading: ' : 'note: '}while the camera orbits, the lit side stays where it is on screen (the fitted light turns ${fmt(turn, 1)}° over ${orbitFits.length} views): the light moves with the camera (given in eye space, or light and normals in different spaces?)`);
    } else say('pass', `the lit side turns as the camera orbits (${fmt(turn, 0)}° over ${orbitFits.length} views): the light stays in the world`);
  }
  if (must.has('orbitToggle')) {
    if (orbitToggles) say('pass', `a control toggles the orbit on and off (${out.controls.orbit})`);
    else if (R.orbit) say('review', `${describe(R.orbit)} starts the orbit, but nothing found stops it`);
    else if (movedAtFirst) say('review', `the camera orbits, but no button toggles the orbit: none of the ${trials} controls tried stops it (the slide asks for one)`);
    else say('review', 'no orbit: the picture never moved, and no control named for the orbit starts it');
  }
  if (pointLight) {
    if (clearlyBetter(pointLight, 'none', 'falloff', T)) {
      say('review', `point light without the 1/r² fall-off: brightness fits a light ${fmt(pointLight.none.distance, 1)} radii from the centre with no fall-off (R² ${fmt(pointLight.none.r2, 3)}) better than with L_i = I/‖p_ℓ − x‖² (R² ${fmt(pointLight.falloff.r2, 3)})`);
    } else if (clearlyBetter(pointLight, 'falloff', 'none', T)) {
      say('pass', `a point light ${fmt(pointLight.falloff.distance, 1)} radii from the centre, with the 1/r² fall-off (R² ${fmt(pointLight.falloff.r2, 3)}; without it ${fmt(pointLight.none.r2, 3)})`);
    }
  }
  // a near point light with 1/r² makes a bright spot a directional fit reads as a highlight: then the
  // highlight is what rises above the point-light model (a page without a specular term has none)
  const nearModel = clearlyNearFalloff(pointLight, T) ? pointLight.falloff.model : null;
  if (fit && nearModel) Object.assign(fit, { highlightPeak: pointLight.falloff.highlightPeak, highlightRise: pointLight.falloff.highlightRise });
  // a lit orbit view's diffuse fit over all its samples (look() fitted a sparser 1500), once
  const fullFit = (v) => (v.fullFit === undefined ? (v.fullFit = diffuseFit(samples(v.img, v.an), T)) : v.fullFit);
  const lightAngle = (f) => (180 / Math.PI) * Math.acos(Math.max(-1, Math.min(1, f.light[2]))); // the light's angle from the viewer (+z)
  let raised = []; // [control, value]: the page's own sliders as set to show the highlight (where they showed it)
  let placeLater = null; // the highlight's place, seen only with the light near the viewer: looked for farther along the orbit at the end
  if (must.has('highlight') && fit) {
    // not seen where judged: the other lit views seen on the orbit may show it (a highlight on the rim, or behind)
    let seen = highlightSeen(fit, T) ? { fit, where: 'the judged view' } : null;
    if (!seen && !nearModel) {
      const other = views.map((v) => ({ fit: fullFit(v), img: v.img })).find((v) => v.fit && highlightSeen(v.fit, T));
      if (other) seen = { fit: other.fit, where: `one of ${views.length} lit views along the orbit` };
    }
    // ... or the page's own material controls show it: ks up to its greatest, then s down (a broad highlight)
    if (!seen && !nearModel && !late('raising ks to look for a highlight')) {
      const ctl = (role) => controls.find((x) => !taken.has(x.index) && (x.type === 'range' || x.type === 'number') && nameRole(x, P) === role);
      const set = [];
      const s10 = (c) => Math.max(Number(c.min || 0) + 1, Math.min(10, Number(c.max || 10)));
      for (const [role, to] of [['ks', (c) => Number(c.max === '' || c.max === undefined ? 1 : c.max)], ['s', s10]]) {
        const c = ctl(role);
        if (!c || seen) continue;
        await page.setValue(c, to(c), ['input', 'change']);
        set.push(c);
        raised.push([c, to(c)]);
        await tick(100);
        const sh = await shot();
        const f = sh && !sh.an.blank ? diffuseFit(samples(sh.img, sh.an), T) : null;
        actions.push(`set ${describe(c)} to ${to(c)} to look for a highlight${f && highlightSeen(f, T) ? ': one shows' : ''}`);
        if (f && highlightSeen(f, T)) seen = { fit: f, broad: set.some((x) => nameRole(x, P) === 's' && s10(x) < Number(x.value)), where: `the judged view with ${set.map((x) => nameRole(x, P)).join(' and ')} set by the page's own slider${set.length > 1 ? 's' : ''}` };
      }
      for (const c of set) await page.setValue(c, c.value, ['input', 'change']);
      if (set.length) await tick(100);
      if (!seen) raised = [];
    }
    out.numbers.highlightViews = 1 + views.length;
    if (seen) say('pass', `a specular highlight in ${seen.where} (up to ${fmt(100 * seen.fit.highlightPeak, 0)}% of the way from the diffuse fit to white, ${fmt(seen.fit.highlightRise, 2)} above it)`);
    // where it is: at w_h, halfway between the light and the viewer (the slides' w_r · w_o peaks there
    // too). w_h and w_i are half the light's angle from the viewer apart, so a view with the light
    // well away from the viewer tells them apart best: of the views that show the highlight over a
    // clean diffuse fit (the light is read from it), the one with the light farthest from the viewer.
    // Not where we lowered s: a highlight made broad by s = 10 is half taken into the diffuse fit,
    // which then reads the light (and w_h) toward it
    if (seen && !nearModel) {
      const clean = (f) => f.r2 >= T.diffuseR2;
      let place = seen.broad ? null : seen;
      for (const v of views) {
        const f = fullFit(v);
        if (f && highlightSeen(f, T) && clean(f) && (!place || !clean(place.fit) || lightAngle(f) > lightAngle(place.fit))) place = { fit: f, where: 'a lit view along the orbit' };
      }
      if (!place) say('pass', 'note: the highlight\'s place is not judged: it shows only with s lowered to 10 by the page\'s own slider, which makes it too broad to place');
      // the light this near the viewer puts w_h near w_i too: farther along the orbit (at the end, where
      // moving the view changes nothing else judged) a view may tell them apart
      else if (lightAngle(place.fit) < T.highlightPlaceLightDegrees && orbitStart && orbitStop && stopped) placeLater = place;
      else judgePlace(place);
    }
    if (!seen) say('mistake', `no specular highlight: nothing brighter than the diffuse fit (${fmt(fit.highlightPeak)}) in ${1 + views.length} views (the judged one${views.length ? ' and the lit ones along the orbit' : ''})`);
  }

  // ---- P4: the sliders: those that change the material or light on the input event ----
  if (must.has('sliders')) {
    progress('trying the sliders');
    const looked = (rubric.parts[part] || {}).sliders || SLIDERS;
    const required = (rubric.parts[part] || {}).requiredSliders || [];
    const sliders = valued.filter((c) => c.type !== 'select' && !taken.has(c.index));
    const base = img;
    const baseFit = fit;
    let inputOk = 0, changeOnly = 0, dead = 0;
    const found = {};
    for (const c of sliders) {
      if (late('the rest of the sliders')) break;
      const k = nameRole(c, P);
      const lo = Number(c.min || 0), hi = Number(c.max === '' || c.max === undefined ? 100 : c.max);
      const target = k === 's' ? (Number(c.value) > (lo + hi) / 2 ? lo : hi) : (Number(c.value) > lo ? lo : hi); // s: far from where it is; others: to the least
      await page.setValue(c, target, ['input']);
      await tick(100);
      let after = await page.snap();
      let how = 'input';
      if (pictureChange(base, after) <= T.sliderChange) {
        await page.setValue(c, target, ['change']);
        await tick(100);
        after = await page.snap();
        how = pictureChange(base, after) > T.sliderChange ? 'change' : 'none';
      }
      const a = analyse(after, T);
      const role = k && k !== 'levelSlider' ? k : null;
      actions.push(`set ${describe(c)} to ${target} (${how === 'none' ? 'no visible change' : `the picture changed on the ${how} event`})`);
      // (a darker material may merge the unlit side with the background: the silhouette may change too)
      if (how !== 'none' && k !== 'levelSlider') {
        if (role && !found[role]) found[role] = c;
        out.controls[role || `slider ${Object.keys(out.controls).length}`] = `${describe(c)}: changes the shading on ${how}`;
        if (how === 'input') inputOk++;
        else changeOnly++;
      } else if (how === 'none') dead++;
      if (how !== 'none' && baseFit && role === 'ks') {
        // the highlight left with ks at its least: above the base picture's near point-light model (its
        // 1/r² spot stays and is no highlight), or above the after picture's own directional fit
        const f = a.blank ? null : nearModel ? { highlightPeak: highlightAbove(perspectiveSamples(after, an, T.pointLightFovy, { max: 1500 }), nearModel, T) }
          : diffuseFit(samples(after, a), T);
        if (f && f.highlightPeak >= baseFit.highlightPeak * 0.5 && f.highlightPeak >= T.highlightPeak) {
          say('review', `ks at ${target} leaves the highlight as it was (${fmt(f.highlightPeak)}): is ks used in the specular term?`);
        }
      }
      // back to where it was (drawn with the next slider's frame, or the last one below)
      await page.setValue(c, c.value, ['input', 'change']);
    }
    await tick(100);
    const named_ = Object.keys(found);
    const missing = looked.filter((k) => !found[k]);
    const cut = out.cutShort.includes('the rest of the sliders');
    if (cut && !inputOk && !changeOnly) say('pass', `note: the sliders were not tried: the rubric's time ran out (${sliders.length} found)`);
    else if (inputOk) say('pass', `${inputOk} slider(s) change the material or light on the input event${named_.length ? ` (${named_.join(', ')})` : ''}`);
    else if (changeOnly) say('review', `${changeOnly} slider(s) update the picture only on the change event, not while sliding (the slide asks for the input event)`);
    else say('review', `no slider changes the material or light (${sliders.length} tried; the slide asks for sliders for the parameters)`);
    if (inputOk && changeOnly) say('review', `${changeOnly} slider(s) update the picture only on the change event, not while sliding (the slide asks for the input event)`);
    const requiredMissing = required.filter((k) => !found[k]);
    if (requiredMissing.length) say('review', `no slider found for ${requiredMissing.join(', ')} (this rubric asks for each)`);
    else if (missing.length && inputOk) say('pass', `note: no slider found for ${missing.join(', ')}`);
    if (must.has('sliderEffects') && dead) say('pass', `note: ${dead} slider(s) change nothing in the picture`);
  }

  if (must.has('highlight') && fit && stopped) {
    const sCtl = controls.find((c) => !taken.has(c.index) && (c.type === 'range' || c.type === 'number') && nameRole(c, P) === 's');
    if (sCtl && !late('s at its least')) await judgeShininessZero(sCtl);
  }

  // ---- P5: the highlight per fragment, seen at a coarse level ----
  if (must.has('perFragment') && fit) {
    const coarse = stopped && !viewMoved ? ladder.find((s) => !s.an.blank && s.an.roundness < T.coarseRoundness && s !== judged) : null;
    const src = await page.sources();
    const fs = src.glsl.filter((s) => /gl_FragColor|out\s+vec4/.test(s) && !/gl_Position/.test(s));
    // a WGSL fragment entry point and the functions it calls
    const wg = src.wgsl.map((s) => {
      const body = s.split(/@fragment/)[1] || '';
      const called = [...body.matchAll(/([A-Za-z_]\w*)\s*\(/g)].map((m) => m[1]);
      return body + called.map((name) => (s.split(new RegExp(`fn\\s+${name}\\s*\\(`))[1] || '').split(/\n}\s*\n/)[0]).join('\n');
    });
    const frag = [...fs, ...wg].some((s) => /pow\s*\(/.test(s));
    if (coarse && coarse.img.width === judged.img.width) {
      const change = shadingChange(coarse.img, coarse.an, judged.img, judged.an);
      out.numbers.coarseShadingChange = change;
      out.images.coarse = coarse.img;
      if (change !== null && change <= T.phongCoarseChange) say('pass', `the shading at a coarse level (roundness ${fmt(coarse.an.roundness)}) stays as smooth as at the finest (RMS ${fmt(change, 3)}): per fragment`);
      else say('mistake', `the highlight follows the triangles at a coarse level (RMS ${fmt(change, 3)} from the finest): shading is per vertex, not per fragment (or the normals are not re-normalised in the fragment shader)`);
    } else if (frag) say('pass', `no coarse level to compare${levelBy.coarsen ? '' : ' (nothing found that coarsens)'}; the fragment shader evaluates the specular term (pow): per fragment`);
    else say('mistake', 'no coarse level to compare, and no pow() in the fragment shader: the model seems evaluated per vertex');
  }
  if (placeLater) await placeFarther(placeLater);
  if (!stopped) say('pass', 'note: the orbit could not be stopped: the pictures were judged as it moves');
  if (out.cutShort.length) say('pass', `note: slow: the rubric's time ran out before ${out.cutShort.join(', ')}; judged on what was seen`);
  return out;

  /** Says whether the highlight sits at w_h in `place` ({ fit, where }), the light's angle from the viewer given. */
  function judgePlace(place) {
    const offset = highlightOffset(place.fit.highlightNormal, place.fit.light);
    if (offset === null) return;
    Object.assign(out.numbers, { highlightOffset: offset, highlightPlaceLight: lightAngle(place.fit) });
    const near = lightAngle(place.fit) < T.highlightPlaceLightDegrees;
    const where = `in ${place.where}, the light ${fmt(lightAngle(place.fit), 0)}° from the viewer`;
    const light = place.fit.light.map((v) => fmt(v)).join(', ');
    const ask = 'is w_o the direction from the surface to the eye, in the same space as n and w_i?';
    // w_h is half the light's angle from w_i: with the light well away from the viewer, a highlight
    // clearly nearer the light than w_h is at the light (w_o or w_r wrong), even within the bound above
    const fromLight = highlightOffset(place.fit.highlightNormal, place.fit.light, 0);
    out.numbers.highlightFromLight = fromLight;
    if (!near && offset - fromLight >= T.highlightAtLightDegrees) say('mistake', `the highlight sits at the light, not halfway between the light and the viewer: ${fmt(fromLight, 0)}° from the light, ${fmt(offset, 0)}° from the halfway normal (the light fitted at ${light}; ${where}): ${ask}`);
    else if (offset > T.highlightPlaceDegrees) say('mistake', `the highlight is ${fmt(offset, 0)}° from where the model puts it (at the normal halfway between the light, fitted at ${light}, and the viewer; ${where}): ${ask}`);
    else say('pass', `the highlight sits where the normal is halfway between the light and the viewer (${fmt(offset, 0)}° off, ${where}${near ? `; with the light this near the viewer that halfway normal is only ${fmt(lightAngle(place.fit) / 2, 0)}° from the light, so a highlight at the light would pass too` : ''})`);
  }

  /**
   * The highlight's place where the light is at least highlightPlaceLightDegrees from the viewer:
   * the orbit on (with the sliders as they showed the highlight), sampled until such a view shows
   * the highlight over a clean diffuse fit, or orbitSamples positions; then off again. Judged there,
   * or where it was seen before.
   */
  async function placeFarther(near) {
    // (a page slow enough to have used most of its time is judged where the highlight was seen)
    if (late('a view with the light away from the viewer', 0.6)) return judgePlace(near);
    progress('looking along the orbit for a view with the light away from the viewer');
    for (const [c, v] of raised) await page.setValue(c, v, ['input', 'change']);
    let far = null, k = 0;
    if (await tryClick(orbitStart, 'the orbit control', { watchMotion: true }) === 'starts') {
      for (; k < T.orbitSamples && !far && !late('a view with the light away from the viewer', 0.9); k++) {
        await tickOrbit(k);
        const sh = await shot();
        const f = sh && !sh.an.blank && sh.an.roundness < T.orbitCoarseRoundness ? diffuseFit(samples(sh.img, sh.an), T) : null;
        if (f && f.r2 >= T.diffuseR2 && highlightSeen(f, T) && lightAngle(f) >= T.highlightPlaceLightDegrees) far = { fit: f, img: sh.img };
      }
      await tryClick(orbitStop, 'the orbit control again', { watchMotion: true });
    }
    for (const [c] of raised) await page.setValue(c, c.value, ['input', 'change']);
    actions.push(`sampled the orbit at ${k} positions for a view with the light ${T.highlightPlaceLightDegrees}° or more from the viewer${raised.length ? `, ${raised.map(([c, v]) => `${nameRole(c, P)} at ${v}`).join(' and ')}` : ''}: ${far ? 'one shows the highlight' : 'none shows the highlight over a clean diffuse fit'}`);
    if (far) out.images.highlightPlace = far.img;
    judgePlace(far ? { fit: far.fit, where: 'a view along the orbit' } : near);
  }

  /**
   * s at its least (where that is 0 or below): the Phong term max(cos φ, 0)^s with s = 0 is pow(0, 0)
   * where cos φ ≤ 0, undefined (NaN: black on many GPUs). One capture at the least s, compared with
   * the judged picture (same view), then s back where it was.
   */
  async function judgeShininessZero(c) {
    const lo = c.min === '' || c.min === undefined || c.min === null ? 0 : Number(c.min); // a range's min defaults to 0
    if (!(lo <= 0)) return;
    await page.setValue(c, lo, ['input', 'change']);
    await tick(100);
    const after = await page.snap();
    await page.setValue(c, c.value, ['input', 'change']);
    await tick(100);
    if (!after || after.width !== img.width || after.height !== img.height) return;
    const spots = darkSpots(img, an, after, fit, T);
    if (!spots) return;
    out.numbers.darkSpotsAtLeastS = spots;
    out.images.leastS = after;
    actions.push(`set slider s to its least, ${lo} (${spots.count} sampled pixels inside the sphere turned dark)`);
    if (spots.share >= T.darkSpotShare && spots.count >= 5) {
      say('review', `s = ${lo} gives black spots inside the sphere (${fmt(100 * spots.share, 1)}% of it darker than diffuse + ambient): pow(0, 0) is undefined; guard it (e.g. cos φ > 0 ? pow(cos φ, s) : 0)`);
    } else say('pass', `s = ${lo} leaves no dark spots inside the sphere (pow(0, 0) guarded)`);
  }
}

/**
 * The page interface with each call's milliseconds and count added up in `timing` ({ method: { ms,
 * calls } }): where a part's time goes, in report.json and on the check page.
 */
export function timed(page, timing) {
  const out = {};
  for (const [k, f] of Object.entries(page)) {
    out[k] = typeof f !== 'function' || k === 'errors' ? f : async (...args) => {
      const t0 = Date.now();
      try { return await f(...args); } finally { addTime(timing, k, Date.now() - t0); }
    };
  }
  return out;
}

/** Adds `ms` to `timing[what]`. */
export function addTime(timing, what, ms) {
  const t = timing[what] || (timing[what] = { ms: 0, calls: 0 });
  t.ms += ms;
  t.calls++;
}

const effectWords = {
  finer: 'the silhouette got rounder', coarser: 'the silhouette got coarser', starts: 'the picture started moving', stops: 'the picture stopped moving',
  shading: 'the shading changed, not the silhouette', blank: 'the picture went blank', none: 'nothing visible changed', unclickable: 'could not be used',
};
