// The units the grader's core and the check page count in, each named once for what it is: never
// a bound on what a page shows (those are the rubric's, grader/core/rubric.json).

/** A share as a percentage: PERCENT × share. */
export const PERCENT = 100;
/** Milliseconds in a second. */
export const MS_PER_SECOND = 1000;
/** One frame of the frozen clock at 60 Hz, in whole milliseconds (the page's time steps by it). */
export const FRAME_MS = 16;
/** A colour channel's greatest byte (also an opaque alpha). */
export const CHANNEL_MAX = 255;
/** The greatest sum of a pixel's three channels, R + G + B. */
export const RGB_MAX = 3 * CHANNEL_MAX;
/** Half a turn in degrees (π radians): degrees = HALF_TURN / π × radians. */
export const HALF_TURN = 180;
/** A right angle in degrees. */
export const RIGHT_ANGLE = 90;
/** A whole turn in degrees. */
export const FULL_TURN = 360;
/** The entries of a 4×4 matrix. */
export const MAT4_ENTRIES = 16;
/** Rounding to millionths: Math.round(x × MILLIONTHS) / MILLIONTHS. */
export const MILLIONTHS = 1e6;
/** Rounding to thousandths. */
export const THOUSANDTHS = 1000;
/** Rounding to hundredths. */
export const HUNDREDTHS = 100;
/** Counts said in thousands (k) and in millions. */
export const THOUSAND = 1000;
export const MILLION = 1e6;
/** Bytes in a kibibyte. */
export const KIB = 1024;
