// The orbit: does the picture move by itself; the lit views along it (kept for the audits: the lit
// side turns with the orbit when the light stays in the world); the control that stops it, or the
// one that starts it. Samples are at fixed virtual times, orbitSampleSeconds apart, with a number of
// frames each that depends only on the sample's index and the page's own work a frame.
import { analyse } from '../measure.js';
import { describe, named, trialOrder, isClickable, sentChanges } from '../controls.js';
import { litView } from '../computed/views.js';
import { readGeometry, readSent } from './geometry.js';
import { cameraOf, cameraTurn } from '../computed/camera.js';
import { fmt } from '../format.js';

/** Is `img` a lit view? Lit views are kept (`orbiting`: seen while the camera orbits). */
export function look(S, img, { orbiting = true, keep = true } = {}) {
  const { lit } = litView(img, S.T);
  if (lit && keep) S.facts.views.push({ image: S.keep(`view-${S.facts.views.length}`, img), orbiting, ...(orbiting && S.camera ? { camera: S.camera } : {}) });
  return lit;
}

/** The camera as the page sent it now (the animated matrices: camera.js), kept for the next views looked at. */
export async function readCamera(S) {
  S.camera = S.facts.sentAnimated ? cameraOf(await readSent(S), S.facts.sentAnimated) : null;
}

/** Has the camera turned, over the orbiting views kept, less than it takes to tell where the light is? (unknown: no) */
function turnedTooLittle(S) {
  const turn = cameraTurn(S.facts.views.filter((v) => v.orbiting).map((v) => v.camera), S.T.cameraRotationTolerance);
  return turn !== null && turn < S.T.cameraTurnDegrees;
}

/** The most frames an orbit sample runs: orbitSampleSeconds of frames, as many as orbitSampleWork affords a page of this cost. */
export const orbitSampleFrames = (S) => Math.min(Math.round(S.T.framesPerSecond * S.T.orbitSampleSeconds), Math.floor(S.T.orbitSampleWork / Math.max(1, S.frameWork)));

// the k-th orbit sample's frames: many pages turn the camera a fixed step a frame, so each sample
// runs more frames as the search goes on, up to orbitSampleFrames
export const tickOrbit = async (S, k) => {
  await S.tick(S.T.orbitSampleSeconds * 1000, Math.max(S.T.orbitSampleLeastFrames, Math.min(S.T.orbitSampleFirstFrames << k, orbitSampleFrames(S))));
  await readCamera(S);
};

/**
 * Looks along the orbit until a lit view shows (a few positions at least), at most orbitSamples
 * positions. A silhouette too coarse to read shading from (a tetrahedron at level 0) is looked at
 * once the sphere is round, after the level ladder (`afterLadder`).
 */
export async function sampleOrbit(S, afterLadder = false) {
  const { T, orbit } = S;
  if (!afterLadder && S.cur.an.roundness >= T.orbitCoarseRoundness) {
    orbit.later = true;
    return;
  }
  S.step('sampling the orbit');
  let k = 0, img = S.cur.img;
  await readCamera(S);
  // a lit view and two samples at least; where the page sends its view matrix, until the camera has
  // turned cameraTurnDegrees over the lit views (a slow orbit: a light that moves with the camera
  // and one that stays in the world look alike over a small turn)
  for (; k < T.orbitSamples && (!look(S, img) || k < T.orbitLeastSamples || turnedTooLittle(S)); k++) {
    await tickOrbit(S, k);
    img = await S.page.snap();
  }
  S.cur = { img, an: analyse(img, T) };
  S.act(`sampled the orbit at ${k} positions ${fmt(T.orbitSampleSeconds, 1)} s apart (${S.facts.views.filter((v) => v.orbiting).length} lit)`);
}

/** Looks along the orbit for a view `good(img, an)` accepts: { img, k } or null, after at most orbitSamples positions. */
export async function searchOrbit(S, good) {
  for (let k = 0; k < S.T.orbitSamples; k++) {
    await tickOrbit(S, k);
    const sh = await S.shot();
    if (sh && good(sh.img, sh.an)) return { img: sh.img, k: k + 1 };
  }
  return { img: null, k: S.T.orbitSamples };
}

/**
 * Whether the picture moves by itself; if so, the lit views along the orbit and the control that
 * stops it; if not (in a shaded part), a control named for the orbit that starts it, the views, and
 * what stops it again. Sets S.orbit: { movedAtFirst, toggles, start, stop, later }.
 */
export async function findOrbit(S, controls) {
  const { facts, T, P } = S;
  const orbit = S.orbit = { movedAtFirst: false, toggles: false, start: null, stop: null, later: false };
  const clickables = controls.filter(isClickable);
  const shaded = S.must.has('diffuse');
  const sent = await readSent(S);
  await S.watch();
  orbit.movedAtFirst = S.moving;
  // the frames drawn so far, no control touched yet (their vertices: a page that draws more every
  // frame), and the geometry of the level the page starts at; what the page sends differently
  // with no control touched (an orbit's view matrix: not a slider's doing)
  facts.geometryAtFirst = await readGeometry(S);
  if (S.moving) facts.sentAnimated = sentChanges(sent, await readSent(S));
  if (shaded) look(S, S.images.first, { orbiting: false });
  if (S.moving) {
    S.act('the picture moves by itself (an orbit or animation)');
    if (shaded) await sampleOrbit(S);
    // the control that stops it: named for the orbit first, then the others
    S.step('looking for the control that stops the orbit');
    for (const c of trialOrder(clickables, 'orbit', P, S.taken).slice(0, T.maxControlTrials)) {
      S.trialsMade++;
      if (await S.tryClick(c, 'a control', { watchMotion: true }) === 'stops') {
        S.assign('orbit', c, 'stopped');
        Object.assign(orbit, { toggles: true, start: c, stop: c });
        break;
      }
    }
  } else if (shaded) {
    // the orbit may be off at first: a control that starts it (named for it first; a start and a stop button)
    S.step('looking for the control that starts the orbit');
    const namedOrbit = trialOrder(clickables, 'orbit', P, S.taken).filter((c) => named(c, 'orbit', P));
    for (const c of namedOrbit) {
      S.trialsMade++;
      if (await S.tryClick(c, 'a control', { watchMotion: true }) !== 'starts') continue;
      await sampleOrbit(S);
      // the same control (a toggle) or another (a stop button) stops it
      for (const s of [c, ...namedOrbit.filter((x) => x !== c)]) {
        if (await S.tryClick(s, 'a control', { watchMotion: true }) === 'stops') {
          S.assign('orbit', c, s === c ? 'starts-stops' : 'starts-other-stops', s === c ? {} : { stopper: describe(s) });
          Object.assign(orbit, { toggles: true, start: c, stop: s });
          break;
        }
      }
      if (!orbit.toggles) S.assign('orbit', c, 'starts');
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
export async function startOrbitToSee(S) {
  const { T, P } = S;
  S.step('starting the orbit to see the lit side');
  const clickables = (await S.page.controls()).filter(isClickable);
  for (const c of trialOrder(clickables, 'orbit', P, S.taken).filter((x) => named(x, 'orbit', P)).slice(0, T.maxControlTrials)) {
    S.trialsMade++;
    if (!await S.press(c, 'a control named for the orbit, to see the lit side,')) continue;
    const seen = await searchOrbit(S, (img) => litView(img, T).lit);
    if (seen.img) {
      S.act(`  → a lit view after ${seen.k} orbit positions`);
      return { shot: { img: seen.img, an: analyse(seen.img, T) }, control: describe(c) };
    }
    S.act(`  → no lit view in ${seen.k} orbit positions`);
    await S.press(c, 'the same control again');
  }
  return null;
}

/** An orbit control found while looking for the level (it started the picture moving): sampled, then stopped again. */
export async function orbitFoundLate(S, c) {
  if (S.must.has('diffuse') && !S.R.orbit) await sampleOrbit(S);
  const again = await S.tryClick(c, 'a control', { watchMotion: true });
  if (!S.R.orbit) {
    S.assign('orbit', c, again === 'stops' ? 'starts-stops' : 'starts');
    S.orbit.toggles = again === 'stops';
    if (S.orbit.toggles) Object.assign(S.orbit, { start: c, stop: c });
  }
}
