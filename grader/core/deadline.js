// The grader's outer bound on a part: timeoutSeconds on the wall clock, and past deadlineShare of
// it the gathering stops and the part is too slow to judge here, with time left to write what was
// seen. One rule for npm run grade (node/run-part.js) and the check page (check/runner.js).
import { MS_PER_SECOND } from './units.js';

/** The wall time (ms, on the clock `started` was read from) past which a part started at `started` is too slow. */
export const deadlineOf = (started, rubric) => started + rubric.deadlineShare * rubric.timeoutSeconds * MS_PER_SECOND;
