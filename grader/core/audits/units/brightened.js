// The audit unit 'brightened' (A picture too dim, read with the light raised): Where the picture
// is too dark, raises the page's own light and reads the shading there; the note says so.
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { noteReadAgain, settings } from '../diffuse.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  brightened: { title: 'A picture too dim, read with the light raised', slide: SLIDE.diffuse, failureTitle: 'The picture is too dim to read', description: 'Where the picture is too dark, raises the page\'s own light and reads the shading there; the note says so.', reads: ['facts.brightened'] },
};

/** Where the picture was too dim to show its shading, the slider the gatherer raised to read it (facts.brightened). */
export function auditBrightened(context) {
  noteReadAgain(context, 'brightened', context.facts.brightened, (b) => `note: the sphere is too dim to show its shading (brightness spread ${fmt(b.before, 3)}: a dark light); it was judged with the page's own slider raised: ${settings(b.steps)} (spread ${fmt(b.after, 3)} then)`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'brightened', (context, { shading }) => (shading.shaded ? auditBrightened(context) : null),
  { uses: ['shading'] });
