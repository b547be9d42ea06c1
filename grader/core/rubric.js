// A teacher's rubric over the default one (grader/core/rubric.json): the command line
// (grader/node/grade.js) merges with it, and the check page can too: plain data, no Node.

/**
 * The rubric a part is graded with: the default `base`, and the teacher's `teacher` in its place
 * where it says something. Keys it leaves out keep the defaults, one level down too: a threshold,
 * a control pattern or a part's key (title, must, sliders, ...) left out keeps the default's.
 * @param {object} base the default rubric (grader/core/rubric.json)
 * @param {object} [teacher] a teacher's rubric (parsed JSON), or none
 */
export function mergeRubric(base, teacher) {
  if (!teacher) return base;
  const parts = { ...base.parts };
  for (const [k, v] of Object.entries(teacher.parts || {})) parts[k] = { ...(base.parts[k] || {}), ...v };
  // (the intake's bounds and the grade files' points are merged key by key too, a part's weight as well)
  const unpack = { ...base.unpack, ...(teacher.unpack || {}) };
  const points = { ...base.points, ...(teacher.points || {}), weights: { ...(base.points || {}).weights, ...((teacher.points || {}).weights || {}) } };
  return { ...base, ...teacher, thresholds: { ...base.thresholds, ...(teacher.thresholds || {}) }, controls: { ...base.controls, ...(teacher.controls || {}) }, parts, unpack, points };
}
