#!/usr/bin/env node
// Makes a fresh machine ready for `npm start`, `npm test`, `npm run grade` and `npm run bench`: installs the npm packages if they are
// missing, and checks for Debian's Chromium (installing it with apt-get when we are root).
// Runs before each of them (npm's pre-scripts); uses only Node's own modules.
import { existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const args = process.argv.slice(2);
if (args.includes('--help')) {
  console.log(`usage: node tools/setup.js [--no-browser]
Installs what npm start / test / run grade / run bench need on a fresh machine:
  - the npm packages (npm ci) when node_modules is missing or stale
  - Debian's chromium (apt-get) when /usr/bin/chromium is missing and we run as root
--no-browser   skip the Chromium check (npm start only needs the packages)
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

export const CHROMIUM = process.env.CHROMIUM_PATH || '/usr/bin/chromium';
if (!args.includes('--no-browser') && !existsSync(CHROMIUM)) {
  const install = 'apt-get update && apt-get install -y chromium';
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  if (isRoot && existsSync('/usr/bin/apt-get')) {
    console.log(`setup: Chromium is missing: installing Debian's chromium package (${install}) ...`);
    if (!run('sh', ['-c', `DEBIAN_FRONTEND=noninteractive ${install}`]) || !existsSync(CHROMIUM)) {
      console.error('setup: installing chromium failed; run: sudo ' + install);
      process.exit(1);
    }
  } else {
    console.error(`setup: the browser tests need Debian's Chromium at ${CHROMIUM}. Run first:\n  sudo ${install}\n(or set CHROMIUM_PATH to another Chromium build)`);
    process.exit(1);
  }
}
