// The audit unit 'all-round' (Closed from every side seen along the orbit): Where the mesh cannot
// be read, looks at the outline at counted positions while the camera turns all the way round.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { pct } from '../../format.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'all-round': { title: 'Closed from every side seen along the orbit', slide: SLIDE.sphere, failureTitle: 'Not closed from every side along the orbit', description: 'Where the mesh cannot be read, looks at the outline at counted positions while the camera turns all the way round.', reads: ['facts.allRound'] },
};

/**
 * Where the mesh could not be read (positions made in a shader), the outlines seen all round the
 * orbit (gather/all-round.js): a round outline with a gap in it is a hole on that side. Views whose
 * outline is not round (an unlit side merging with the background) tell nothing and are left out.
 */
export function auditAllRound({ facts, thresholds, sayAs, numbers, imagesShown }) {
  const say = sayAs('all-round');
  const r = facts.allRound;
  if (!r) return;
  const round = r.views.filter((v) => !v.blank && v.roundness <= thresholds.roundness);
  const gaps = round.filter((v) => v.fill < thresholds.fill);
  numbers.allRound = { views: r.views.length, round: round.length, gaps: gaps.length, turned: r.turned };
  const where = r.turned !== null ? `at ${r.views.length} positions along the orbit, the camera turning ${Math.round(r.turned)}°` : `at ${r.views.length} positions along the orbit (the page sends no view matrix the grader could read: how far it turned is not known)`;
  const why = `the mesh could not be read from what the page sent (${r.why})`;
  if (gaps.length) {
    if (r.gap) imagesShown.allRoundGap = r.gap;
    say('mistake', `a hole shows from some side: looked ${where}, ${gaps.length} of ${round.length} round outlines are not filled (down to ${pct(Math.min(...gaps.map((v) => v.fill)))}: the background shows through the sphere) (${why})`);
  } else if (round.length) {
    say('pass', `closed from every side it was seen from: ${round.length} round, filled outlines ${where} (${why}, so it was looked at all round)`);
  } else say('pass', `note: could not see whether the sphere is closed all round: no view ${where} showed a round outline (${why})`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'all-round', auditAllRound);
