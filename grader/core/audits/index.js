// Every audit by its id (Lighthouse's audit meta): its title, the title a part that misses it gets
// (failureTitle), what it checks (description), the slide's sentence it checks (null
// where a miss names none: the page, not the step), a note shown beside that sentence, and the
// artifacts it reads. A reason carries its audit's id (verdict.js), and the check page, the
// feedback pages, grades.csv and the grader's README find a reason's slide and its column by that
// id, never by its words.
import { META as page } from './page.js';
import { AUDIT_LIST } from './list.js';

/** id → { id, title, failureTitle, description, slide, note?, reads, module }: module, the unit that declares it (units/<id>.js), or page. */
export const AUDITS = {};
const declare = (id, m, module) => {
  // (a unit that says another's id shares that unit's declaration: the same object, declared once)
  if (AUDITS[id] && AUDITS[id].declared !== m) throw new Error(`audit id ${id} is declared in both ${AUDITS[id].module} and ${module}`);
  if (!AUDITS[id]) AUDITS[id] = Object.defineProperty({ id, ...m, module }, 'declared', { value: m, enumerable: false });
};
for (const [id, m] of Object.entries(page)) declare(id, m, 'page');
for (const u of AUDIT_LIST) for (const [id, m] of Object.entries(u.meta)) declare(id, m, u.id);

/** `id`'s meta; throws for an id no audit declares (a reason must carry a declared id). */
export function auditMeta(id) {
  const m = AUDITS[id];
  if (!m) throw new Error(`no audit has the id ${id}`);
  return m;
}
