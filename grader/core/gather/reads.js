// What the gathering read of the rubric: each threshold and control pattern a gatherer looks at
// while it drives the page (a picture "changed" by sliderChange, a silhouette settled by
// silhouetteSettled, how many controls are tried) decides what is gathered, not only how it is
// judged. The session reads the rubric through recorders, and the artifact keeps every key read
// with its value (facts.gatheredWith): --audit-only under another rubric names the parts whose
// gathering a changed key would change (staleKeys), and --regather-changed gathers them again.
import { readsAs } from '../computed/memo.js';

/** `obj` (a part of the rubric) read through a recorder: each own key read is noted in `into` as `prefix + key` → its value. */
export function recording(obj, into, prefix = '') {
  const view = new Proxy(obj, {
    get(target, key, receiver) {
      const v = Reflect.get(target, key, receiver);
      if (typeof key === 'string' && Object.hasOwn(target, key) && !(prefix + key in into)) into[prefix + key] = v;
      return v;
    },
  });
  return readsAs(view, obj);
}

/** The value the rubric gives a key of facts.gatheredWith ('sliderChange', 'controls.orbit', 'parts.WP04P4.must'). */
function valueOf(rubric, key) {
  const [head, ...rest] = key.split('.');
  if (head === 'controls') return (rubric.controls || {})[rest.join('.')];
  if (head === 'parts') return ((rubric.parts || {})[rest[0]] || {})[rest[1]];
  return (rubric.thresholds || {})[key];
}

/**
 * The keys of `gatheredWith` (an artifact's facts.gatheredWith) that `rubric` gives another value:
 * what gathering again would read otherwise. null for an artifact gathered before the gathering kept
 * what it read (it cannot tell).
 */
export function staleKeys(gatheredWith, rubric) {
  if (!gatheredWith) return null;
  return Object.keys(gatheredWith)
    .filter((k) => JSON.stringify(valueOf(rubric, k)) !== JSON.stringify(gatheredWith[k]))
    .sort();
}
