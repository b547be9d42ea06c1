// "Draw a solid sphere": the subdivision controls, a round closed outline at the judged level, and
// the outline getting rounder with each level.
import { fmt } from '../format.js';
import { SLIDE } from './slides.js';
import { rolesInWords } from '../computed/roles.js';
import { sphereView } from '../computed/evidence.js';
import { analyse } from '../measure.js';
import { unit, end } from './unit.js';
import { PERCENT, THOUSAND } from '../units.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'level-controls': { title: 'Controls that subdivide and coarsen the sphere', slide: SLIDE.buttons, failureTitle: 'No controls that subdivide and coarsen the sphere', description: 'Finds the controls by what they do to the outline (rounder, coarser), whatever they are named: buttons, keys, sliders, menus.', reads: ['facts.level', 'facts.roles'] },
  'heavy-level': { title: 'The level climb ended by a heavy frame', slide: SLIDE.buttons, failureTitle: 'The level climb ended at a heavy frame', description: 'Stops subdividing where a frame\'s work passes heavyLevelWork once the sphere is round enough.', reads: ['facts.heavyLevel', 'facts.ladder'] },
  sphere: { title: 'A round closed sphere, rounder with each level', slide: SLIDE.sphere, failureTitle: 'Not a round closed sphere', description: 'Fits a circle to the outline at the judged level and measures its roundness and fill, level by level.', reads: ['images.judged', 'images.first', 'facts.ladder'] },
};

/** The slide's Subdivide and Coarsen buttons, as found by their effect. */
export function auditLevelControls({ facts, thresholds, must, sayAs }) {
  const say = sayAs('level-controls');
  const L = facts.level;
  if (!must.has('level-controls') || !L) return;
  const hasLevel = L.subdivide || L.slider;
  const roles = rolesInWords(facts, thresholds);
  if (hasLevel) say('pass', `has controls to subdivide (${roles.subdivide || roles.levelSlider})`);
  else if (!L.stopped) say('review', 'the level controls could not be looked for: the picture never stood still');
  else say('review', `nothing found that makes the sphere finer: ${L.trials} controls tried${L.valued ? ', sliders and menus stepped' : ''}, and the arrow, + and − keys pressed (the slide asks for Subdivide and Coarsen buttons)`);
  if (L.subdivide && !L.coarsen && !L.slider) say('review', 'nothing found that makes the sphere coarser (the slide asks for a Coarsen button too)');
}

/** A level with heavy work a frame ended the climb: said as a note. */
export function auditHeavyLevel({ facts, sayAs }) {
  const say = sayAs('heavy-level');
  const last = facts.ladder[facts.ladder.length - 1];
  if (facts.heavyLevel) say('pass', `note: the last level reached draws ${fmt(facts.heavyLevel / THOUSAND, 0)}k vertices a frame; with the sphere round to ${fmt(PERCENT * last.roundness, 1)}% there, no finer level was tried (each has four times the triangles)`);
}

/**
 * A round closed sphere at the judged level (`judged`: { an, circleArc }), and rounder with each
 * level (`ladder`: each level's roundness, as climbed; `firstRoundness`: the first frame's).
 */
export function auditSphere({ thresholds, sayAs, numbers }, judged, ladder, firstRoundness) {
  const say = sayAs('sphere');
  const { an, circleArc } = judged;
  Object.assign(numbers, {
    radius: an.radius,
    roundness: an.roundness,
    fill: an.fill,
    coverage: an.coverage,
    firstRoundness,
    levelsSeen: ladder.length,
  });
  if (circleArc) say('pass', `part of the sphere is as dark as the background: its outline was fitted to the lit edge (${circleArc}° of a circle)`);
  if (an.radius < thresholds.minRadiusPixels) say('review', `the sphere is very small on screen (${fmt(an.radius, 0)} px radius): hard to judge`);
  else if (an.roundness <= thresholds.roundness && an.fill >= thresholds.fill) {
    say('pass', `a round closed sphere (radius ${fmt(an.radius, 0)} px, roundness ${fmt(an.roundness, 3)})`);
  } else if (an.touches) say('review', 'the object touches the canvas edge: its silhouette cannot be judged');
  else say('mistake', `the object is not a round closed sphere (roundness ${fmt(an.roundness, 3)}, fill ${fmt(an.fill)}${ladder.length > 1 ? ', after subdividing' : ''})`);
  if (ladder.length > 2) {
    const rs = ladder.filter((r) => Number.isFinite(r));
    if (rs[0] > rs[rs.length - 1] + thresholds.rounderBy) say('pass', `rounder with each level (roundness ${fmt(rs[0], 3)} → ${fmt(rs[rs.length - 1], 3)})`);
  }
}

/**
 * The judged picture (the level judged, as facts.judged names it) and its sphere's outline ({ img,
 * an, raw, circleArc }, for the units that use it), or the end of the judging where it is blank.
 */
function judgedPicture({ facts, images, thresholds, imagesShown }) {
  imagesShown.judged = facts.facesImage || facts.judged;
  const img = images[facts.judged];
  const raw = analyse(img, thresholds);
  if (raw.blank) return end('the picture went blank after the controls were used', 'sphere');
  const { an, circleArc } = sphereView(img, thresholds);
  return { img, an, raw, circleArc };
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  unit(META, 'heavy-level', auditHeavyLevel),
  unit(META, 'level-controls', auditLevelControls),
  unit(META, 'judged-picture', judgedPicture, { says: ['sphere'], reads: ['facts.judged', 'facts.facesImage'] }),
  unit(META, 'sphere', (context, results) => {
    const first = analyse(context.images.first, context.thresholds).roundness;
    return auditSphere(context, results['judged-picture'], context.facts.ladder.map((l) => l.roundness), first);
  },
    { uses: ['judged-picture'] }),
];
