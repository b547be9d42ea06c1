// When the check page gives a part no verdict: "not checked here", never a fail that is not the
// student's. Two cases: the part uses WebGPU and this browser has none (Firefox ESR, a browser
// without an adapter), and the self-check's own instrumentation broke the page (an error that
// names its globals, or a page script that ran before it: check/frame-watch.js's `broken`). Plain
// functions of what the check saw; the part's own errors stay the student's.

/** The verdict the check page gives such a part (window.check's parts, the card's badge). */
export const NOT_CHECKED = 'not checked';

/** Whether a page's or script's source calls WebGPU (navigator.gpu, requestAdapter, a 'webgpu' canvas context). */
export function usesWebGPU(source) {
  return /\bnavigator\s*\.\s*gpu\b|\brequestAdapter\s*\(|getContext\s*\(\s*["'`]webgpu["'`]/.test(source);
}

/** What the check page says at the top, once, when a part is not checked for want of WebGPU. */
export const NO_WEBGPU_HERE = 'This browser has no WebGPU, which your WebGPU parts need: they are marked "not checked here", not failed. ' +
  'Check them in Chromium or Google Chrome (or Edge) with WebGPU, where the teacher\'s grader runs them too. The WebGL parts are checked here as usual.';

/**
 * Why a checked part gets no verdict here, or null when its verdict stands.
 * @param {object} o
 * @param {boolean} o.webgpuHere this browser has navigator.gpu and an adapter
 * @param {boolean} o.usedWebGPU the part's page or scripts call WebGPU (usesWebGPU), or the grader saw it ask
 * @param {string|null} o.api the API the part drew with (the grader's state), if any
 * @param {string[]} o.broken what the frame watch saw the instrumentation break
 * @returns {{ why: 'webgpu'|'instrumentation', reason: string } | null}
 */
export function notCheckedHere({ webgpuHere, usedWebGPU, api, broken = [] }) {
  if (!webgpuHere && usedWebGPU && !/^webgl/.test(api || '')) {
    return { why: 'webgpu', reason: 'not checked here: this part uses WebGPU, which this browser does not have (no navigator.gpu, or no WebGPU adapter). ' +
      'Check it in Chromium or Google Chrome with WebGPU.' };
  }
  if (broken.length) {
    return { why: 'instrumentation', reason: `not checked here: the self-check's own instrumentation broke this page (${broken[0]}), so it gives no verdict on it: ` +
      'the trouble is the self-check\'s, not necessarily your page\'s. Tell your teacher, with this message.' };
  }
  return null;
}

/** Whether this browser has a WebGPU adapter (the API alone is not enough: headless and some GPUs give none). */
export async function hasWebGPU() {
  try {
    return !!(navigator.gpu && (await navigator.gpu.requestAdapter()));
  } catch {
    return false;
  }
}
