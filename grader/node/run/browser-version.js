// The name and version of a browser: from its executable's --version (for `npm run grade -- --help`,
// before any browser runs), and from a running browser's own answer (for the report: the browser
// that graded). Chromium on Windows prints nothing for --version: then the path alone is said.
import { spawnSync } from 'node:child_process';

/** How long an executable's --version is waited for. */
const VERSION_TIMEOUT_MS = 5000;

/** The first line an executable prints for --version ("Chromium 156.0.8078.108 built on ..."), or null. */
export function versionOfExecutable(file, timeoutMs = VERSION_TIMEOUT_MS) {
  if (!file) return null;
  const run = spawnSync(file, ['--version'], { encoding: 'utf8', timeout: timeoutMs, stdio: ['ignore', 'pipe', 'ignore'] });
  const line = (run.stdout || '').split('\n').map((l) => l.trim()).find(Boolean);
  return run.status === 0 && line ? line.replace(/\s+built on .*$/, '') : null;
}

/** A browser's name from its --version line ("Chromium 156.0.8078.108" → "Chromium"), or `fallback`. */
export function nameOfVersionLine(line, fallback) {
  const m = /^(.*?)\s+v?\d+(\.\d+)+/.exec(line || '');
  return m && m[1] ? m[1] : fallback;
}

/**
 * "Chromium 156.0.8078.108", "Firefox 128.5.0esr": a running browser's `name` and its version, as
 * Playwright's browser.version() says it ("156.0.8078.108") or puppeteer's ("firefox/128.5.0esr").
 */
export function browserLabel(name, version) {
  const v = String(version || '').trim().replace(/^[A-Za-z ]+\//, '');
  return v ? `${name} ${v}` : name;
}
