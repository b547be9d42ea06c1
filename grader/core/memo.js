// A pure measurement of a picture, read once: f(img, T) remembered for each picture object and
// thresholds object (a gatherer and the audits read the same picture many times). The pictures are
// never changed once taken, and the cache lets go of a picture when nothing else holds it.

/** `f(img, T)` remembered by `img` and `T` (objects). */
export function memo(f) {
  const byImage = new WeakMap();
  return (img, T) => {
    if (!img || typeof img !== 'object' || !T || typeof T !== 'object') return f(img, T);
    let byT = byImage.get(img);
    if (!byT) byImage.set(img, (byT = new WeakMap()));
    if (!byT.has(T)) byT.set(T, f(img, T));
    return byT.get(T);
  };
}
