// The audit unit 'level-ladder' (The level ladder climbed and judged at the last level that
// drew): Subdivides until the silhouette settles, and judges the last level that drew.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'level-ladder': { title: 'The level ladder climbed and judged at the last level that drew', slide: SLIDE.buttons, failureTitle: 'The level ladder was not climbed to the end', description: 'Subdivides until the silhouette settles, and judges the last level that drew.', reads: ['facts.ladder', 'facts.blankAtHigherLevel'] },
};



/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'level-ladder', ({ facts, sayAs }) => {
  if (facts.blankAtHigherLevel) sayAs('level-ladder')('mistake', 'the picture goes blank at a higher level: judged at the last level that drew');
});
