// What the audits of a picture read again with the page's own controls share (units/unclipped.js,
// brightened.js): the settings made, in words.

/** The settings a gatherer made to see the shading, in words: "kd to 0.8, then Le to 0.75". */
export const settings = (steps) => steps.map((x) => `${x.role} to ${x.value}`).join(', then ');
