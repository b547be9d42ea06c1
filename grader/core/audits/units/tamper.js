// The audit unit 'tamper' (The page left what the grader reads through alone): Checks that the
// browser's functions and the grader's hooks it reads through are still the ones installed before
// the page ran.
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  tamper: { title: 'The page left what the grader reads through alone', slide: null, failureTitle: 'The page replaced what the grader reads through', description: 'Checks that the browser\'s functions and the grader\'s hooks it reads through are still the ones installed before the page ran.', reads: ['facts.tampered'] },
};

/** A page that replaced what the grader reads through may show one thing and hand the grader another. */
function auditTamper({ facts, sayAs }) {
  if (facts.tampered) sayAs('tamper')('review', `the page replaced or probed what the grader reads it through: ${facts.tampered.join(', ')} (a hand-in must not change the browser's own functions or the grader's, nor draw otherwise under a test driver): what it showed may not be what the grader saw, a teacher looks`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'tamper', auditTamper);
