// A file a page asks for that is not where it asks, found as the student's own machine or a
// teacher would. Pure: it sees only the list of the submission's files, so the grader's server
// (serve-submission.js) and the check page's service worker use the same rule.

/**
 * The stand-in for `asked` (a path as the page asked for it, '/'-separated, root-absolute or not)
 * among `files` (the submission's files, relative, '/'-separated): the same path in other letter
 * case (Windows and macOS ignore case: "Common/MV.js" for "common/mv.js"), else the one file of
 * that name in the submission, or the one whose folders match the asked path's the furthest
 * from the end ("../../Common/MV.js" from a part folder that went up past the submission's root).
 * Null when there is none or no single best. `files` may be a function that lists them (called
 * only when needed).
 */
export function findStandIn(asked, files) {
  const parts = asked.replace(/^\/+/, '').split('/').filter(Boolean);
  if (!parts.length) return null;
  const lower = parts.join('/').toLowerCase();
  const all = typeof files === 'function' ? files() : files;
  const sameCase = all.filter((f) => f.toLowerCase() === lower);
  if (sameCase.length === 1) return sameCase[0];
  const name = parts.at(-1).toLowerCase();
  const named = all.filter((f) => f.split('/').at(-1).toLowerCase() === name);
  if (named.length <= 1) return named[0] ?? null;
  const wanted = parts.map((x) => x.toLowerCase()).reverse();
  const shared = (f) => {
    const a = f.toLowerCase().split('/').reverse();
    let k = 0;
    while (k < a.length && k < wanted.length && a[k] === wanted[k]) k++;
    return k;
  };
  const best = Math.max(...named.map(shared));
  const top = named.filter((f) => shared(f) === best);
  return top.length === 1 ? top[0] : null;
}

/** Content types the grader and the check page serve a submission's files with. */
export const TYPES = { '.html': 'text/html', '.htm': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.gif': 'image/gif', '.svg': 'image/svg+xml',
  '.vert': 'text/plain', '.frag': 'text/plain', '.glsl': 'text/plain', '.txt': 'text/plain', '.wgsl': 'text/plain' };

/** The content type of a path by its extension. */
export function typeOf(file) {
  const m = /\.[^./]+$/.exec(file);
  return (m && TYPES[m[0].toLowerCase()]) || 'application/octet-stream';
}
