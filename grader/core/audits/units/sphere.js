// The audit unit 'sphere' (A round closed sphere, rounder with each level): Fits a circle to the
// outline at the judged level and measures its roundness and fill, level by level.
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { analyse } from '../../measure.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  sphere: { title: 'A round closed sphere, rounder with each level', slide: SLIDE.sphere, failureTitle: 'Not a round closed sphere', description: 'Fits a circle to the outline at the judged level and measures its roundness and fill, level by level.', reads: ['images.judged', 'images.first', 'facts.ladder'] },
};

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

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'sphere', (context, results) => {
  const first = analyse(context.images.first, context.thresholds).roundness;
  return auditSphere(context, results['judged-picture'], context.facts.ladder.map((l) => l.roundness), first);
},
  { uses: ['judged-picture'] });
