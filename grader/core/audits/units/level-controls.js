// The audit unit 'level-controls' (Controls that subdivide and coarsen the sphere): Finds the
// controls by what they do to the outline (rounder, coarser), whatever they are named: buttons,
// keys, sliders, menus.
import { SLIDE } from '../slides.js';
import { rolesInWords } from '../../computed/roles.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'level-controls': { title: 'Controls that subdivide and coarsen the sphere', slide: SLIDE.buttons, failureTitle: 'No controls that subdivide and coarsen the sphere', description: 'Finds the controls by what they do to the outline (rounder, coarser), whatever they are named: buttons, keys, sliders, menus.', reads: ['facts.level', 'facts.roles'] },
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

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'level-controls', auditLevelControls);
