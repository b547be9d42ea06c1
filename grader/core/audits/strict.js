// The audit units run strictly, as the tests run them: a unit that reads a fact it does not name
// (unit.js's requiredFacts) or says an id its meta does not declare throws, naming both. The
// judging is otherwise the same: what a unit sets on its context (notGraded) is set on the audit's.
import { requiredFacts } from './unit.js';

/** `units` (AUDIT_LIST's shape), each run strictly. */
export function strictly(units) {
  return units.map((u) => {
    const may = new Set(requiredFacts(u));
    return { ...u, run: (context, results) => {
      const facts = new Proxy(context.facts, { get: (o, k) => {
        if (typeof k === 'string' && !may.has(k)) throw new Error(`the audit unit ${u.id} reads facts.${k}, which it does not name`);
        return o[k];
      } });
      const sayAs = (id) => {
        if (!u.meta[id]) throw new Error(`the audit unit ${u.id} says ${id}, which it does not declare`);
        return context.sayAs(id);
      };
      return u.run(new Proxy(context, { get: (o, k) => (k === 'facts' ? facts : k === 'sayAs' ? sayAs : o[k]) }), results);
    } };
  });
}
