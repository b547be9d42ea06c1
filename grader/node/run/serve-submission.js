// Serving one submission to the grader's browser: its own files at an origin of their own,
// through the browser's request routing (Playwright's in Chromium, puppeteer's in Firefox:
// firefox-page.js), so nothing else is reachable. Other hosts are blocked and
// listed; a file not where the page asks is looked for by findStandIn (standin.js) and said.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { findStandIn, typeOf } from '../../core/standin.js';

// Between a submission's files and the URLs its pages ask for, paths are turned into URLs and back
// by Node's url module (file: URLs of the root and the file), never by splitting or joining strings
// on a separator: the same on Windows (path.win32, C:\\...) as on POSIX. `pathImpl` is Node's
// path of this machine, or the other one's in tests.
const fileUrl = (file, pathImpl) => pathToFileURL(file, { windows: pathImpl === path.win32 });
const rootUrl = (root, pathImpl) => fileUrl(pathImpl.join(root, pathImpl.sep), pathImpl);

/**
 * The URL of `rel` (a path relative to `root`, as findParts gives it) on a submission's `origin`,
 * with `query` ('a=1&b=2') if given.
 */
export function urlOf(origin, root, rel, query = '', pathImpl = path) {
  const base = rootUrl(root, pathImpl);
  const file = fileUrl(pathImpl.join(root, rel), pathImpl);
  // (the file's URL below its root's: the same percent-encoding for spaces, æøå, # and ?)
  const url = new URL(`.${file.pathname.slice(base.pathname.length - 1)}`, new URL('/', origin));
  url.search = query;
  return url;
}

/**
 * The file under `root` that a request for `href` stands for, or null when it is outside the
 * submission or no file name (an encoded separator: %2F, or %5C on Windows).
 */
export function fileOf(root, href, pathImpl = path) {
  let file;
  try {
    const asked = new URL(`.${new URL(href).pathname}`, rootUrl(root, pathImpl));
    file = fileURLToPath(asked, { windows: pathImpl === path.win32 });
  } catch {
    return null;
  }
  const inside = pathImpl.relative(pathImpl.resolve(root), file);
  if (inside === '..' || inside.startsWith(`..${pathImpl.sep}`) || pathImpl.isAbsolute(inside)) return null;
  return file;
}

/**
 * Every file under `root`, each as its names from `root` down ([folder, ..., file]), up to a
 * depth and a count.
 */
export function filesUnder(root, segments = [], out = [], pathImpl = path) {
  if (segments.length > 8 || out.length > 5000) return out;
  let names;
  try {
    names = readdirSync(pathImpl.join(root, ...segments), { withFileTypes: true });
  } catch {
    return out;
  }
  for (const d of names) {
    if (d.name.startsWith('.') || d.name === 'node_modules') continue;
    if (d.isDirectory()) filesUnder(root, [...segments, d.name], out, pathImpl);
    else out.push([...segments, d.name]);
  }
  return out;
}

/**
 * The serving rules, apart from any browser's request routing (Playwright's here, puppeteer's in
 * firefox-page.js): `site` ({ root, origin, log, former }) is read at each request, so that a page
 * kept for the next part serves that part's folder at its origin (`former`: the origins of the parts
 * before, refused without a word; no `root`: an empty page, between two parts). `log` gets
 * { blocked, errors, notes } pushed to: requests to other hosts and outside the submission, missing
 * files, stand-ins. Returns answer(href, navigation) → { status, body, contentType } to fulfil the
 * request with, or { abort: true } to refuse it.
 */
export function submissionAnswers(site) {
  let files = null, listed = null; // the submission's files, listed on the first miss
  return (href, navigation) => {
    const { root, origin, log } = site;
    if (listed !== root) [files, listed] = [null, root];
    const url = new URL(href);
    if (!root && url.origin === origin) return { status: 200, contentType: 'text/html', body: '<!doctype html>' }; // between two parts
    if (url.origin !== origin) {
      if (site.former && site.former.has(url.origin)) return { abort: true }; // a part graded before, left behind
      const kind = navigation ? 'navigation or popup' : 'request';
      const entry = `${kind}: ${url.href}`;
      // (once: Firefox asks again)
      const own = url.protocol.startsWith('data') || url.protocol.startsWith('blob');
      if (!own && !log.blocked.includes(entry)) log.blocked.push(entry);
      return { abort: true };
    }
    let rel;
    try {
      rel = decodeURIComponent(url.pathname);
    } catch {
      return { status: 400, body: 'bad path' };
    }
    let file = fileOf(root, url.href);
    if (!file) {
      log.blocked.push(`outside the submission: ${rel}`);
      return { status: 403, body: 'outside the submission' };
    }
    const st = statSync(file, { throwIfNoEntry: false });
    if (st && st.isDirectory()) file = path.join(file, 'index.html');
    let body;
    try {
      body = readFileSync(file);
    } catch {
      // (findStandIn compares paths as the page asks for them: names joined by '/', a URL's path)
      files ??= new Map(filesUnder(root).map((names) => [names.join('/'), names]));
      const standIn = findStandIn(rel, () => [...files.keys()]);
      if (!standIn) {
        log.errors.push(`missing file: ${rel}`);
        return { status: 404, body: 'not found' };
      }
      file = path.join(root, ...files.get(standIn));
      body = readFileSync(file);
      log.notes.push(`served ${standIn} for ${rel}, which is not in the submission as written (letter case, or a folder above the submission)`);
    }
    return { status: 200, body, contentType: typeOf(file) };
  };
}

/** Serves a submission in a Playwright browser context by submissionAnswers' rules. */
export async function serveSubmission(context, site) {
  const answer = submissionAnswers(site);
  await context.route('**/*', async (route) => {
    const a = answer(route.request().url(), route.request().isNavigationRequest());
    return a.abort ? route.abort('blockedbyclient') : route.fulfill(a);
  });
}
