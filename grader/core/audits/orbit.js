// WP04P3: "the camera orbits the sphere" with a button that toggles it: the lit side turns as the
// camera orbits (a light that stays in the world), and a control starts and stops the orbit.
import { describe } from '../controls.js';

const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));
const angle = (a, b) => (180 / Math.PI) * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));

/** The orbit restarted to look at the shading would not stop again. */
export function auditOrbitStopsAgain({ facts, say }) {
  if (facts.orbitKeptMoving) say('review', 'the orbit did not stop again: the pictures were judged as it moves');
}

/** The lit side turning with the orbit (the lit views' sparse fits, `lit`), and the orbit's control. */
export function auditOrbit({ facts, T, must, say, numbers }, lit) {
  const orbitFits = lit.filter((v) => v.orbiting).map((v) => v.fit);
  if (must.has('diffuse') && orbitFits.length >= 2) {
    let turn = 0;
    for (let i = 1; i < orbitFits.length; i++) turn = Math.max(turn, angle(orbitFits[0].light, orbitFits[i].light));
    numbers.lightTurn = turn;
    // on a sphere only the shading shows the orbit: where the step asks for the orbit (P3) a light that
    // moves with the camera hides it; elsewhere the slides leave the light's space to the student
    if (turn < T.lightTurnDegrees) {
      say(must.has('orbitToggle') ? 'review' : 'pass', `${must.has('orbitToggle') ? 'the orbit does not show in the shading: ' : 'note: '}while the camera orbits, the lit side stays where it is on screen (the fitted light turns ${fmt(turn, 1)}° over ${orbitFits.length} views): the light moves with the camera (given in eye space, or light and normals in different spaces?)`);
    } else say('pass', `the lit side turns as the camera orbits (${fmt(turn, 0)}° over ${orbitFits.length} views): the light stays in the world`);
  }
  if (must.has('orbitToggle')) {
    const o = facts.orbit;
    const control = o.control === null ? null : facts.controls.find((c) => c.index === o.control);
    if (o.toggles) say('pass', `a control toggles the orbit on and off (${facts.roles.orbit})`);
    else if (control) say('review', `${describe(control)} starts the orbit, but nothing found stops it`);
    else if (o.movedAtFirst) say('review', `the camera orbits, but no button toggles the orbit: none of the ${facts.level.trials} controls tried stops it (the slide asks for one)`);
    else say('review', 'no orbit: the picture never moved, and no control named for the orbit starts it');
  }
}

/** The orbit could not be stopped: said as a note. */
export function auditNotStopped({ facts, say }) {
  if (!facts.stopped) say('pass', 'note: the orbit could not be stopped: the pictures were judged as it moves');
}
