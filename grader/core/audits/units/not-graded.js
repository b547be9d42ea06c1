// The audit unit 'not-graded' (A part this browser cannot run (WebGPU here without it)): A part
// that uses WebGPU, in a browser that has none (Firefox ESR), is not graded there.
import { NOT_GRADED } from '../../verdict.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'not-graded': { title: 'A part this browser cannot run (WebGPU here without it)', slide: null, failureTitle: 'This browser cannot run the part', description: 'A part that uses WebGPU, in a browser that has none (Firefox ESR), is not graded there.', reads: ['facts.first'] },
};

/**
 * A part that asked for WebGPU (navigator.gpu, a 'webgpu' canvas) where the browser has none, and
 * got no WebGL context either, is not graded here: the browser is to blame, not the page. The
 * reason, or null.
 */
export function notGradedHere({ facts }) {
  const g = facts.first;
  if (!g || !g.webgpuMissing || /^webgl/.test(g.api || '')) return null;
  return `${NOT_GRADED}: this part uses WebGPU (it asked for navigator.gpu or a 'webgpu' canvas), and this browser has no WebGPU ` +
    '(Firefox ESR has none): grade it in Chromium, npm run grade without --browser firefox';
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'not-graded', (context) => {
  const reason = notGradedHere(context);
  if (reason) context.notGraded = { reason, id: 'not-graded' };
});
