// The check page's side of serving a hand-in to its frames (check/sw.js only carries the
// requests): a path asked for, answered from the dropped files as the grader's server answers it.
// A folder gives its index.html; a file not where the page asked (other letter case, a folder too
// far up) is found by findStandIn and said in the notes; HTML gets the frame's instrumentation as
// its first script; JavaScript gets the loop guard (inline scripts, classic scripts, modules and
// what they import alike). Nothing else is ever read.
import { findStandIn, typeOf } from '../grader/core/standin.js';
import { guardInlineScripts, guardLoops } from './guard.js';
import { usesWebGPU } from './not-checked.js';

/** The HTTP statuses the check page answers its frames with. */
const OK = 200, NOT_FOUND = 404;

/**
 * The URL path under which the frames live: BASE + session + '/' + the hand-in's own path; the
 * check page's own folder's run/, wherever the site is served from (/check/run/, or
 * /course/check/run/ on a site published under a path). In Node (the unit tests) /check/run/.
 */
export const BASE = typeof location === 'undefined' ? '/check/run/' : new URL('./run/', import.meta.url).pathname;
/** The instrumentation's own path in a session (a name no hand-in uses). */
export const FRAME_SCRIPT = '__check_frame__.js';

/**
 * The path inside the hand-in that a URL path of a session's frame asks for. A page that went one
 * folder too far up ("../../Common/MV.js") or used a root-absolute path ("/Common/MV.js") lands
 * beside or above the session's folder; as on the grader's server, whose root is the hand-in's
 * root, that is the hand-in's root.
 */
export function askedPath(urlPath, session) {
  let rel;
  try {
    rel = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  const segments = rel.split('/').filter(Boolean);
  const base = [...BASE.split('/').filter(Boolean), session];
  let k = 0;
  while (k < base.length && segments[k] === base[k]) k++;
  return segments.slice(k).join('/') + (rel.endsWith('/') && segments.length > k ? '/' : '');
}

/**
 * Puts `<script src=FRAME_SCRIPT>` before every script of an HTML page: after <head>, else <html>,
 * else the doctype, else at the very start; a tag that comes after the page's first script (a
 * page that begins with its scripts and opens <head> below them), or that stands in a comment,
 * is passed over.
 */
export function injectFrameScript(html, src) {
  const tag = `<script src="${src}"></script>`;
  const plain = html.replace(/<!--[\s\S]*?(?:-->|$)/g, (c) => ' '.repeat(c.length)); // comments blanked, positions kept
  const firstScript = plain.search(/<script\b/i);
  for (const re of [/<head\b[^>]*>/i, /<html\b[^>]*>/i, /<!doctype[^>]*>/i]) {
    const m = re.exec(plain);
    const at = m ? m.index + m[0].length : -1;
    if (m && (firstScript < 0 || at <= firstScript)) return html.slice(0, at) + tag + html.slice(at);
  }
  return tag + html;
}

/** A hand-in as a source of files: its paths, and each file's contents. */
export function handInSource(files) {
  const paths = [...files.keys()];
  return { paths, read: async (p) => files.get(p) ?? null };
}

/**
 * The answer to a frame's request for `rel` (a path inside the source). `module`: the frame asked
 * for a module script (check/sw.js: a script fetched in cors mode, as a module's imports are).
 * `webgpu`: the page or script served calls WebGPU.
 * @param {{ paths: string[], read: (path: string) => Promise<Blob|null> }} source
 * @param {string} rel
 * @param {{ frameScript: string, session: string, loopSeconds: number, module?: boolean }} how (loopSeconds: a loop that runs so long without returning is stopped)
 * @returns {Promise<{ status: number, type: string, body: string|Blob, note?: string, missing?: string, webgpu?: boolean }>}
 */
export async function answer(source, rel, { frameScript, session, loopSeconds, module = false }) {
  if (rel === FRAME_SCRIPT) return { status: OK, type: 'text/javascript', body: frameScript };
  let file = rel.replace(/\/+$/, '');
  const isFolder = (f) => !source.paths.includes(f) && source.paths.some((k) => k.startsWith(`${f}/`));
  if (rel.endsWith('/') || file === '' || isFolder(file)) file = file ? `${file}/index.html` : 'index.html';
  let note;
  let blob = await source.read(file);
  if (!blob) {
    const standIn = findStandIn(rel, source.paths);
    if (!standIn) return { status: NOT_FOUND, type: 'text/plain', body: 'not found', missing: `/${rel}` };
    note = `served ${standIn} for /${rel}, which is not in the submission as written (letter case, or a folder above the submission)`;
    file = standIn;
    blob = await source.read(file);
  }
  const type = typeOf(file);
  if (type === 'text/html') {
    const html = await blob.text();
    const body = injectFrameScript(guardInlineScripts(html, loopSeconds), `${BASE}${session}/${FRAME_SCRIPT}`);
    return { status: OK, type: 'text/html', note, webgpu: usesWebGPU(html), body };
  }
  if (type === 'text/javascript') {
    const js = await blob.text();
    const body = guardLoops(js, { module: module || /\.mjs$/i.test(file), seconds: loopSeconds });
    return { status: OK, type, note, webgpu: usesWebGPU(js), body };
  }
  return { status: OK, type, note, body: blob };
}
