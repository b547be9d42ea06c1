// The audit unit 'ladder-climbed': a part whose gathering stopped before it climbed the levels ends
// here, said as 'level-ladder' (units/level-ladder.js): nothing past the first frame can be judged.
import { unit, end } from '../unit.js';
import { META as META_LEVEL_LADDER } from './level-ladder.js';

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META_LEVEL_LADDER, 'ladder-climbed',
  ({ facts }) => (facts.ladder ? null : end('the grader stopped before the level ladder', 'level-ladder')), { says: ['level-ladder'] });
