// The init scripts a graded page gets, in the order they must run, the same in either browser: the
// browser's own functions kept first (natives.js), the page kept open where it is (stay.js),
// WebGPU's capture where the browser has WebGPU (Chromium; Firefox ESR has none), then the draw
// batch, the instrumentation, the pixels and the canvases (canvases.js), the console (console.js),
// the recorders, the frozen clock and the watch on the grader's hooks.
import { webgpuCaptureScript } from '../../browser/webgpu-capture.js';
import { drawBatchScript } from '../../browser/draw-batch.js';
import { instrumentScript } from '../../browser/instrument.js';
import { recordersInit } from '../../browser/geometry.js';
import { nativesInit } from '../../browser/natives.js';
import { stayInit } from '../../browser/stay.js';
import { pixelsScript } from '../../browser/pixels.js';
import { canvasesScript } from '../../browser/canvases.js';
import { consoleScript } from '../../browser/console.js';
import { tamperScript } from '../../browser/tamper.js';
import { FROZEN, clockScript } from '../../browser/clock.js';

// the draws of WebGL frames nobody looks at left undone (grader/browser/unseen-frames.js)
const skipUnseenScript = 'window.__grade.unseen.on = true;';

/**
 * The scripts' texts, in order; `webgpu`: the browser has WebGPU, and its frames are captured;
 * `skipUnseen`: the draws of a frame another follows before the canvas is read are left undone.
 */
export const gradedPageScripts = ({ webgpu, skipUnseen = false }) => [
  nativesInit, stayInit, ...(webgpu ? [webgpuCaptureScript] : []), drawBatchScript, instrumentScript,
  ...(skipUnseen ? [skipUnseenScript] : []), pixelsScript, canvasesScript, consoleScript, recordersInit,
  clockScript(FROZEN),
  tamperScript,
];
