// The audit unit 'orbit-stops-again' (The orbit stops, and stops again): Looks for the control
// that stops the orbit, and checks that it stops again after being restarted.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'orbit-stops': { title: 'The orbit stops, and stops again', slide: SLIDE.orbit, failureTitle: 'The orbit does not stop', description: 'Looks for the control that stops the orbit, and checks that it stops again after being restarted.', reads: ['facts.stopped', 'facts.orbitKeptMoving'] },
};

/** The orbit restarted to look at the shading would not stop again. */
export function auditOrbitStopsAgain({ facts, sayAs }) {
  const say = sayAs('orbit-stops');
  if (facts.orbitKeptMoving) say('review', 'the orbit did not stop again: the pictures were judged as it moves');
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'orbit-stops-again', auditOrbitStopsAgain, { says: ['orbit-stops'] });
