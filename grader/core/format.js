// How the grader writes a number in a reason or a record: to d decimals, and a dash for a number
// that was not measured (null, undefined, NaN), so that no reason says "NaN".

/** x to d decimals ('–' when x is missing). */
export const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));
