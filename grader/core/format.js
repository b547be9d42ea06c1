// How the grader writes a number in a reason or a record: to d decimals, and a dash for a number
// that was not measured (null, undefined, NaN), so that no reason says "NaN"; a share as a whole per cent.
import { PERCENT } from './units.js';

/** x to d decimals ('–' when x is missing). */
export const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));

/** A share (0–1) as a whole per cent: 0.234 → '23%'. */
export const pct = (x) => `${Math.round(PERCENT * x)}%`;
