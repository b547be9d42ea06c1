// The audit unit 'too-slow' (Gathered within the rubric's bounds): Gathers within counted budgets
// and the rubric's time and work bounds; a part past them is not graded here (or the rubric's
// tooSlowVerdict), never failed for being slow.
import { NOT_GRADED, tooSlowWords, tooHeavyWords } from '../../verdict.js';
import { unit, end } from '../unit.js';
import { tooSlow } from '../page.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'too-slow': { title: 'Gathered within the rubric\'s bounds', slide: null, failureTitle: 'Too slow to judge here', description: 'Gathers within counted budgets and the rubric\'s time and work bounds; a part past them is not graded here (or the rubric\'s tooSlowVerdict), never failed for being slow.', reads: ['facts.tooSlow', 'facts.tooHeavy'] },
};

/**
 * Nothing is judged where the gathering ran out of its bound: where it ran out depends on the
 * machine, the verdict must not. A page that draws is not broken for being slow: not graded here
 * (the rubric's tooSlowVerdict), or said at that verdict.
 */
function auditTooSlow(context) {
  const { facts, rubric, sayAs } = context;
  if (!facts.tooSlow) return null;
  const slow = tooSlow(
    rubric,
    facts.tooHeavy != null ? tooHeavyWords(rubric, facts.tooSlow, facts.tooHeavy) : tooSlowWords(rubric, facts.tooSlow),
  );
  if (slow.level === NOT_GRADED) context.notGraded = { reason: slow.reason, id: slow.id };
  else sayAs(slow.id)(slow.level, slow.reason);
  return end();
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'too-slow', auditTooSlow);
