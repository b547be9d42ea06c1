// Where the similarity check finds a hand-in's parts: the grader's own part finder, re-exported
// here only, so that the check follows the grader when its modules move.
export { PARTS, findParts } from '../node/parts.js';
