#!/usr/bin/env node
// Makes a fresh machine ready for `npm start`, `npm test`, `npm run grade` and `npm run bench`: installs the npm packages if they are
// missing, and checks for Debian's Chromium, and with --firefox Firefox ESR too (installing them with
// apt-get when we are root, else printing the one line to run).
// Runs before each of them (npm's pre-scripts); uses only Node's own modules.
import { existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const args = process.argv.slice(2);
if (args.includes('--help')) {
  console.log(`usage: node tools/setup.js [--no-browser | --firefox]
Installs what npm start / test / run grade / run bench need on a fresh machine:
  - the npm packages (npm ci) when node_modules is missing or stale
  - Debian's chromium (apt-get) when /usr/bin/chromium is missing, and with --firefox Debian's
    firefox-esr when /usr/bin/firefox-esr is missing: as root it installs them, otherwise it
    prints the one line to run
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

// The browsers npm test drives, each a Debian package: Chromium (Playwright) and Firefox ESR
// (puppeteer-core, tools/firefox.js)
const BROWSERS = [
  { name: 'Chromium', path: process.env.CHROMIUM_PATH || '/usr/bin/chromium', pkg: 'chromium', env: 'CHROMIUM_PATH' },
  { name: 'Firefox', path: process.env.FIREFOX_PATH || '/usr/bin/firefox-esr', pkg: 'firefox-esr', env: 'FIREFOX_PATH' },
];
const wanted = args.includes('--no-browser') ? [] : args.includes('--firefox') ? BROWSERS : BROWSERS.slice(0, 1);
const missing = wanted.filter((b) => !existsSync(b.path));
if (missing.length > 0) {
  const packages = missing.map((b) => b.pkg).join(' ');
  const install = `apt-get update && apt-get install -y ${packages}`;
  const sudoInstall = `sudo apt-get update && sudo apt-get install -y ${packages}`;
  const names = missing.map((b) => b.name).join(' and ');
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  if (isRoot && existsSync('/usr/bin/apt-get')) {
    console.log(`setup: ${names} ${missing.length > 1 ? 'are' : 'is'} missing: installing Debian's ${packages} (${install}) ...`);
    if (!run('sh', ['-c', `DEBIAN_FRONTEND=noninteractive ${install}`]) || !missing.every((b) => existsSync(b.path))) {
      console.error(`setup: installing ${packages} failed; run: ${sudoInstall}`);
      process.exit(1);
    }
  } else {
    const where = missing.map((b) => `${b.name} at ${b.path}`).join(' and ');
    const vars = missing.map((b) => b.env).join(' or ');
    console.error(`setup: the browser tests need Debian's ${where}. Run first:\n  ${sudoInstall}\n(or set ${vars} to another build)`);
    process.exit(1);
  }
}
