// grader/node/run/find-browser.js on made-up machines: which Chromium or Firefox it picks on Debian,
// Ubuntu with only the snap, Fedora, macOS, Windows, Playwright's cache alone, and what it says when
// there is none (the one install command of that OS); the environment variable wins.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { findBrowser, candidates, installCommand, linuxFamily, thisMachine } from '../../grader/node/run/find-browser.js';

const DEBIAN = 'PRETTY_NAME="Debian GNU/Linux 12 (bookworm)"\nID=debian\n';
const UBUNTU = 'NAME="Ubuntu"\nID=ubuntu\nID_LIKE=debian\n';
const FEDORA = 'NAME="Fedora Linux"\nID=fedora\n';
const ARCH = 'NAME="Arch Linux"\nID=arch\n';
const MINT = 'NAME="Linux Mint"\nID=linuxmint\nID_LIKE="ubuntu debian"\n';

/** A made-up machine: its files (executables) and folders' listings. */
function machine(platform, files, extra = {}) {
  const p = platform === 'win32' ? path.win32 : path.posix;
  const set = new Set(files);
  return {
    platform,
    exists: (f) => set.has(f),
    list: (dir) => [...new Set(files.filter((f) => p.dirname(f).startsWith(dir + p.sep) || p.dirname(f) === dir)
      .map((f) => f.slice(dir.length + 1).split(p.sep)[0]))],
    home: platform === 'win32' ? 'C:\\Users\\Søren Ålund' : platform === 'darwin' ? '/Users/anna' : '/home/anna',
    cwd: platform === 'win32' ? 'C:\\Users\\Søren Ålund' : '/home/anna',
    osRelease: DEBIAN,
    ...extra,
  };
}

test('Debian: /usr/bin/chromium and /usr/bin/firefox-esr, also when PATH does not have /usr/bin', () => {
  const m = machine('linux', ['/usr/bin/chromium', '/usr/bin/firefox-esr', '/usr/bin/firefox'], { env: { PATH: '/usr/local/bin:/usr/bin:/bin' } });
  assert.deepEqual([findBrowser('chromium', m).path, findBrowser('firefox', m).path], ['/usr/bin/chromium', '/usr/bin/firefox-esr']);
  const noPath = { ...m, env: {} };
  assert.equal(findBrowser('chromium', noPath).path, '/usr/bin/chromium');
  assert.equal(findBrowser('chromium', noPath).how, 'the usual Linux install');
});

test('PATH comes before /usr/bin for the same name; a name earlier in the list wins over a later one', () => {
  const m = machine('linux', ['/home/anna/bin/chromium', '/usr/bin/chromium', '/usr/bin/google-chrome'], { env: { PATH: '/home/anna/bin:/usr/bin' } });
  assert.equal(findBrowser('chromium', m).path, '/home/anna/bin/chromium');
  const chrome = machine('linux', ['/usr/bin/google-chrome', '/opt/google/chrome/chrome'], { env: { PATH: '/usr/bin' } });
  assert.equal(findBrowser('chromium', chrome).path, '/usr/bin/google-chrome');
});

test('Ubuntu with only the snaps: /snap/bin/chromium and /snap/bin/firefox', () => {
  const m = machine('linux', ['/snap/bin/chromium', '/snap/bin/firefox'], { env: { PATH: '/usr/bin:/bin' }, osRelease: UBUNTU });
  assert.deepEqual(findBrowser('chromium', m), { found: true, path: '/snap/bin/chromium', how: 'the Ubuntu snap', install: installCommand('chromium', m) });
  assert.equal(findBrowser('firefox', m).path, '/snap/bin/firefox');
  // (on PATH too, as Ubuntu sets it: PATH finds it first)
  assert.equal(findBrowser('chromium', { ...m, env: { PATH: '/usr/bin:/snap/bin' } }).how, 'PATH');
});

test('Fedora: chromium-browser in /usr/bin, or Google Chrome in /opt; Arch: google-chrome-stable on PATH; Edge', () => {
  const fedora = machine('linux', ['/usr/bin/chromium-browser', '/usr/bin/firefox'], { env: { PATH: '/usr/bin' }, osRelease: FEDORA });
  assert.equal(findBrowser('chromium', fedora).path, '/usr/bin/chromium-browser');
  assert.equal(findBrowser('firefox', fedora).path, '/usr/bin/firefox');
  const chromeOnly = machine('linux', ['/opt/google/chrome/chrome'], { env: {}, osRelease: FEDORA });
  assert.equal(findBrowser('chromium', chromeOnly).path, '/opt/google/chrome/chrome');
  const arch = machine('linux', ['/usr/local/bin/google-chrome-stable'], { env: { PATH: '/usr/local/bin:/usr/bin' }, osRelease: ARCH });
  assert.equal(findBrowser('chromium', arch).path, '/usr/local/bin/google-chrome-stable');
  const edge = machine('linux', ['/usr/bin/microsoft-edge'], { env: {} });
  assert.equal(findBrowser('chromium', edge).path, '/usr/bin/microsoft-edge');
});

test('macOS: Google Chrome, then Chromium, then Edge in /Applications (or ~/Applications); Firefox.app', () => {
  const chrome = '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome';
  const edge = '/Applications/Microsoft Edge.app/Contents/MacOS/Microsoft Edge';
  const m = machine('darwin', [edge, chrome, '/Applications/Firefox.app/Contents/MacOS/firefox'], { env: { PATH: '/usr/bin:/bin' } });
  assert.equal(findBrowser('chromium', m).path, chrome);
  assert.equal(findBrowser('firefox', m).path, '/Applications/Firefox.app/Contents/MacOS/firefox');
  assert.equal(findBrowser('chromium', machine('darwin', [edge], { env: {} })).path, edge);
  const mine = '/Users/anna/Applications/Chromium.app/Contents/MacOS/Chromium';
  assert.equal(findBrowser('chromium', machine('darwin', [mine], { env: {} })).path, mine);
});

test('Windows: Program Files, Program Files (x86) and LOCALAPPDATA as Playwright looks, env names in any case', () => {
  const env = { LOCALAPPDATA: 'C:\\Users\\Søren Ålund\\AppData\\Local', ProgramFiles: 'C:\\Program Files', 'PROGRAMFILES(X86)': 'C:\\Program Files (x86)', Path: 'C:\\Windows\\system32' };
  const chrome = 'C:\\Program Files\\Google\\Chrome\\Application\\chrome.exe';
  const userChrome = 'C:\\Users\\Søren Ålund\\AppData\\Local\\Google\\Chrome\\Application\\chrome.exe';
  const edge = 'C:\\Program Files (x86)\\Microsoft\\Edge\\Application\\msedge.exe';
  const firefox = 'C:\\Program Files\\Mozilla Firefox\\firefox.exe';
  assert.equal(findBrowser('chromium', machine('win32', [edge, chrome], { env })).path, chrome);
  assert.equal(findBrowser('chromium', machine('win32', [edge, userChrome, chrome], { env })).path, userChrome);
  assert.equal(findBrowser('chromium', machine('win32', [edge], { env })).path, edge);
  assert.equal(findBrowser('firefox', machine('win32', [firefox], { env })).path, firefox);
  // no ProgramFiles variables, HOMEDRIVE only (as Playwright allows for)
  assert.equal(findBrowser('chromium', machine('win32', ['D:\\Program Files\\Google\\Chrome\\Application\\chrome.exe'], { env: { HOMEDRIVE: 'D:' } })).path,
    'D:\\Program Files\\Google\\Chrome\\Application\\chrome.exe');
  // on PATH (a quoted entry too)
  assert.equal(findBrowser('chromium', machine('win32', ['E:\\Portable Apps\\chrome.exe'], { env: { PATH: 'C:\\Windows;"E:\\Portable Apps"' } })).path, 'E:\\Portable Apps\\chrome.exe');
});

test("Playwright's cache only: its newest chromium-<revision>, on Linux, macOS and Windows; PLAYWRIGHT_BROWSERS_PATH", () => {
  const linux = machine('linux', ['/home/anna/.cache/ms-playwright/chromium-1100/chrome-linux/chrome', '/home/anna/.cache/ms-playwright/chromium-1200/chrome-linux64/chrome',
    '/home/anna/.cache/ms-playwright/chromium_headless_shell-1200/chrome-headless-shell-linux64/chrome-headless-shell'], { env: { PATH: '/usr/bin' } });
  assert.deepEqual(findBrowser('chromium', linux), { found: true, path: '/home/anna/.cache/ms-playwright/chromium-1200/chrome-linux64/chrome', how: "Playwright's browser cache", install: installCommand('chromium', linux) });
  const xdg = machine('linux', ['/var/cache/x/ms-playwright/chromium-1100/chrome-linux/chrome'], { env: { XDG_CACHE_HOME: '/var/cache/x' } });
  assert.equal(findBrowser('chromium', xdg).path, '/var/cache/x/ms-playwright/chromium-1100/chrome-linux/chrome');
  const own = machine('linux', ['/srv/pw browsers/chromium-1300/chrome-linux64/chrome'], { env: { PLAYWRIGHT_BROWSERS_PATH: '/srv/pw browsers' } });
  assert.equal(findBrowser('chromium', own).path, '/srv/pw browsers/chromium-1300/chrome-linux64/chrome');
  const mac = '/Users/anna/Library/Caches/ms-playwright/chromium-1200/chrome-mac-arm64/Google Chrome for Testing.app/Contents/MacOS/Google Chrome for Testing';
  assert.equal(findBrowser('chromium', machine('darwin', [mac], { env: {} })).path, mac);
  const win = 'C:\\Users\\Søren Ålund\\AppData\\Local\\ms-playwright\\chromium-1200\\chrome-win64\\chrome.exe';
  assert.equal(findBrowser('chromium', machine('win32', [win], { env: { LOCALAPPDATA: 'C:\\Users\\Søren Ålund\\AppData\\Local' } })).path, win);
  assert.equal(findBrowser('chromium', machine('win32', [win], { env: {} })).path, win); // (LOCALAPPDATA unset: the home's AppData\Local)
  // a Firefox of Playwright's (a patched build puppeteer cannot drive) is not taken
  assert.equal(findBrowser('firefox', machine('linux', ['/home/anna/.cache/ms-playwright/firefox-1500/firefox/firefox'], { env: {} })).found, false);
});

test('nothing found: the one install command of that OS, and the variable to set', () => {
  const none = (platform, osRelease) => findBrowser('chromium', machine(platform, [], { env: { PATH: '/usr/bin' }, osRelease }));
  const lines = {
    debian: ['linux', DEBIAN, 'sudo apt-get update && sudo apt-get install -y chromium'],
    ubuntu: ['linux', UBUNTU, 'sudo apt-get update && sudo apt-get install -y chromium-browser'],
    mint: ['linux', MINT, 'sudo apt-get update && sudo apt-get install -y chromium-browser'],
    fedora: ['linux', FEDORA, 'sudo dnf install -y chromium'],
    arch: ['linux', ARCH, 'sudo pacman -S --needed chromium'],
    unknown: ['linux', '', 'sudo apt-get update && sudo apt-get install -y chromium'],
    macOS: ['darwin', '', 'brew install --cask google-chrome'],
    Windows: ['win32', '', 'winget install -e --id Google.Chrome'],
  };
  for (const [name, [platform, osRelease, line]] of Object.entries(lines)) {
    const r = none(platform, osRelease);
    assert.equal(r.found, false, name);
    assert.equal(r.install.line, line, name);
    assert.ok(r.message.includes(`\n  ${line}\n`), `${name}: ${r.message}`);
    assert.match(r.message, /set CHROMIUM_PATH/);
  }
  const firefox = (platform, osRelease) => findBrowser('firefox', machine(platform, [], { env: {}, osRelease })).install.line;
  assert.equal(firefox('linux', DEBIAN), 'sudo apt-get update && sudo apt-get install -y firefox-esr');
  assert.equal(firefox('linux', FEDORA), 'sudo dnf install -y firefox');
  assert.equal(firefox('darwin', ''), 'brew install --cask firefox');
  assert.equal(firefox('win32', ''), 'winget install -e --id Mozilla.Firefox');
  assert.equal(installCommand('chromium', { platform: 'linux', osRelease: DEBIAN }).root, 'apt-get update && apt-get install -y chromium');
  assert.equal(installCommand('chromium', { platform: 'linux', osRelease: FEDORA }).root, null);
  assert.deepEqual([DEBIAN, UBUNTU, FEDORA, ARCH, MINT, 'ID=rocky\nID_LIKE="rhel centos fedora"', 'ID=gentoo'].map(linuxFamily), ['debian', 'ubuntu', 'fedora', 'arch', 'ubuntu', 'fedora', null]);
});

test('the environment variable wins over every place; one that names nothing is said, not passed over', () => {
  const m = machine('linux', ['/usr/bin/chromium', '/tmp/chr/chromium', '/usr/bin/firefox-esr', '/opt/ff/firefox'], { env: { PATH: '/usr/bin', CHROMIUM_PATH: '/tmp/chr/chromium', FIREFOX_PATH: '/opt/ff/firefox' } });
  assert.deepEqual([findBrowser('chromium', m).path, findBrowser('chromium', m).how], ['/tmp/chr/chromium', 'CHROMIUM_PATH']);
  assert.equal(findBrowser('firefox', m).path, '/opt/ff/firefox');
  const wrong = findBrowser('chromium', { ...m, env: { ...m.env, CHROMIUM_PATH: '/nowhere/chrome' } });
  assert.equal(wrong.found, false);
  assert.match(wrong.message, /not at \/nowhere\/chrome \(CHROMIUM_PATH\)/);
  const win = machine('win32', ['C:\\Tools\\chrome.exe', 'C:\\Program Files\\Google\\Chrome\\Application\\chrome.exe'], { env: { ProgramFiles: 'C:\\Program Files', chromium_path: 'C:\\Tools\\chrome.exe' } });
  assert.equal(findBrowser('chromium', win).path, 'C:\\Tools\\chrome.exe');
});

test("the places under a test's root (BROWSER_FINDER_ROOT) instead of the machine's", () => {
  const m = machine('linux', ['/usr/bin/chromium', '/fake/usr/bin/chromium'], { env: {}, root: '/fake' });
  assert.equal(findBrowser('chromium', m).path, '/fake/usr/bin/chromium');
  assert.equal(findBrowser('chromium', { ...m, root: '/empty' }).found, false);
  assert.ok(candidates('chromium', { ...m, root: '/empty' }).every((c) => c.file.startsWith('/empty/')));
});

test('npm run grade with no browser found prints the install line and exits 1 (this machine, its places hidden)', () => {
  const empty = mkdtempSync(path.join(os.tmpdir(), 'no-browser-'));
  try {
    // (PATH: an empty folder; node is run by its own path)
    const env = { PATH: empty, HOME: empty, BROWSER_FINDER_ROOT: empty };
    const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', 'tests/fixtures/handins/anna', '--out', path.join(empty, 'out')], { encoding: 'utf8', env });
    assert.equal(run.status, 1, run.stderr);
    const line = installCommand('chromium', thisMachine()).line; // (Debian's apt-get line here)
    assert.ok(run.stderr.startsWith(`grade: No Chromium, Google Chrome or Microsoft Edge was found on this machine. Install one:\n  ${line}\n(or set CHROMIUM_PATH`), run.stderr);
  } finally {
    rmSync(empty, { recursive: true, force: true });
  }
});
