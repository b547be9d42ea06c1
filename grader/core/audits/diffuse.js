// What the audits of a picture read again with the page's own controls share (units/unclipped.js,
// brightened.js): the settings made, in words, and the note said with the picture read.

/** The settings a gatherer made to see the shading, in words: "kd to 0.8, then Le to 0.75". */
export const settings = (steps) => steps.map((x) => `${x.role} to ${x.value}`).join(', then ');

/**
 * The note of audit `id` where the gatherer read the picture again with the page's own controls
 * (`seen`: facts.unclipped or facts.brightened, { image, steps, ... }): `words(seen)`, with its picture.
 */
export function noteReadAgain({ sayAs, imagesShown }, id, seen, words) {
  if (!seen) return;
  imagesShown[id] = seen.image;
  sayAs(id)('pass', words(seen));
}
