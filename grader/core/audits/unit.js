// An audit as a declared unit (Lighthouse's audit, as this grader runs it): an id, the ids of the
// reasons it says with each one's meta (title, the slide's sentence, the artifacts it reads), the
// units whose results it reads, and one pure function run(context, results). audits/list.js puts
// the units in the order they run; core/audit.js runs that list and nothing else.
//
// A unit's result is results[id] for the units after it that name it in `uses`. A unit that ends
// the part's judging (nothing more can be judged: the part is too slow here, it drew nothing, its
// picture went blank) returns end(fail, failId).

/**
 * A unit from its module's META (id → { title, failureTitle (its heading where a part misses it),
 * description (what it checks, in a sentence), slide, note?, reads }): it says `id` and the ids in
 * `also`; it reads the results of `uses`; `reads` names the facts it reads besides its ids' own
 * (a unit that says nothing, a reading other units use, names them there).
 */
export function unit(META, id, run, { also = [], uses = [], reads = [], says = [id, ...also] } = {}) {
  const meta = {};
  for (const s of says) {
    if (!META[s]) throw new Error(`the unit ${id} says ${s}, which its module's META does not declare`);
    if (!META[s].failureTitle || !META[s].description) throw new Error(`the audit ${s} declares no failureTitle or description (the words a part that misses it gets, and what it checks)`);
    meta[s] = META[s];
  }
  return { id, meta, uses, reads, run };
}

/** What a unit returns to end the part's judging: `fail` (the reason the part cannot be judged, or null: nothing more to judge) said by `failId`. */
export const end = (fail = null, failId = null) => ({ end: { fail, failId } });

/** The facts a unit reads (the keys after "facts."): its ids' reads and its own. */
export function requiredFacts(u) {
  const all = [...Object.values(u.meta).flatMap((m) => m.reads), ...u.reads];
  return [...new Set(all.filter((r) => r.startsWith('facts.')).map((r) => r.slice('facts.'.length)))];
}
