// The audit unit 'loops-multiply' (One animation loop, however often a control is used): Counts
// the animation loops and the draws a frame before and after the grader's clicks; a note, never a
// change of verdict.
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'loops-multiply': { title: 'One animation loop, however often a control is used', slide: null, failureTitle: 'Each click starts another animation loop', description: 'Counts the animation loops and the draws a frame before and after the grader\'s clicks; a note, never a change of verdict.', reads: ['facts.frameDraws'] },
};

/**
 * A page whose controls each start another animation loop (a click runs init() again, or calls the
 * loop's function that asks for the next frame): after the grader's clicks it runs several loops a
 * frame and draws its sphere as many times. Said to the student as a note; the verdict stands on the
 * pictures.
 */
export function auditLoopsMultiply({ facts, thresholds, sayAs, numbers }) {
  const f = facts.frameDraws;
  if (!f || !f.first || !f.last || !f.clicks || !(f.first.loops >= 1) || !(f.first.draws > 0)) return;
  if (
    f.last.loops < thresholds.loopsMultiplied * f.first.loops ||
    f.last.draws < thresholds.loopsMultiplied * f.first.draws
  ) {
    return;
  }
  numbers.frameDraws = f;
  // (the loops are counted exactly; the draws a frame also hold a click's own drawing)
  sayAs('loops-multiply')('pass', `note: the page draws its sphere ${f.last.loops} times a frame after ${f.clicks} click${f.clicks === 1 ? '' : 's'} (${f.last.loops} animation loops, where it started with ${f.first.loops}; ${f.last.draws} draw calls a frame, ${f.first.draws} at first): each click starts another animation loop, so the orbit speeds up and the page slows`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'loops-multiply', auditLoopsMultiply);
