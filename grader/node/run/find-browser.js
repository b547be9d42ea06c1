// Which browser the grader, the tests, the bench and the tools drive: the one Chromium (or Chrome,
// or Edge) and the one Firefox this machine has, looked for in a fixed order, or the one command
// that installs one on this OS. Pure apart from findHere(): the platform, the environment, the
// file system and PATH come in as parameters, so the order can be tested on made-up machines.
// Never downloads a browser.
import { accessSync, constants, readFileSync, readdirSync, statSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';

// the executable names on Linux's PATH (and /usr/bin, /snap/bin), in the order they are preferred
const LINUX_NAMES = {
  chromium: ['chromium', 'chromium-browser', 'google-chrome', 'google-chrome-stable', 'microsoft-edge', 'microsoft-edge-stable'],
  firefox: ['firefox-esr', 'firefox'],
};
// where the vendors' own packages put them (the places Playwright's 'chrome' and 'msedge' channels look)
const LINUX_PLACES = {
  chromium: ['/opt/google/chrome/chrome', '/opt/microsoft/msedge/msedge'],
  firefox: ['/usr/lib/firefox-esr/firefox-esr', '/usr/lib/firefox/firefox', '/opt/firefox/firefox'],
};
// macOS: an app in /Applications (or ~/Applications)
const MAC_APPS = {
  chromium: ['Google Chrome.app/Contents/MacOS/Google Chrome', 'Chromium.app/Contents/MacOS/Chromium', 'Microsoft Edge.app/Contents/MacOS/Microsoft Edge'],
  firefox: ['Firefox.app/Contents/MacOS/firefox'],
};
// Windows: under %LOCALAPPDATA%, %ProgramFiles%, %ProgramFiles(x86)% (as Playwright's channels)
const WINDOWS_APPS = {
  chromium: [['Google', 'Chrome', 'Application', 'chrome.exe'], ['Chromium', 'Application', 'chrome.exe'], ['Microsoft', 'Edge', 'Application', 'msedge.exe']],
  firefox: [['Mozilla Firefox', 'firefox.exe']],
};
const WINDOWS_NAMES = { chromium: ['chrome.exe', 'msedge.exe'], firefox: ['firefox.exe'] };
// inside one of Playwright's chromium-<revision> folders: Chrome for Testing's layout, then the older one
const PLAYWRIGHT_CHROMIUM = {
  linux: [['chrome-linux64', 'chrome'], ['chrome-linux', 'chrome']],
  darwin: [['chrome-mac-arm64', 'Google Chrome for Testing.app', 'Contents', 'MacOS', 'Google Chrome for Testing'],
    ['chrome-mac-x64', 'Google Chrome for Testing.app', 'Contents', 'MacOS', 'Google Chrome for Testing'],
    ['chrome-mac', 'Chromium.app', 'Contents', 'MacOS', 'Chromium']],
  win32: [['chrome-win64', 'chrome.exe'], ['chrome-win', 'chrome.exe']],
};

export const ENV_VAR = { chromium: 'CHROMIUM_PATH', firefox: 'FIREFOX_PATH' };
const TITLE = { chromium: 'Chromium', firefox: 'Firefox' };

/** The path functions of a platform: Windows' or POSIX's, whatever this machine is. */
export const pathFor = (platform) => (platform === 'win32' ? path.win32 : path.posix);

/** An environment variable, by its name in any letter case on Windows (as Windows reads them). */
function envGet(env, name, platform) {
  if (env[name] !== undefined) return env[name];
  if (platform !== 'win32') return undefined;
  const key = Object.keys(env).find((k) => k.toUpperCase() === name.toUpperCase());
  return key === undefined ? undefined : env[key];
}

/** Which Linux this is, from /etc/os-release's text: 'debian', 'ubuntu', 'fedora', 'arch' or null. */
export function linuxFamily(osRelease = '') {
  const field = (k) => ((new RegExp(`^${k}=["']?([^"'\\n]*)`, 'm').exec(osRelease) || [])[1] || '').toLowerCase();
  const ids = [field('ID'), ...field('ID_LIKE').split(/\s+/)].filter(Boolean);
  for (const family of ['ubuntu', 'debian', 'fedora', 'arch']) {
    if (ids.includes(family) || (family === 'fedora' && ids.some((i) => ['rhel', 'centos'].includes(i)))) return family;
  }
  return null;
}

const INSTALL = {
  debian: { chromium: 'chromium', firefox: 'firefox-esr' },
  ubuntu: { chromium: 'chromium-browser', firefox: 'firefox' },
};

/**
 * The one command that installs `kind` ('chromium' | 'firefox') on this OS: { line, root }, where
 * `line` is what a user types and `root` the same without sudo (apt only: tools/setup.js runs it
 * when it is root), or null.
 */
export function installCommand(kind, { platform, osRelease = '' }) {
  if (platform === 'darwin') return { line: kind === 'firefox' ? 'brew install --cask firefox' : 'brew install --cask google-chrome', root: null };
  // (-e --id: winget matches a bare name by substring, and may find more than one package)
  if (platform === 'win32') return { line: `winget install -e --id ${kind === 'firefox' ? 'Mozilla.Firefox' : 'Google.Chrome'}`, root: null };
  const family = linuxFamily(osRelease);
  const pkg = kind === 'firefox' ? 'firefox' : 'chromium';
  if (family === 'fedora') return { line: `sudo dnf install -y ${pkg}`, root: null };
  if (family === 'arch') return { line: `sudo pacman -S --needed ${pkg}`, root: null };
  // Debian, Ubuntu, and any other Linux (Debian's is this project's own)
  const apt = INSTALL[family === 'ubuntu' ? 'ubuntu' : 'debian'][kind];
  return { line: `sudo apt-get update && sudo apt-get install -y ${apt}`, root: `apt-get update && apt-get install -y ${apt}` };
}

/** Playwright's browser cache, as Playwright reads it (PLAYWRIGHT_BROWSERS_PATH first). */
function playwrightCache({ platform, env, home, cwd }) {
  const p = pathFor(platform);
  const set = envGet(env, 'PLAYWRIGHT_BROWSERS_PATH', platform);
  if (set && set !== '0') return p.resolve(cwd, set);
  if (platform === 'darwin') return p.join(home, 'Library', 'Caches', 'ms-playwright');
  if (platform === 'win32') return p.join(envGet(env, 'LOCALAPPDATA', platform) || p.join(home, 'AppData', 'Local'), 'ms-playwright');
  return p.join(envGet(env, 'XDG_CACHE_HOME', platform) || p.join(home, '.cache'), 'ms-playwright');
}

/**
 * Every place `kind` is looked for, in order: [{ file, how }]. `how` says which rule found it.
 * `list(dir)` gives a folder's names (Playwright's cache), [] when it is not there; `root` (tests
 * only) is where the fixed places of the OS are looked up instead of '/'.
 */
export function candidates(kind, { platform, env = {}, list = () => [], home = '', cwd = '/', root = null }) {
  const p = pathFor(platform);
  const out = [];
  const add = (file, how) => { if (file && !out.some((c) => c.file === file)) out.push({ file, how }); };
  const fixed = (file) => (root ? p.join(root, file) : file);
  const pathDirs = (envGet(env, 'PATH', platform) || '')
    .split(p.delimiter)
    .map((d) => d.replace(/^"(.*)"$/, '$1'))
    .filter((d) => d && p.isAbsolute(d));
  if (platform === 'win32') {
    const prefixes = ['LOCALAPPDATA', 'ProgramFiles', 'ProgramFiles(x86)'].map((k) => envGet(env, k, platform));
    const drive = envGet(env, 'HOMEDRIVE', platform) || envGet(env, 'SystemDrive', platform);
    if (drive) prefixes.push(p.join(`${drive}\\`, 'Program Files'), p.join(`${drive}\\`, 'Program Files (x86)'));
    for (const app of WINDOWS_APPS[kind]) for (const prefix of prefixes.filter(Boolean)) add(p.join(prefix, ...app), 'the usual Windows install');
    for (const name of WINDOWS_NAMES[kind]) for (const dir of pathDirs) add(p.join(dir, name), 'PATH');
  } else if (platform === 'darwin') {
    for (const app of MAC_APPS[kind]) {
      add(fixed(p.join('/Applications', app)), 'the usual macOS install');
      if (home) add(p.join(home, 'Applications', app), 'the usual macOS install');
    }
    for (const name of LINUX_NAMES[kind]) for (const dir of pathDirs) add(p.join(dir, name), 'PATH');
  } else {
    for (const name of LINUX_NAMES[kind]) {
      for (const dir of pathDirs) add(p.join(dir, name), 'PATH');
      add(fixed(p.join('/usr/bin', name)), 'the usual Linux install');
      add(fixed(p.join('/snap/bin', name)), 'the Ubuntu snap');
    }
    for (const file of LINUX_PLACES[kind]) add(fixed(file), 'the usual Linux install');
  }
  if (kind === 'chromium' && PLAYWRIGHT_CHROMIUM[platform]) {
    const cache = playwrightCache({ platform, env, home, cwd });
    const revision = (n) => Number(n.slice('chromium-'.length)) || 0;
    const builds = list(cache).filter((n) => /^chromium-\d+$/.test(n)).sort((a, b) => revision(b) - revision(a));
    for (const b of builds) for (const inner of PLAYWRIGHT_CHROMIUM[platform]) add(p.join(cache, b, ...inner), "Playwright's browser cache");
  }
  return out;
}

/**
 * The browser of `kind` ('chromium' | 'firefox') to drive: { found: true, path, how } (how: which
 * rule found it), or { found: false, message }; both with `install`, the one command for this OS
 * (installCommand).
 * `exists(file)` says a file is there and can be run. The environment variable (CHROMIUM_PATH,
 * FIREFOX_PATH) wins when it names a file that exists; one that names nothing is an error.
 */
export function findBrowser(kind, inputs) {
  const { platform, env = {}, exists } = inputs;
  const install = installCommand(kind, inputs);
  const name = ENV_VAR[kind];
  const chosen = envGet(env, name, platform);
  const title = TITLE[kind];
  if (chosen) {
    if (exists(chosen)) return { found: true, path: chosen, how: name, install };
    return { found: false, install, message: `${title} is not at ${chosen} (${name}): set ${name} to a browser's executable, or unset it and install one: ${install.line}` };
  }
  const hit = candidates(kind, inputs).find((c) => exists(c.file));
  if (hit) return { found: true, path: hit.file, how: hit.how, install };
  const which = kind === 'firefox' ? 'Firefox' : 'Chromium, Google Chrome or Microsoft Edge';
  return { found: false, install, message: `No ${which} was found on this machine. Install one:\n  ${install.line}\n(or set ${name} to a browser's executable)` };
}

/** This machine's inputs to findBrowser: the process's platform and environment, its files. */
export function thisMachine(env = process.env) {
  let osRelease = '';
  try {
    osRelease = readFileSync('/etc/os-release', 'utf8');
  } catch { /* (not Linux, or none) */ }
  const platform = process.platform;
  return {
    platform, env, osRelease, home: os.homedir(), cwd: process.cwd(),
    // (tests only: the OS's fixed places looked up under this folder, to play a machine without them)
    root: env.BROWSER_FINDER_ROOT || null,
    exists: (file) => {
      try {
        if (!statSync(file).isFile()) return false;
        if (platform !== 'win32') accessSync(file, constants.X_OK);
        return true;
      } catch {
        return false;
      }
    },
    list: (dir) => {
      try {
        return readdirSync(dir);
      } catch {
        return [];
      }
    },
  };
}

/** findBrowser on this machine. */
export const findHere = (kind, env = process.env) => findBrowser(kind, thisMachine(env));
