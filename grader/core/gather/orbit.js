// The orbit: does the picture move by itself; the lit views along it (kept for the audits: the lit
// side turns with the orbit when the light stays in the world); the control that stops it, or the
// one that starts it. Samples are at fixed virtual times, orbitSampleSeconds apart, with a number of
// frames each that depends only on the sample's index and the page's own work a frame.
import { analyse } from '../measure.js';
import { describe, trialOrder, isClickable, sentChanges } from '../controls.js';
import { freeClickablesNamed } from './params.js';
import { litView } from '../computed/views.js';
import { readGeometry, readSent, readSurface } from './geometry.js';
import { cameraOf, cameraTurn, cameraPath } from '../computed/camera.js';
import { fmt } from '../format.js';
import { MS_PER_SECOND, FULL_TURN } from '../units.js';

/** Is `img` a lit view? Lit views are kept (`orbiting`: seen while the camera orbits). */
export function keepIfLit(session, img, { orbiting = true, keep = true } = {}) {
  const { lit } = litView(img, session.thresholds);
  if (lit && keep) {
    session.facts.views.push({
      image: session.keep(`view-${session.facts.views.length}`, img),
      orbiting,
      ...(orbiting && session.camera ? { camera: session.camera } : {}),
      // the vertices a frame drew there (the page's draws): a view taken before the ladder is coarser than the judged one
      ...(session.frameVertices > 0 ? { vertices: Math.round(session.frameVertices) } : {}),
    });
  }
  return lit;
}

/** The camera as the page sent it now (the animated matrices: camera.js), kept for the next views looked at. */
export async function readCamera(session) {
  session.camera = session.facts.sentAnimated ? cameraOf(await readSent(session), session.facts.sentAnimated) : null;
}

/**
 * The surface of the lit view `v` just kept along the orbit (no frame has run since), the first, as its
 * `surface`: where the light is judged (P3–P5), the light fitted on its surface and on the judged
 * view's says whether it stays in the world as the camera turns (audits/units/orbit-light.js).
 */
async function firstViewSurface(session, v) {
  if (!v || !v.orbiting || !session.must.has('diffuse') || session.facts.views.some((x) => x.surface)) return;
  const surface = await readSurface(session, `${v.image}-`);
  if (surface) v.surface = surface;
}

/** Has the camera turned, over the orbiting views kept, less than it takes to tell where the light is? (unknown: no) */
function turnedTooLittle(session) {
  const turn = cameraTurn(
    session.facts.views.filter((v) => v.orbiting).map((v) => v.camera),
    session.thresholds.cameraRotationTolerance,
  );
  return turn !== null && turn < session.thresholds.cameraTurnDegrees;
}

/** The most frames an orbit sample runs: orbitSampleSeconds of frames, as many as orbitSampleWork affords a page of this cost. */
export const orbitSampleFrames = (session) =>
  Math.min(
    Math.round(session.thresholds.framesPerSecond * session.thresholds.orbitSampleSeconds),
    Math.floor(session.thresholds.orbitSampleWork / Math.max(1, session.frameWork)),
  );

// the k-th orbit sample's frames: many pages turn the camera a fixed step a frame, so each sample
// runs more frames as the search goes on, up to orbitSampleFrames
export const tickOrbit = async (session, k) => {
  await session.tick(
    session.thresholds.orbitSampleSeconds * MS_PER_SECOND,
    Math.max(
      session.thresholds.orbitSampleLeastFrames,
      Math.min(session.thresholds.orbitSampleFirstFrames << k, orbitSampleFrames(session)),
    ),
  );
  await readCamera(session);
};

/**
 * Looks along the orbit until a lit view shows (a few positions at least), at most orbitSamples
 * positions, and no farther than once round where no view is lit: where the page sends its view
 * matrix and the camera has gone all the way round, every view the orbit shows has been shown. A
 * silhouette too coarse to read shading from (a tetrahedron at level 0) is looked at once the
 * sphere is round, after the level ladder (`afterLadder`).
 */
export async function sampleOrbit(session, afterLadder = false) {
  const { thresholds, orbit } = session;
  if (!afterLadder && session.cur.an.roundness >= thresholds.orbitCoarseRoundness) {
    orbit.later = true;
    return;
  }
  session.step('sampling the orbit');
  let k = 0, img = session.cur.img;
  await readCamera(session);
  const cameras = [session.camera];
  const roundUnlit = () => !session.facts.views.some((v) => v.orbiting) &&
    cameraPath(cameras, thresholds.cameraRotationTolerance) >= FULL_TURN;
  // the view kept for `img` (none: it was not lit, or not looked at), whose surface is read before
  // the next frame where it is the first lit view along the orbit
  let kept = null;
  const keepLit = () => {
    const n = session.facts.views.length, lit = keepIfLit(session, img);
    kept = session.facts.views.length > n ? session.facts.views[n] : null;
    return lit;
  };
  // a lit view and two samples at least; where the page sends its view matrix, until the camera has
  // turned cameraTurnDegrees over the lit views (a slow orbit: a light that moves with the camera
  // and one that stays in the world look alike over a small turn)
  for (
    ;
    k < thresholds.orbitSamples &&
    (!keepLit() || k < thresholds.orbitLeastSamples || turnedTooLittle(session)) &&
    !roundUnlit();
    k++
  ) {
    await firstViewSurface(session, kept);
    kept = null;
    await tickOrbit(session, k);
    img = await session.page.snap();
    cameras.push(session.camera);
  }
  await firstViewSurface(session, kept);
  session.cur = { img, an: analyse(img, thresholds) };
  const round = roundUnlit() ? '; the camera went all the way round' : '';
  session.act(`sampled the orbit at ${k} positions ${fmt(thresholds.orbitSampleSeconds, 1)} s apart (${session.facts.views.filter((v) => v.orbiting).length} lit${round})`);
}

/** Looks along the orbit for a view `good(img, an)` accepts: { img, k } or null, after at most orbitSamples positions. */
export async function searchOrbit(session, good) {
  for (let k = 0; k < session.thresholds.orbitSamples; k++) {
    await tickOrbit(session, k);
    const sh = await session.shot();
    if (sh && good(sh.img, sh.an)) return { img: sh.img, k: k + 1 };
  }
  return { img: null, k: session.thresholds.orbitSamples };
}

/**
 * Whether the picture moves by itself; if so, the lit views along the orbit and the control that
 * stops it; if not (in a shaded part), a control named for the orbit that starts it, the views, and
 * what stops it again. Sets session.orbit: { movedAtFirst, toggles, start, stop, later }.
 */
export async function findOrbit(session, controls) {
  const { facts, thresholds, patterns } = session;
  const orbit = session.orbit = { movedAtFirst: false, toggles: false, start: null, stop: null, later: false };
  const clickables = controls.filter(isClickable);
  const shaded = session.must.has('diffuse');
  session.mark('watching whether the picture moves by itself');
  const sent = await readSent(session);
  await session.watch();
  orbit.movedAtFirst = session.moving;
  // the frames drawn so far, no control touched yet (their vertices: a page that draws more every
  // frame), and the geometry of the level the page starts at; what the page sends differently
  // with no control touched (an orbit's view matrix: not a slider's doing)
  facts.geometryAtFirst = await readGeometry(session);
  if (session.moving) facts.sentAnimated = sentChanges(sent, await readSent(session));
  if (shaded) keepIfLit(session, session.images.first, { orbiting: false });
  if (session.moving) {
    session.act('the picture moves by itself (an orbit or animation)');
    if (shaded) await sampleOrbit(session);
    // the control that stops it: named for the orbit first, then the others
    session.step('looking for the control that stops the orbit');
    for (const c of trialOrder(clickables, 'orbit', patterns, session.taken).slice(0, thresholds.maxControlTrials)) {
      session.trialsMade++;
      if (await session.tryClick(c, 'a control', { watchMotion: true }) === 'stops') {
        session.assign('orbit', c, 'stopped');
        Object.assign(orbit, { toggles: true, start: c, stop: c });
        break;
      }
    }
  } else if (shaded) {
    // the orbit may be off at first: a control that starts it (named for it first; a start and a stop button)
    session.step('looking for the control that starts the orbit');
    const namedOrbit = freeClickablesNamed(session, controls, 'orbit');
    for (const c of namedOrbit) {
      session.trialsMade++;
      if (await session.tryClick(c, 'a control', { watchMotion: true }) !== 'starts') continue;
      await sampleOrbit(session);
      // the same control (a toggle) or another (a stop button) stops it
      for (const s of [c, ...namedOrbit.filter((x) => x !== c)]) {
        if (await session.tryClick(s, 'a control', { watchMotion: true }) === 'stops') {
          session.assign('orbit', c, s === c ? 'starts-stops' : 'starts-other-stops', s === c ? {} : { stopper: describe(s) });
          Object.assign(orbit, { toggles: true, start: c, stop: s });
          break;
        }
      }
      if (!orbit.toggles) session.assign('orbit', c, 'starts');
      break;
    }
  }
  facts.movedAtFirst = orbit.movedAtFirst;
}

/**
 * A lit step whose picture stays one colour after its wait (the unlit side toward the camera, on
 * a background of that colour) has its orbit started: each control named for the orbit, clicked in
 * turn, and the orbit looked along (searchOrbit: counted samples) until a lit view shows (a thin
 * crescent is no outline to judge levels by); a control that shows none is clicked again, to leave
 * the page as it was. { shot, control } (the lit view, the control's description, left on: the
 * orbit is then found moving), or null.
 */
export async function startOrbitToSee(session) {
  const { thresholds } = session;
  session.step('starting the orbit to see the lit side');
  const namedOrbit = freeClickablesNamed(session, await session.page.controls(), 'orbit');
  for (const c of namedOrbit.slice(0, thresholds.maxControlTrials)) {
    session.trialsMade++;
    if (!await session.press(c, 'a control named for the orbit, to see the lit side,')) continue;
    const seen = await searchOrbit(session, (img) => litView(img, thresholds).lit);
    if (seen.img) {
      session.act(`  → a lit view after ${seen.k} orbit positions`);
      return { shot: { img: seen.img, an: analyse(seen.img, thresholds) }, control: describe(c) };
    }
    session.act(`  → no lit view in ${seen.k} orbit positions`);
    await session.press(c, 'the same control again');
  }
  return null;
}

/** An orbit control found while looking for the level (it started the picture moving): sampled, then stopped again. */
export async function orbitFoundLate(session, c) {
  if (session.must.has('diffuse') && !session.roles.orbit) await sampleOrbit(session);
  const again = await session.tryClick(c, 'a control', { watchMotion: true });
  if (!session.roles.orbit) {
    session.assign('orbit', c, again === 'stops' ? 'starts-stops' : 'starts');
    session.orbit.toggles = again === 'stops';
    if (session.orbit.toggles) Object.assign(session.orbit, { start: c, stop: c });
  }
}
