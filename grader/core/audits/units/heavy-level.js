// The audit unit 'heavy-level' (The level climb ended by a heavy frame): Stops subdividing where
// a frame's work passes heavyLevelWork once the sphere is round enough.
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { PERCENT, THOUSAND } from '../../units.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'heavy-level': { title: 'The level climb ended by a heavy frame', slide: SLIDE.buttons, failureTitle: 'The level climb ended at a heavy frame', description: 'Stops subdividing where a frame\'s work passes heavyLevelWork once the sphere is round enough.', reads: ['facts.heavyLevel', 'facts.ladder'] },
};

/** A level with heavy work a frame ended the climb: said as a note. */
export function auditHeavyLevel({ facts, sayAs }) {
  const say = sayAs('heavy-level');
  const last = facts.ladder[facts.ladder.length - 1];
  if (facts.heavyLevel) say('pass', `note: the last level reached draws ${fmt(facts.heavyLevel / THOUSAND, 0)}k vertices a frame; with the sphere round to ${fmt(PERCENT * last.roundness, 1)}% there, no finer level was tried (each has four times the triangles)`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'heavy-level', auditHeavyLevel);
