// A sphere closed from every side. Where the page's mesh can be read, the
// geometry audits know every side exactly (open edges, winding). Where it cannot (positions made in
// a shader), the orbit is run on and the outline read at counted positions until the camera has
// turned all the way round (the view matrix the page sends; where it sends none, roundSamples
// positions), and the orbit is stopped again where it was stopped. Where the camera's turn is read,
// each step is sized from the last to turn about roundStepDegrees, so that no side goes unseen (a
// hole seen obliquely notches the outline; it shows as a gap only near face-on). Each position's
// outline is kept as numbers, the first with a gap as a picture; the audit (auditAllRound) judges them.
import { cameraTurn } from '../computed/camera.js';
import { readCamera, orbitSampleFrames } from './orbit.js';
import { FULL_TURN, MS_PER_SECOND } from '../units.js';

/** Looks at the sphere all round its orbit where its mesh cannot be read: sets facts.allRound. */
export async function lookAllRound(session) {
  const { thresholds, facts, orbit } = session;
  const g = facts.geometry;
  if (!g || !g.why || !orbit) return;
  const stopped = !session.moving;
  if (stopped && !(orbit.start && orbit.stop)) return;
  session.step('looking at the sphere from every side');
  if (stopped && await session.tryClick(orbit.start, 'the orbit control, to look all round,', { watchMotion: true }) !== 'starts') return;
  const views = [];
  await readCamera(session);
  let last = session.camera, turned = last ? 0 : null, gap = null;
  // frames a step: at most an orbit sample's (orbit.js), at least one
  const most = () => Math.max(1, orbitSampleFrames(session));
  let frames = thresholds.roundFirstFrames;
  for (let k = 0; k < thresholds.roundSamples && !(turned >= FULL_TURN); k++) {
    await session.tick((MS_PER_SECOND * frames) / thresholds.framesPerSecond, frames);
    const sh = await session.shot();
    await readCamera(session);
    const step = turned !== null ? cameraTurn([last, session.camera], thresholds.cameraRotationTolerance) : null;
    turned = step !== null ? turned + step : null;
    last = session.camera;
    // the next step's frames: sized to turn about roundStepDegrees where this one's turn is read, else doubled
    frames = Math.max(
      1,
      Math.min(most(), step > 0 ? Math.round((frames * thresholds.roundStepDegrees) / step) : 2 * frames),
    );
    const an = sh ? sh.an : { blank: true };
    views.push(
      an.blank ? { blank: true } : { roundness: an.roundness, fill: an.fill, ...(turned !== null ? { turned } : {}) },
    );
    if (!gap && !an.blank && an.roundness <= thresholds.roundness && an.fill < thresholds.fill) {
      gap = session.keep('all-round-gap', sh.img);
    }
  }
  facts.allRound = { views, turned, gap, why: g.why };
  session.act(`looked at ${views.length} positions along the orbit${turned !== null ? ` (the camera turned ${Math.round(turned)}°)` : ''}`);
  if (stopped) await session.tryClick(orbit.stop, 'the orbit control again', { watchMotion: true });
}
