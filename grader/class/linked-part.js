// A part's page that is only a link to another part's page ("Part 5: see part 4", a meta refresh):
// no canvas and no script of its own, and a link whose target is the page found for another part.
// Graded once, as the part it links to; the linking part says so and goes to a teacher. No Node:
// the paths are the caller's (the command's node:path, the class page's '/'-separated POSIX_PATHS).

/** '/'-separated paths relative to a hand-in, as the class page keeps them (the subset of node:path linkedPart uses). */
export const POSIX_PATHS = {
  dirname: (p) => (p.includes('/') ? p.slice(0, p.lastIndexOf('/')) : '.'),
  join: (...parts) => parts.join('/'),
  // '.' and '..' resolved as a URL resolves them (a '..' past the hand-in stays at its top)
  normalize: (p) => decodeURIComponent(new URL(p.split('/').map(encodeURIComponent).join('/'), 'http://h/').pathname.slice(1)),
};

/** The link targets in `html`: each <a href> and a <meta http-equiv="refresh" content="0; url=…">, as written. */
function targets(html) {
  const out = [];
  for (const m of html.matchAll(/<a\b[^>]*?\bhref\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))/gi)) out.push(m[1] ?? m[2] ?? m[3]);
  for (const m of html.matchAll(/<meta\b[^>]*?http-equiv\s*=\s*["']?refresh[^>]*>/gi)) {
    const url = /url\s*=\s*['"]?([^'">\s]+)/i.exec(m[0]);
    if (url) out.push(url[1]);
  }
  return out;
}

/**
 * The part whose page `html` (the page `rel` of a submission, relative to its root, written with
 * `pathImpl`: node:path, or POSIX_PATHS) only links to: { part, page } where the page has no <canvas>
 * and no <script> and one of its links, resolved from its folder, is `parts[part]` for another part; else null.
 */
export function linkedPart(html, rel, parts, { pathImpl }) {
  if (/<canvas\b|<script\b/i.test(html)) return null;
  const here = pathImpl.dirname(rel);
  for (const t of targets(html)) {
    if (/^[a-z][a-z0-9+.-]*:|^\/\//i.test(t)) continue; // another site, mailto:, javascript:
    let file;
    try {
      file = decodeURIComponent(t.split(/[?#]/)[0]);
    } catch {
      continue;
    }
    if (!file) continue;
    const target = pathImpl.normalize(pathImpl.join(here, ...file.split('/')));
    for (const [part, page] of Object.entries(parts)) {
      if (page && page !== rel && pathImpl.normalize(page) === target) return { part, page };
    }
  }
  return null;
}
