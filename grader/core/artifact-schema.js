// The shape of a part's artifact (facts.json), by number: `schema` says which shape a file has,
// and an artifact of an older shape is brought to today's here, in one place, so that no audit
// guesses a shape. Shapes:
//   1: no `schema` key; a role in facts.roles may be a sentence (written before roles were kept as
//      facts: the control, its description and a word for what was seen)
//   2: `schema` is 2; every role is an object
//   3: the rubric's `must` (kept in gatheredWith, as the gathering read it) lists audit ids, not the
//      older names (MUST_RENAMED in core/rubric.js) (today's)
import { mustIds } from './rubric.js';

// a rubric key that lists a part's musts (parts.WP04P3.must)
const mustKey = (k) => /^parts\.[^.]+\.must$/.test(k);
/** An object with each value v at key k replaced by f(v, k), in the same key order. */
const mapValues = (o, f) => Object.fromEntries(Object.entries(o).map(([k, v]) => [k, f(v, k)]));

/** The shape the grader writes and audits. */
export const ARTIFACT_SCHEMA = 3;

/** What each older shape needs to become the next one: schema → (facts) → facts. */
const UPGRADES = {
  1: (facts) => ({
    ...facts,
    ...(facts.roles ? { roles: mapValues(facts.roles, (r) => (typeof r === 'string' ? { words: r } : r)) } : {}),
  }),
  2: (facts) => ({
    ...facts,
    ...(facts.gatheredWith
      ? { gatheredWith: mapValues(facts.gatheredWith, (v, k) => (mustKey(k) && Array.isArray(v) ? mustIds(v) : v)) }
      : {}),
  }),
};

/** An artifact's facts read from a file, in today's shape (`schema` set); throws on a shape newer than this grader's. */
export function currentFacts(facts) {
  let from = facts.schema ?? 1;
  if (!Number.isInteger(from) || from < 1) throw new Error(`this artifact's schema (${JSON.stringify(facts.schema)}) is not one the grader knows`);
  if (from > ARTIFACT_SCHEMA) throw new Error(`this artifact was written by a newer grader (schema ${from}; this grader reads up to ${ARTIFACT_SCHEMA}): grade it with that grader, or gather it again`);
  let out = facts;
  for (; from < ARTIFACT_SCHEMA; from++) out = UPGRADES[from](out);
  return { ...out, schema: ARTIFACT_SCHEMA };
}
