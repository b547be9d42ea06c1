// The audit unit 'orbit-not-stopped': an orbit the grader could not stop, said as a note of
// 'orbit-stops' (units/orbit-stops-again.js): the pictures were judged as it moves.
import { unit } from '../unit.js';
import { META as META_ORBIT_STOPS_AGAIN } from './orbit-stops-again.js';

/** The orbit could not be stopped: said as a note. */
export function auditNotStopped({ facts, sayAs }) {
  const say = sayAs('orbit-stops');
  if (!facts.stopped) say('pass', 'note: the orbit could not be stopped: the pictures were judged as it moves');
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META_ORBIT_STOPS_AGAIN, 'orbit-not-stopped', auditNotStopped, { says: ['orbit-stops'] });
