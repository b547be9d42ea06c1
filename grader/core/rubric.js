// A teacher's rubric over the default one (grader/core/rubric.json): the command line
// (grader/node/cli/grade.js) merges with it, and the check page can too: plain data, no Node.
import { AUDITS } from './audits/index.js';

/** The names a part's `must` had before it listed audit ids, and the audit each one is. */
export const MUST_RENAMED = { subdivideControls: 'level-controls', normalColours: 'normal-colours', frontFaces: 'front-faces', depthCulling: 'depth-culling',
  orbitToggle: 'orbit-toggle', perFragment: 'per-fragment', sliderEffects: 'sliders' };

/** A `must` list in audit ids: an older name read as its id, each once, in its order. */
export const mustIds = (must) => [...new Set(must.map((x) => MUST_RENAMED[x] || x))];

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
  for (const [k, v] of Object.entries(teacher.parts || {})) {
    parts[k] = { ...(base.parts[k] || {}), ...v };
    if (v.must !== undefined) parts[k].must = checkedMust(v.must, k);
  }
  // (the intake's bounds and the grade files' points are merged key by key too, a part's weight as well)
  const unpack = { ...base.unpack, ...(teacher.unpack || {}) };
  const points = {
    ...base.points,
    ...(teacher.points || {}),
    weights: { ...(base.points || {}).weights, ...((teacher.points || {}).weights || {}) },
  };
  return {
    ...base,
    ...teacher,
    thresholds: { ...base.thresholds, ...(teacher.thresholds || {}) },
    controls: { ...base.controls, ...(teacher.controls || {}) },
    parts,
    unpack,
    points,
  };
}

/** A teacher's `must` for `part`, in audit ids; throws, naming them, on a list that is not one or on an id no audit has. */
function checkedMust(must, part) {
  if (!Array.isArray(must) || must.some((x) => typeof x !== 'string')) throw new Error(`the rubric's parts.${part}.must is not a list of audit ids (it is ${JSON.stringify(must)})`);
  const ids = mustIds(must);
  const unknown = ids.filter((x) => !AUDITS[x]);
  if (unknown.length) {
    throw new Error(`the rubric's parts.${part}.must names ${unknown.map((x) => `"${x}"`).join(', ')}, which no audit has: a part's must lists audit ids (grader/README.md, the table of audit units), such as ${Object.values(MUST_RENAMED).slice(0, 4).join(', ')}`);
  }
  return ids;
}
