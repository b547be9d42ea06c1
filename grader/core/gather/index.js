// Gathering one part, as a teacher brings it to a state by hand: its first frame, its controls
// found by what they do, the orbit sampled and stopped, the sphere subdivided until round, then
// what the step asks to be tried. The result is an artifact, plain data: `facts` (JSON) and
// `images` (named pictures); it holds no verdict and no reason (the audits give those). What is
// gathered depends only on the page, the rubric and counts: the page's clock is frozen and
// stepped, and the wall clock is an outer bound (facts.tooSlow says where it ran out).
//
// It drives the page only through the page interface (grader/node/run/playwright-page.js for the
// grader, check/frame-page.js for the check page): state(), snap(), controls(), click(c),
// setValue(c, v, events), press(key), tick(ms, frames) → state(), setNoCull(on), sources(), errors(),
// tampered(), stayed().
import { chooseStepCanvas } from './step-canvas.js';
import { openSession, TooSlow, TooHeavy, FIRST_FRAME, addStep, drewAFrame } from './session.js';
import { findOrbit, sampleOrbit, keepIfLit, startOrbitToSee } from './orbit.js';
import { findLevel, climbLevelLadder } from './level.js';
import { probeFaces, probeDepthCulling } from './faces.js';
import { raiseHighlight, placeFarther } from './highlight.js';
import { trySliders, leastShininess } from './sliders.js';
import { unclip, brighten } from './visible.js';
import { readGeometry, readSurface } from './geometry.js';
import { lookAllRound } from './all-round.js';
import { startToDraw } from './start.js';
import { setStepShading } from './shading-control.js';
import { revealSliders } from './reveal.js';
import { sphereView, shadingOf, litViewFits, highlightEvidence } from '../computed/evidence.js';
import { shownDifference } from '../measure/shown.js';
import { browserFailed } from '../audits/page.js';

export { FIRST_FRAME, addStep };

/**
 * Gathers one opened part: { facts, images }. `timing` ({ method: { ms, calls } }) hears where the
 * time went by page call, `steps` ({ step: ms }) by step of the gathering.
 */
export async function gatherPart(page, options) {
  const { part, rubric, progress = () => {}, deadline = Infinity, timing = {}, steps = {} } = options;
  const session = openSession(timed(page, timing), { part, rubric, progress, deadline, steps });
  try {
    await gather(session);
  } catch (err) {
    // a bound, or the browser failing itself (its renderer crashed): what was gathered before stays
    const message = String(err && err.message).split('\n')[0];
    if (browserFailed(err)) session.facts.browserFailed = { message, doing: session.doing };
    else if (!(err instanceof TooSlow)) throw err;
    else session.facts.tooSlow = err.doing;
    if (err instanceof TooHeavy) session.facts.tooHeavy = err.work;
  } finally {
    session.mark(null);
  }
  session.facts.errors = [...page.errors()];
  // the grader's hooks the page replaced (a hand-in is untrusted code): the audit names them
  const tampered = page.tampered ? await page.tampered().catch(() => null) : null;
  if (tampered && tampered.length) session.facts.tampered = tampered;
  // what the page tried that would have closed or left it (kept open: grader/browser/stay.js)
  const stayed = page.stayed ? await page.stayed().catch(() => null) : null;
  if (stayed && stayed.length) session.facts.stayed = stayed;
  return { facts: session.facts, images: session.images };
}

/** The part gathered in the order a teacher works: the first frame, the controls, the orbit and the level, then what the step asks to be tried. */
async function gather(session) {
  const first = await firstFrame(session);
  if (!first || first.an.blank) return;
  // the page's animation loops and draws a frame before any control is touched, and after them all
  if (session.frameDraws) session.facts.frameDraws = { first: session.frameDraws };
  session.mark('reading the controls');
  const controls = await session.page.controls();
  session.facts.controls = controls;
  session.cur = first;
  await setStepShading(session, controls);
  const judged = await orbitAndLevel(session, controls);
  if (judged) await whatTheStepAsks(session, controls, judged.img);
  // (the last frames the gathering ran: no frame is run for it)
  if (session.facts.frameDraws) {
    Object.assign(session.facts.frameDraws, {
      last: session.frameDraws,
      clicks: session.facts.actions.filter((a) => /^(clicked|pressed) /.test(a)).length,
    });
  }
}

/**
 * The first frame: frames run only once nothing the page awaits in real time is pending; a page
 * that shows one colour has a counted number of frames more. facts.first, facts.canvas and the
 * picture `first`; returns the first shot ({ img, an }) or null (no canvas).
 */
async function firstFrame(session) {
  const { page, thresholds, facts, must } = session;
  session.step(FIRST_FRAME);
  await session.settle();
  await session.tick(thresholds.firstTickMs, 1);
  for (let k = 0; k < thresholds.firstFrameTicks; k++) {
    const s = await session.settle();
    if (drewAFrame(s)) break;
    if (s.adapter === null || s.shaderErrors.length || (!s.api && k >= thresholds.noContextTicks)) break;
    // it threw or alerted: no need to wait longer
    if (k >= thresholds.errorTicks && page.errors().some((e) => /^(page error|dialog)/.test(e))) break;
    await session.tick(thresholds.frameMs);
  }
  let g = await page.state();
  // no draw call yet and no shader or GPU error: a control named for starting the page is clicked
  const startedBy = !g.draws && g.adapter !== null && !g.shaderErrors.length && !g.gpuErrors.length
    ? await startToDraw(session) : null;
  if (startedBy) g = await page.state();
  facts.api = g.api;
  facts.first = { api: g.api, adapter: g.adapter, draws: g.draws, shaderErrors: g.shaderErrors, gpuErrors: g.gpuErrors,
    ...(g.webgpuMissing ? { webgpuMissing: true } : {}), // it asked for WebGPU where the browser has none (Firefox ESR)
    ...(startedBy ? { startedBy } : {}) };
  await chooseStepCanvas(session);
  let firstShot = await session.shot();
  if (!firstShot) return null;
  // a page that drew without an error and shows one colour (its unlit side on a background of the
  // same colour, say) has its chance: a counted number of frames more, then the picture it shows then is its first
  if (firstShot.an.blank && g.draws > 0 && !g.shaderErrors.length && !g.gpuErrors.length) {
    session.step('waiting for a visible frame');
    await session.tick(thresholds.blankWaitFrames * thresholds.frameMs, thresholds.blankWaitFrames);
    const later = await session.shot();
    facts.first.waited = thresholds.blankWaitFrames;
    if (later) firstShot = later;
    // a lit step may face its unlit side to the camera until its orbit is started
    const started = firstShot.an.blank && must.has('diffuse') ? await startOrbitToSee(session) : null;
    if (started) {
      firstShot = started.shot;
      facts.first.orbitStarted = started.control;
    }
    facts.first.blankGeometry = firstShot.an.blank ? await readGeometry(session) : null;
  }
  facts.canvas = { width: firstShot.img.width, height: firstShot.img.height };
  session.keep('first', firstShot.img);
  await compareShown(session, 'first');
  return firstShot;
}

/**
 * The orbit found and stopped, the sphere subdivided until round (the ladder), the orbit looked at
 * again where the shading needs it, and the level to judge: facts.orbit, facts.ladder, facts.judged.
 * Returns the judged level's shot, or null where it is blank.
 */
async function orbitAndLevel(session, controls) {
  const { facts, must } = session;
  await findOrbit(session, controls);
  const stopped = facts.stopped = !session.moving;
  await findLevel(session, controls);
  await climbLevelLadder(session);
  const ladder = session.ladder;
  // the orbit looked at where the shading can be read (it was too coarse at first): on again,
  // sampled, off again; the view it stops at is judged. Only where it buys evidence: the judged view
  // is unlit, or the step asks for the orbit (P3)
  const { orbit } = session;
  const unlit = () => !keepIfLit(session, ladder[ladder.length - 1].img, { orbiting: false, keep: false });
  if (orbit.later && must.has('diffuse') && (must.has('orbit-toggle') || unlit())) {
    const at = ladder.length - 1;
    if (!stopped) {
      await sampleOrbit(session, true);
      ladder[at] = session.cur;
      facts.viewMoved = true;
    } else if (orbit.start && orbit.stop && await session.tryClick(orbit.start, 'the orbit control again', { watchMotion: true }) === 'starts') {
      facts.viewMoved = true;
      await sampleOrbit(session, true);
      if (await session.tryClick(orbit.stop, 'the orbit control again', { watchMotion: true }) === 'stops') ladder[at] = session.cur;
      else facts.orbitKeptMoving = true;
    }
  }
  Object.assign((facts.orbit = {}), {
    movedAtFirst: orbit.movedAtFirst,
    toggles: orbit.toggles,
    start: orbit.start ? orbit.start.index : null,
    stop: orbit.stop ? orbit.stop.index : null,
    control: session.roles.orbit ? session.roles.orbit.index : null,
  });
  // a page that goes blank at a higher level is judged at the last level it drew
  let j = ladder.length - 1;
  if (ladder[j].an.blank) {
    const drawn = ladder.map((s, k) => (s.an.blank ? -1 : k)).filter((k) => k >= 0);
    if (drawn.length) {
      j = drawn[drawn.length - 1];
      facts.blankAtHigherLevel = true;
    }
  }
  // each level's outline as measured on the way up; its picture where an audit reads it (the judged
  // level; every level where a coarse one is compared with it, P5)
  facts.ladder = ladder.map((s, k) => ({ roundness: s.an.roundness, blank: !!s.an.blank,
    ...(k === j || must.has('per-fragment') ? { image: session.keep(`level-${k}`, s.img) } : {}) }));
  facts.judgedLevel = j;
  // the vertices a frame draws at the judged level (the page's draws), where it is the level the page shows now
  if (j === ladder.length - 1 && session.frameVertices > 0) facts.judgedVertices = Math.round(session.frameVertices);
  session.mark('reading the geometry and the surface');
  facts.geometry = await readGeometry(session);
  // the judged view's surface per pixel, where the lighting or the side seen is judged: each pixel's
  // position and normal as the page drew them
  if (must.has('diffuse') || must.has('highlight') || must.has('front-faces')) facts.surface = await readSurface(session);
  facts.judged = facts.ladder[j].image;
  return ladder[j].an.blank ? null : ladder[j];
}

/** What the step asks to be tried on the judged picture `img`: the faces, the shading made readable, the highlight, the sliders, s at its least, the highlight's place, the view all round. */
async function whatTheStepAsks(session, controls, img) {
  const { page, thresholds, facts, must, orbit } = session;
  const stopped = facts.stopped;
  const { an } = sphereView(img, thresholds);
  session.mark('trying the faces and the depth test');
  if (must.has('front-faces')) await probeFaces(session, controls, { img, an });
  if (must.has('depth-culling')) await probeDepthCulling(session, controls);
  // a picture that clips to white over much of the sphere: read with the page's own kd, Le, La
  // lowered; one too dim to show its shading, with the page's own Le (else kd) raised
  const shaded = must.has('diffuse') || must.has('highlight');
  session.mark('reading the shading');
  const shadeImg =
    (shaded && ((await unclip(session, controls, img, an)) || (await brighten(session, controls, img, an)))) || img;
  const shading = shaded ? shadingOf(shadeImg, an, thresholds) : null;
  let placeLater = false;
  if (must.has('highlight') && shading.fit) {
    const views = litViewFits(facts.views, facts, session.images, thresholds);
    if (!highlightEvidence(shading, views, null, session.images, thresholds).seen && !shading.nearModel) {
      session.mark('raising the highlight');
      await raiseHighlight(session, controls);
    }
    placeLater =
      highlightEvidence(shading, views, facts.raised, session.images, thresholds).farther &&
      !!orbit.start &&
      !!orbit.stop &&
      stopped;
  }
  if (must.has('sliders')) await trySliders(session, await revealSliders(session, controls));
  session.mark('s at its least');
  if (must.has('highlight') && shading.fit && stopped) await leastShininess(session, controls);
  session.mark('the highlight\'s place');
  facts.sources = await page.sources();
  if (placeLater) await placeFarther(session, controls);
  session.mark('the picture as the browser shows it');
  await compareShown(session, 'last');
  // last: it turns the orbit on and off again, and nothing after it reads the picture
  await lookAllRound(session);
}

/**
 * The picture as the browser shows it beside the page's own read-back (the second channel, where the
 * driver has one): facts.shown[] gets how far they agree, and where they differ the browser's picture
 * is kept (`shown-<at>`), for the report to show what a student saw.
 */
async function compareShown(session, at) {
  if (!session.page.shown) return;
  session.outOfTime();
  const two = await session.page.shown();
  const d = shownDifference(two, session.thresholds);
  if (d.compared && d.share > session.thresholds.shownDifferShare) d.image = session.keep(`shown-${at}`, two.shown);
  (session.facts.shown || (session.facts.shown = [])).push({ at, ...d });
}

/**
 * The page interface with each call's milliseconds and count added up in `timing` ({ method: { ms,
 * calls } }): where a part's time goes, in report.json and on the check page (never read by the gathering).
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
