// Finding a file a page asked for that is not where it asked (pure: no file system; browser-safe).

/**
 * A file the page asked for that is not where it asked, found as the student's own machine or a
 * teacher would: the same path in other letter case (Windows and macOS ignore case: "Common/MV.js"
 * for "common/mv.js"), else the one file of that name in the submission, or the one whose folders
 * match the asked path's the furthest from the end ("../../Common/MV.js" from a part folder that
 * went up past the submission's root). Null when there is none or no single best.
 * @param {string} askedPath the path asked for, relative to the submission's root ('/'-separated)
 * @param {string[]} files the submission's files, relative '/'-separated paths
 */
export function findStandIn(askedPath, files) {
  const asked = askedPath.replace(/^\/+/, '').split('/').filter(Boolean);
  if (!asked.length) return null;
  const lower = asked.join('/').toLowerCase();
  const sameCase = files.filter((f) => f.toLowerCase() === lower);
  if (sameCase.length === 1) return sameCase[0];
  const name = asked.at(-1).toLowerCase();
  const named = files.filter((f) => f.split('/').at(-1).toLowerCase() === name);
  if (named.length <= 1) return named[0] ?? null;
  const shared = (f) => {
    const a = f.toLowerCase().split('/').reverse(), b = asked.map((x) => x.toLowerCase()).reverse();
    let k = 0;
    while (k < a.length && k < b.length && a[k] === b[k]) k++;
    return k;
  };
  const best = Math.max(...named.map(shared));
  const top = named.filter((f) => shared(f) === best);
  return top.length === 1 ? top[0] : null;
}
