// A pure measurement of a picture, read once: f(img, thresholds) (or f(img, an, thresholds): its analysis too)
// remembered for each picture object and each object read with it (a gatherer and the audits read
// the same picture many times). The pictures are never changed once taken, and the cache lets go
// of a picture when nothing else holds it.
//
// The gathering reads the rubric's thresholds through a recorder (gather/reads.js) and the audits
// read them as they are: an argument marked by `readsAs` counts as the object it reads, so the
// audit of a part just gathered finds the fits its gathering made. (The gathering runs first, so
// each threshold a fit reads is still recorded as read in gathering.)

const readThrough = new WeakMap(); // a recorder → the object it reads

/** Marks `view` (a Proxy of `obj` that only watches reads) as `obj` for every memo; returns `view`. */
export function readsAs(view, obj) {
  readThrough.set(view, obj);
  return view;
}

const keyOf = (a) => readThrough.get(a) || a;

/** `f(...args)` remembered by its arguments (objects, compared by identity); called afresh where one is not an object. */
export function memo(f) {
  const root = new WeakMap();
  return (...args) => {
    if (!args.every((a) => a && typeof a === 'object')) return f(...args);
    let map = root;
    for (const a of args.slice(0, -1)) {
      const key = keyOf(a);
      let next = map.get(key);
      if (!next) map.set(key, (next = new WeakMap()));
      map = next;
    }
    const last = keyOf(args[args.length - 1]);
    if (!map.has(last)) map.set(last, f(...args));
    return map.get(last);
  };
}
