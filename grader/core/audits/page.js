// What is said of a part before or around its audits (the page missing, not opened, stopped by the
// time bound, linked to another part's page, the grader's own trouble, the browser's own failure,
// a hand-in not unpacked): ids as the audits' are, so that every reason carries one. (A page that
// replaced what the grader reads through, and a part too slow here, are audits: units/tamper.js,
// units/too-slow.js.)
import { SLIDE } from './slides.js';
import { NOT_GRADED } from '../verdict.js';

/** These reasons' ids: id → title, the slide's sentence a miss quotes (or null), what it reads. */
export const META = {
  'page-missing': { title: 'A page for the part in the hand-in', slide: null, failureTitle: 'No page for the part in the hand-in', description: 'Looks for the part\'s page by folder and file name (WP04P1, Part1, p01, …), by section number and step title, and by the page\'s own title.', reads: ['the hand-in'] },
  'page-opens': { title: 'The page opens', slide: SLIDE.sphere, failureTitle: 'The page could not be opened', description: 'Opens the part\'s page in the browser, served from the hand-in\'s own folder with nothing else reachable.', reads: ['the page'] },
  'page-finishes': { title: 'The page finishes within the rubric\'s bound', slide: SLIDE.sphere, failureTitle: 'The page did not finish within the rubric\'s bound', description: 'Gives the page the rubric\'s timeoutSeconds on the wall clock; a page that never returns from a frame fails here.', reads: ['the page'] },
  'linked-page': { title: 'A page of its own, not a link to another part\'s', slide: SLIDE.sphere, failureTitle: 'The page only links to another part\'s page', description: 'A page with no canvas and no script of its own that links to another part\'s page is graded as that part, once.', reads: ['the hand-in'] },
  'not-unpacked': { title: 'The hand-in could be unpacked', slide: null, failureTitle: 'The hand-in could not be unpacked', description: 'Unpacks the course site\'s download within the rubric\'s bounds (files, bytes, depth), zips inside it too.', reads: ['the download'] },
  'not-graded-in-run': { title: 'A part this run did not grade', slide: null, failureTitle: 'Not graded in this run', description: 'A part left out of this run (another shard, or the run stopped before it) is said so, never failed.', reads: [] },
  'browser-failed': { title: 'The browser kept running the page to the end', slide: null, failureTitle: 'The browser failed while grading this page', description: 'Where the browser itself fails (it runs out of memory, loses its connection to the page or the page\'s frame), the part is not graded here, with the browser\'s message: a grade rests on the page, never on the browser that ran it.', reads: ['the page'] },
  'grader-trouble': { title: 'The grader finished on this page', slide: null, failureTitle: 'The grader could not finish on this page', description: 'Where the grader itself fails on a page, the part is a review for a teacher, never a pass.', reads: ['the page'] },
  'page-errors': { title: 'Errors the page reported (no verdict changes)', slide: null, failureTitle: 'The page reported errors', description: 'The page\'s own errors and alerts, listed for the student; they change no verdict.', reads: ['facts.errors'] },
  'not-checked': { title: 'A part the check page cannot check in this browser', slide: null, failureTitle: 'The check page cannot check this part in this browser', description: 'A WebGPU part in a browser without WebGPU is not checked on the check page.', reads: [] },
};

/** A reason `id` said at `level`, as findingsOf gives one ({ id, level, reason }). */
export const finding = (id, level, reason) => ({ id, level, reason });

/** No page for `part` in the hand-in. */
export const missingPage = (part) => finding('page-missing', 'fail', `no page for ${part} was found in the submission`);

/** The page did not finish within the rubric's bound (`why`: what stopped it, if known). */
export const timedOut = (rubric, why) => finding('page-finishes', 'fail', `the page did not finish within the rubric's bound of ${rubric.timeoutSeconds} s (it never returns, or is far too slow)${why ? `: ${why}` : ''}`);

/** The bound ran out at the first frame: a frame that never returns. */
export const stoppedAtFirstFrame = (rubric, what) => finding('page-finishes', 'fail', `the page did not finish within the rubric's bound of ${rubric.timeoutSeconds} s: stopped while ${what} (a frame that never returns?)`);

/**
 * A page past the rubric's bound (or its gatherWork) once it drew, `why` in words (tooSlowWords,
 * tooHeavyWords): too slow here, not broken, at the rubric's tooSlowVerdict.
 */
export const tooSlow = (rubric, why) =>
  rubric.tooSlowVerdict === NOT_GRADED
    ? finding('too-slow', NOT_GRADED, `${NOT_GRADED}: ${why}`)
    : finding('too-slow', rubric.tooSlowVerdict, why);

/** A part's page that only links to another part's page (`to`: { part, page }). */
export const linkedPage = (part, page, to) => finding('linked-page', 'review', `REVIEW: the page for ${part} (${page}) has no canvas and no script of its own: it links to ${to.part}'s page (${to.page}), graded as ${to.part}; a part is not graded twice (does that page do ${part}'s step too? a teacher looks)`);

/** The page could not be opened (`why`). */
export const notOpened = (why) => finding('page-opens', 'fail', `the page could not be opened: ${why}`);

/** A finding that stops a part's judging, as the judging carries it: { fail (the reason), failId }. */
export const asFail = (f) => ({ fail: f.reason, failId: f.id });

// what a browser says when it fails itself, not the page it runs: out of memory, its connection to
// the page (puppeteer's protocol and session, a detached frame), a crashed renderer
const BROWSER_FAILED = /out of memory|Protocol error|detached Frame|frame was detached|Session closed|Connection closed|Target closed|Target crashed|Page crashed/i;

/** Is `err` the browser's own failure (BROWSER_FAILED), not the grader's trouble with the page? */
export const browserFailed = (err) => BROWSER_FAILED.test(String(err && err.message));

/**
 * The browser (`browser`: its name and version, or null) failed while grading the page (`err`):
 * not graded here, with the browser's message and what to do; never a verdict on the page.
 */
export const browserFailure = (err, browser) =>
  finding(
    'browser-failed',
    NOT_GRADED,
    `${NOT_GRADED}: the browser${browser ? ` (${browser})` : ''} failed while grading this page, not the page ("${String(err.message).split('\n')[0]}"): grade this part again, or in the other browser (--browser)`,
  );

/** The grader's own trouble with a page (`err`): never a pass on it, a teacher looks. A check. */
export const graderTrouble = (err) => finding('grader-trouble', 'review', `the grader could not finish on this page: ${err.message.split('\n')[0]}`);

/**
 * What a part gathered with an error `err` is judged by: the browser's own failure (browserFailed)
 * is { notGraded, notGradedId } (browserFailure), the grader's own trouble { checks: [graderTrouble] }.
 */
export function troubleWith(err, browser) {
  if (!browserFailed(err)) return { checks: [graderTrouble(err)] };
  const f = browserFailure(err, browser);
  return { checks: [], notGraded: f.reason, notGradedId: f.id };
}
