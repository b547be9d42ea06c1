// Serving one submission to the grader's browser: its own files at an origin of their own,
// through the browser's request routing (Playwright's in Chromium, puppeteer's in Firefox:
// firefox-page.js), so nothing else is reachable. Other hosts are blocked and
// listed; a file not where the page asks is looked for by findStandIn (standin.js) and said.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { findStandIn, typeOf } from '../core/standin.js';

/** Every file under `root` (relative paths, '/'-separated), up to a depth and a count. */
export function filesUnder(root, dir = '', out = [], depth = 0) {
  if (depth > 8 || out.length > 5000) return out;
  let names;
  try {
    names = readdirSync(path.join(root, dir), { withFileTypes: true });
  } catch {
    return out;
  }
  for (const d of names) {
    if (d.name.startsWith('.') || d.name === 'node_modules') continue;
    const rel = dir ? `${dir}/${d.name}` : d.name;
    if (d.isDirectory()) filesUnder(root, rel, out, depth + 1);
    else out.push(rel);
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
      if (!url.protocol.startsWith('data') && !url.protocol.startsWith('blob') && !log.blocked.includes(entry)) log.blocked.push(entry); // (once: Firefox asks again)
      return { abort: true };
    }
    let rel;
    try {
      rel = decodeURIComponent(url.pathname);
    } catch {
      return { status: 400, body: 'bad path' };
    }
    let file = path.resolve(root, `.${rel}`);
    if (file !== root && !file.startsWith(root + path.sep)) {
      log.blocked.push(`outside the submission: ${rel}`);
      return { status: 403, body: 'outside the submission' };
    }
    const st = statSync(file, { throwIfNoEntry: false });
    if (st && st.isDirectory()) file = path.join(file, 'index.html');
    let body;
    try {
      body = readFileSync(file);
    } catch {
      const standIn = findStandIn(rel, () => (files ??= filesUnder(root)));
      if (!standIn) {
        log.errors.push(`missing file: ${rel}`);
        return { status: 404, body: 'not found' };
      }
      file = path.join(root, standIn);
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
