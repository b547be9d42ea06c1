// The audit unit 'orbit-light' (The lit side turns as the camera orbits): Compares the light
// fitted in the lit views with how far the camera turned (its view matrix, as the page sent it).
import { describe } from '../../controls.js';
import { cameraRotations, rotationsTurn, staysInWorld } from '../../computed/camera.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { rolesInWords } from '../../computed/roles.js';
import { unit } from '../unit.js';
import { HALF_TURN } from '../../units.js';
import { lightSpaceOnSurface } from '../../computed/light-space.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'orbit-light': { title: 'The lit side turns as the camera orbits', slide: SLIDE.orbit, failureTitle: 'The lit side does not turn as the camera orbits', description: 'Fits the light on the page\'s own surface in the first lit view along the orbit and in the judged view, in the space of its normals, and says whether it stays there (a light in the world) or turns with the camera the page\'s P·V·M shows (a light in the eye\'s space); where the surfaces cannot say, compares the light fitted in the lit views\' pictures with how far the camera turned (its view matrix, as the page sent it).', reads: ['facts.views', 'facts.surface'] },
  'orbit-toggle': { title: 'A button toggles the orbit', slide: SLIDE.orbit, failureTitle: 'No button toggles the orbit', description: 'Finds the control that starts and stops the orbit by what it does to the picture.', reads: ['facts.orbit', 'facts.controls', 'facts.roles', 'facts.level'] },
};

const signedAngle = (a, b) =>
  (HALF_TURN / Math.PI) *
  Math.acos(
    Math.max(-1, Math.min(1, (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (Math.hypot(...a) * Math.hypot(...b)))),
  );

const angle = (a, b) =>
  (HALF_TURN / Math.PI) * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));

/**
 * The light's space read on a lit view's own surface and the judged view's (computed/light-space.js: `read`): said
 * and true, or false where the surfaces cannot say (the pictures judge it then).
 */
function lightOnSurface({ thresholds, must, sayAs, numbers }, read) {
  const say = sayAs('orbit-light');
  if (!read || read.why) return false;
  numbers.lightOnSurface = read;
  const words = `on the page's own surface in a lit view along the orbit and in the judged view, the fitted light turns ${fmt(read.turn, 1)}° in the space of its normals, where a light in the eye's space would have turned ${fmt(read.eyeTurn, 1)}° (the camera turns ${fmt(read.cameraTurn, 1)}°: its P·V·M, as the page drew)`;
  const asked = must.has('orbit-toggle');
  // (a light that turned clearly where one in the eye's space would have turned little is not in the eye's space)
  if (read.eyeTurn < thresholds.lightSeparationDegrees && read.turn < thresholds.lightClearTurnDegrees) {
    say(asked ? 'review' : 'pass', `${asked ? '' : 'note: '}the camera turned too little between the lit views seen to tell whether the light stays in the world (${words}; ${thresholds.lightSeparationDegrees}° at least are needed)`);
  } else if (read.eyeTurn >= thresholds.lightSeparationDegrees && read.fromEye < read.turn) {
    say(asked ? 'review' : 'pass', `${asked ? 'the orbit does not show in the shading: ' : 'note: '}while the camera orbits, the lit side stays where it is on screen (${words}; ${fmt(read.fromEye, 1)}° from there): the light moves with the camera (given in eye space, or light and normals in different spaces?)`);
  } else say('pass', `the lit side turns as the camera orbits (${words}): the light stays in the world`);
  return true;
}

/** The lit side turning with the orbit (the lit views' own surfaces, else their sparse fits, `lit`), and the orbit's control. */
export function auditOrbit(context, lit, exact = null) {
  const { facts, thresholds, must, sayAs, numbers } = context;
  const say = sayAs('orbit-light');
  const orbiting = lit.filter((v) => v.orbiting), orbitFits = orbiting.map((v) => v.fit);
  // (two lit views seen along the orbit at least, as on the pictures: one alone may be the judged view)
  const onSurface = must.has('diffuse') && orbitFits.length >= 2 ? lightSpaceOnSurface(context, exact) : null;
  if (onSurface && onSurface.why) numbers.lightOnSurface = onSurface;
  if (must.has('diffuse') && orbitFits.length >= 2 && !lightOnSurface(context, onSurface)) {
    let turn = 0;
    for (let i = 1; i < orbitFits.length; i++) turn = Math.max(turn, angle(orbitFits[0].light, orbitFits[i].light));
    numbers.lightTurn = turn;
    // where the page sent its view matrix: how far a light in the world would have turned on screen
    // between the views (the best fitted view's light, turned as the camera turned). A fit that turns
    // far less than that is a light that moves with the camera, whatever the fits' noise; where the
    // camera's turn moves such a light little (it turned too little, or about the light itself), the
    // fit's own turn tells only when it is clear
    const seen = orbiting.filter((v) => v.camera),
      rs = cameraRotations(
        seen.map((v) => v.camera),
        thresholds.cameraRotationTolerance,
      );
    let apart = null;
    if (rs) {
      const ref = seen.reduce((b, v, k) => (v.fit.r2 > seen[b].fit.r2 ? k : b), 0), l = seen[ref].fit.light;
      apart = Math.max(...rs.map((r) => signedAngle(staysInWorld(rs[ref], r, l), l)));
    }
    const camera = rotationsTurn(rs);
    if (rs) Object.assign(numbers, { cameraTurn: camera, lightTurnIfWorld: apart });
    const why = onSurface ? `; on the pictures: the page's own surface cannot say: ${onSurface.why}` : '';
    const words = `the fitted light turns ${fmt(turn, 1)}° over ${orbitFits.length} views${rs ? `, where a light in the world would have turned ${fmt(apart, 1)}° on screen (the camera turns ${fmt(camera, 1)}°: its view matrix, as the page sent it)` : ''}${why}`;
    // on a sphere only the shading shows the orbit: where the step asks for the orbit (P3) a light that
    // moves with the camera hides it; elsewhere the slides leave the light's space to the student
    if (rs && apart < thresholds.lightSeparationDegrees && turn < thresholds.lightClearTurnDegrees) {
      say(must.has('orbit-toggle') ? 'review' : 'pass', `${must.has('orbit-toggle') ? '' : 'note: '}the camera turned too little between the lit views seen to tell whether the light stays in the world (${words}; ${thresholds.lightSeparationDegrees}° at least are needed)`);
    } else if (turn < Math.max(thresholds.lightTurnDegrees, rs ? thresholds.lightFollowsWorld * apart : 0)) {
      say(must.has('orbit-toggle') ? 'review' : 'pass', `${must.has('orbit-toggle') ? 'the orbit does not show in the shading: ' : 'note: '}while the camera orbits, the lit side stays where it is on screen (${words}): the light moves with the camera (given in eye space, or light and normals in different spaces?)`);
    } else say('pass', `the lit side turns as the camera orbits (${rs ? words : `${fmt(turn, 0)}° over ${orbitFits.length} views${why}`}): the light stays in the world`);
  }
  if (must.has('orbit-toggle')) {
    const sayToggle = sayAs('orbit-toggle');
    const o = facts.orbit;
    const control = o.control === null ? null : facts.controls.find((c) => c.index === o.control);
    if (o.toggles) sayToggle('pass', `a control toggles the orbit on and off (${rolesInWords(facts, thresholds).orbit})`);
    else if (control) sayToggle('review', `${describe(control)} starts the orbit, but nothing found stops it`);
    else if (o.movedAtFirst) sayToggle('review', `the camera orbits, but no button toggles the orbit: none of the ${facts.level.trials} controls tried stops it (the slide asks for one)`);
    else sayToggle('review', 'no orbit: the picture never moved, and no control named for the orbit starts it');
  }
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'orbit-light', (context, results) => auditOrbit(context, results['lit-views'], results['surface-fit']),
  { also: ['orbit-toggle'], uses: ['lit-views', 'surface-fit'] });
