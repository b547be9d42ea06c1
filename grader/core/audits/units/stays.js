// The audit unit 'stays' (The page stays where the grader opened it): what a page tried that would
// have closed its window or left it (grader/browser/stay.js kept it open, and the grading went on),
// said with the control clicked last. Closing the window, leaving for another page or going back
// is not a mistake of the step: a note. A control that loads the page again (a button inside a
// <form> sends it, a reload) undoes in a browser what the click did, as the page starts over: the
// grader judged the page it kept, and a teacher looks (review).
import { unit } from '../unit.js';
import { describe } from '../../controls.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  stays: { title: 'The page stays where the grader opened it', slide: null, failureTitle: 'A control loads the page again', description: 'A page\'s window.close() does nothing, and a navigation that would leave the loaded page (a link, location, a form sent, a reload, history.back()) is cancelled and the grading goes on: closing or leaving is a note naming the control; loading the page again, which undoes in a browser what the click did, is a review.', reads: ['facts.stayed', 'facts.controls'] },
};

// what each attempt would have done, in words
const TRIED = {
  close: () => 'tried to close the window: the grader kept it open',
  leave: (to) => `tried to leave the page for ${to}: the grader kept the page`,
  back: () => 'tried to go back in the browser\'s history: the grader kept the page',
};

/** Says what the page tried (facts.stayed: [{ what, to, control }]): the controls that load the page again at once, the rest each once. */
function auditStays({ facts, sayAs }) {
  const say = sayAs('stays');
  const who = (control) => {
    const c = control === null ? null : (facts.controls || []).find((k) => k.index === control);
    return c ? `the ${describe(c)}` : 'the page';
  };
  const again = (facts.stayed || []).filter((t) => t.what === 'again').map((t) => who(t.control));
  if (again.length) {
    const how = again.includes('the page') ? 'the page loads itself again once loaded (a reload, or a form sent): in a browser it starts over'
      : `${again.join(' and ')} load${again.length > 1 ? '' : 's'} the page again (a button sends the form it is in, or a reload): in a browser the page starts over and what the click did is lost`;
    say('review', `${how}; the grader kept the page and judged the rest, a teacher looks`);
  }
  for (const { what, to, control } of facts.stayed || []) {
    if (what !== 'again') say('pass', `note: ${who(control)} ${(TRIED[what] || TRIED.leave)(to)} (not a mistake of the step; the grading went on)`);
  }
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'stays', auditStays);
