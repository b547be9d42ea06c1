// The machine's Chromium (find-browser.js: Debian's on this one) as the grader, the tests and the
// tools launch it: the flags a machine without a GPU needs, and those for a SwiftShader WebGPU
// adapter (hand-ins come in both APIs).
import { findHere } from './find-browser.js';

const FOUND = findHere('chromium');
/** The Chromium (or Chrome, or Edge) to drive, or null when the machine has none (CHROMIUM_MISSING says what to run). */
export const CHROMIUM = FOUND.found ? FOUND.path : null;
/** Why there is no CHROMIUM, with the one command that installs one on this OS (null when there is one). */
export const CHROMIUM_MISSING = FOUND.found ? null : FOUND.message;
/** The one command that installs a Chromium (or Chrome) on this OS. */
export const CHROMIUM_INSTALL = FOUND.install.line;
/** Which rule found CHROMIUM (CHROMIUM_PATH, PATH, the usual install, Playwright's cache). */
export const CHROMIUM_HOW = FOUND.found ? FOUND.how : null;
// (--disable-gpu-compositing: the page is composited on the CPU, not through SwiftShader's GL; the
// canvases still draw with SwiftShader, the screenshots and captures are the same pixels, and each
// frame costs less: foundation and lighting specs 3m11 → 2m34, a class graded 2m57 → 2m35)
export const CHROMIUM_ARGS = [
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--no-first-run', '--disable-quic', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-compositing',
];

/** Chromium flags for a SwiftShader WebGPU adapter on this machine (no --disable-gpu): what
 * grader/browser/webgpu-capture.js reads a WebGPU canvas through. */
export const WEBGPU_ARGS = ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-webgpu-adapter=swiftshader'];

/** Launches Chromium, or throws an Error saying how to install it. */
export async function launchChromium(options = {}) {
  if (!CHROMIUM) throw new Error(CHROMIUM_MISSING);
  // (loaded here, not at the top: a command that launches no browser does not wait for Playwright)
  const { chromium } = await import('@playwright/test');
  return chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, ...options });
}
