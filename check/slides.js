// What the check page's cards link and quote: the slide's sentence a part misses (the grader's
// core/audits/missed-slides.js, shared with the feedback pages) and our step that does it right.
export { missedSlides } from '../grader/core/audits/missed-slides.js';

/** Our own step for a part, relative to the check page. */
export const stepLink = (part) => `../${part}/`;
