// The audit unit 'too-slow' (Gathered within the rubric's bounds): Gathers within counted budgets
// and the rubric's time and work bounds; a part past them is not graded here (or the rubric's
// tooSlowVerdict), never failed for being slow; but a mistake already found in the page's own
// record stands, and the rest is said not to have been judged.
import { NOT_GRADED, tooSlowWords, tooHeavyWords } from '../../verdict.js';
import { unit, end } from '../unit.js';
import { tooSlow, browserFailure } from '../page.js';
import { UNIT as growth } from './growth.js';
import { UNIT as winding } from './winding.js';

/**
 * The units whose evidence is the page's own record of what it sent, complete once read, whatever
 * the gathering did later: the vertices of its first frames (growth), the winding of the triangles
 * it uploaded against the culling it set (winding). A mistake they find stands where the gathering
 * stopped on a bound after it.
 */
const ON_RECORD = [growth, winding];

/** Runs the ON_RECORD units on `context`; returns the mistakes they said ({ id, level, reason }). */
function mistakesOnRecord(context, results) {
  const said = [];
  const sayAs = (id) => {
    const say = context.sayAs(id);
    return (level, reason) => {
      if (level !== 'pass') said.push({ id, level, reason });
      say(level, reason);
    };
  };
  for (const u of ON_RECORD) u.run({ ...context, sayAs }, results);
  return said;
}

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'too-slow': { title: 'Gathered within the rubric\'s bounds', slide: null, failureTitle: 'Too slow to judge here', description: 'Gathers within counted budgets and the rubric\'s time and work bounds; a part past them is not graded here (or the rubric\'s tooSlowVerdict), never failed for being slow, and a part whose browser failed itself is not graded here, unless a mistake was already read from what the page sent (its mesh growing every frame, its winding against its culling): then that mistake stands and the rest is said not judged.', reads: ['facts.tooSlow', 'facts.tooHeavy', 'facts.browserFailed'] },
};

/**
 * Nothing more is judged where the gathering ran out of its bound: where it ran out depends on the
 * machine, the verdict must not. A page that draws is not broken for being slow: not graded here
 * (the rubric's tooSlowVerdict), or said at that verdict. But a mistake read from the page's own
 * record before the bound (ON_RECORD) is a mistake on any machine: it stands, with the rest said
 * not judged.
 */
function auditTooSlow(context, results) {
  const { facts, rubric, sayAs } = context;
  if (facts.browserFailed) return auditBrowserFailed(context, results);
  if (!facts.tooSlow) return null;
  const words = (judged) => (facts.tooHeavy != null
    ? tooHeavyWords(rubric, facts.tooSlow, facts.tooHeavy, judged) : tooSlowWords(rubric, facts.tooSlow, judged));
  const slow = tooSlow(rubric, words());
  const found = mistakesOnRecord(context, results);
  if (found.length && slow.level === NOT_GRADED) {
    sayAs(slow.id)('mistake', `the rest was not judged: ${words(onlyBefore(found))}`);
  } else if (slow.level === NOT_GRADED) context.notGraded = { reason: slow.reason, id: slow.id };
  else sayAs(slow.id)(slow.level, slow.reason);
  return end();
}

/** What was judged of a part stopped after `found` (the mistakes on record), in words. */
const onlyBefore = (found) => `only what the page sent before was read (${found.map((f) => f.id).join(', ')})`;

/**
 * The browser failed itself while gathering (its renderer crashed: facts.browserFailed, { message,
 * doing }): not the page's doing, so not graded here, unless a mistake was read on record before.
 */
function auditBrowserFailed(context, results) {
  const { message, doing } = context.facts.browserFailed;
  const found = mistakesOnRecord(context, results);
  const failed = `the browser failed while ${doing}, not the page ("${message}")`;
  if (found.length) context.sayAs('too-slow')('mistake', `the rest was not judged: ${failed}; ${onlyBefore(found)}`);
  else context.notGraded = { reason: browserFailure({ message }, null).reason, id: 'browser-failed' };
  return end();
}

/** The unit (audits/list.js runs it in its order). */
const onRecordReads = ON_RECORD.flatMap((u) => Object.values(u.meta).flatMap((m) => m.reads));
export const UNIT = unit(META, 'too-slow', auditTooSlow, { reads: onRecordReads });
