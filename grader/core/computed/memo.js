// A pure measurement of a picture, read once: f(img, thresholds) (or f(img, an, thresholds): its analysis too)
// remembered for each picture object and each object read with it (a gatherer and the audits read
// the same picture many times). The pictures are never changed once taken, and the cache lets go
// of a picture when nothing else holds it.

/** `f(...args)` remembered by its arguments (objects, compared by identity); called afresh where one is not an object. */
export function memo(f) {
  const root = new WeakMap();
  return (...args) => {
    if (!args.every((a) => a && typeof a === 'object')) return f(...args);
    let map = root;
    for (const a of args.slice(0, -1)) {
      let next = map.get(a);
      if (!next) map.set(a, (next = new WeakMap()));
      map = next;
    }
    const last = args[args.length - 1];
    if (!map.has(last)) map.set(last, f(...args));
    return map.get(last);
  };
}
