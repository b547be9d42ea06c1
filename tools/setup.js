#!/usr/bin/env node
// Makes a fresh machine ready for `npm start`, `npm test`, `npm run grade` and `npm run bench`: installs the npm packages if they are
// missing, and checks for a Chromium (or Chrome, or Edge), and with --firefox a Firefox too, as
// grader/node/run/find-browser.js finds them (installing Debian's with apt-get when we are root on Debian
// or Ubuntu, else printing the one line to run for this OS).
// Runs before each of them (npm's pre-scripts); uses only Node's own modules.
import { existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { ENV_VAR, findHere } from '../grader/node/run/find-browser.js';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const args = process.argv.slice(2);
if (args.includes('--help')) {
  console.log(`usage: node tools/setup.js [--no-browser | --firefox]
Installs what npm start / test / run grade / run bench need on a fresh machine:
  - the npm packages (npm ci) when node_modules is missing or stale
  - a browser: Chromium, Google Chrome or Microsoft Edge, and with --firefox Firefox too, found
    in this order: CHROMIUM_PATH / FIREFOX_PATH, PATH and the usual installs of this OS (Debian's
    /usr/bin/chromium and /usr/bin/firefox-esr here), Playwright's browser cache. None found: as
    root on Debian or Ubuntu it installs one with apt-get, otherwise it prints the one command
    for this OS (apt-get, dnf, pacman, brew, winget). It never downloads a browser itself.
--no-browser   skip the browser check (npm start only needs the packages)
--firefox      check for Firefox too (npm test drives both browsers)
exit codes: 0 ready, 1 something is missing that this script could not install`);
  process.exit(0);
}

function run(cmd, cmdArgs) {
  const r = spawnSync(cmd, cmdArgs, { cwd: root, stdio: 'inherit' });
  return r.status === 0;
}

const marker = path.join(root, 'node_modules', '.package-lock.json');
if (!existsSync(marker)) {
  console.log('setup: node_modules is missing: installing the pinned npm packages (npm ci) ...');
  if (!run('npm', ['ci', '--no-audit', '--no-fund'])) {
    console.error('setup: npm ci failed. Run it yourself in ' + root + ' and read its error.');
    process.exit(1);
  }
}

// The browsers npm test drives, found as grader/node/run/find-browser.js finds them (CHROMIUM_PATH,
// FIREFOX_PATH, the usual installs of this OS, Playwright's cache): Chromium (Playwright) and
// Firefox (puppeteer-core, grader/node/run/firefox.js)
const wanted = args.includes('--no-browser') ? [] : args.includes('--firefox') ? ['chromium', 'firefox'] : ['chromium'];
const missing = () => wanted.map((kind) => ({ kind, ...findHere(kind) })).filter((b) => !b.found);
const lacking = missing();
if (lacking.length > 0) {
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  // as root on Debian or Ubuntu, apt installs them (not when the finder is told to look elsewhere:
  // BROWSER_FINDER_ROOT, for tests, hides what apt would install)
  const canInstall = isRoot && !process.env.BROWSER_FINDER_ROOT && lacking.every((b) => b.install.root && !process.env[ENV_VAR[b.kind]]);
  if (canInstall) {
    for (const b of lacking) {
      console.log(`setup: no ${b.kind} found: installing it (${b.install.root}) ...`);
      if (!run('sh', ['-c', `DEBIAN_FRONTEND=noninteractive ${b.install.root}`])) {
        console.error(`setup: installing ${b.kind} failed; run: ${b.install.line}`);
        process.exit(1);
      }
    }
  }
  const still = canInstall ? missing() : lacking;
  if (still.length > 0) {
    for (const b of still) console.error(`setup: ${b.message}`);
    process.exit(1);
  }
}
