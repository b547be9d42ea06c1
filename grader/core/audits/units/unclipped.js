// The audit unit 'unclipped' (A picture clipped to white, read with the sliders lowered): Where
// the picture saturates, lowers the page's own sliders and reads the shading there; the note says
// so.
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { PERCENT } from '../../units.js';
import { noteReadAgain, settings } from '../diffuse.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  unclipped: { title: 'A picture clipped to white, read with the sliders lowered', slide: SLIDE.diffuse, failureTitle: 'The picture clipped to white', description: 'Where the picture saturates, lowers the page\'s own sliders and reads the shading there; the note says so.', reads: ['facts.unclipped'] },
};

/** Where the picture clipped to white, the sliders the gatherer lowered to read its shading (facts.unclipped). */
export function auditUnclipped(context) {
  noteReadAgain(context, 'unclipped', context.facts.unclipped, (u) => {
    const sliders = `slider${u.steps.length > 1 ? 's' : ''}`;
    return `note: the picture clips to white over ${fmt(PERCENT * u.before, 0)}% of the sphere, which hides its shading and highlight; they were judged with the page's own ${sliders} lowered: ${settings(u.steps)} (${fmt(PERCENT * u.after, 0)}% white then)`;
  });
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'unclipped', (context, { shading }) => (shading.shaded ? auditUnclipped(context) : null),
  { uses: ['shading'] });
