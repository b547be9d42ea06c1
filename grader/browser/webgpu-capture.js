// Seeing what a WebGPU page draws in headless Chromium. Headless Chromium gets a SwiftShader
// WebGPU adapter (WEBGPU_ARGS, grader/node/run/chromium.js) but cannot present a WebGPU canvas: a screenshot shows one flat
// colour. So an init script (webgpuCaptureScript, for context.addInitScript) stands in for the
// canvas's 'webgpu' context: configure() remembers the device and format, getCurrentTexture()
// hands out an ordinary texture of the canvas's size (RENDER_ATTACHMENT | COPY_SRC | the page's
// own usage), and after every queue.submit that drew into it the texture is copied into a buffer
// (copyTextureToBuffer, rows padded to 256 bytes), mapped (mapAsync), turned into RGBA (bgra8unorm
// swizzled) and put on the canvas through its 2D context. The page's files are not changed; the
// canvas then shows, screenshots and reads back like any other canvas.
// readWebGPUFrame(page) waits for the last frame's copy and returns it.

/**
 * The init script's body (its parts are passed in as arguments: the script is their text, see
 * webgpuCaptureScript). Publishes window.__webgpuCapture.
 */
function webgpuCapture(toRGBA, copier, capturedContextClass) {
  if (typeof navigator === 'undefined' || !navigator.gpu || typeof GPUQueue === 'undefined') return;
  const state = {
    frames: 0, captured: 0, width: 0, height: 0, format: null, pending: null, waiting: new Set(), errors: [],
  };
  // waits until the last submitted frame has been copied (no timers: the grader's clock may be
  // paused; a finished copy starts the next one at once)
  state.settled = async () => {
    for (let k = 0; k < 100 && state.pending; k++) await state.pending;
  };
  Object.defineProperty(window, '__webgpuCapture', { value: state, enumerable: false });
  const contexts = new Set();
  const realGetContext = HTMLCanvasElement.prototype.getContext;
  const realSubmit = GPUQueue.prototype.submit;
  const fakes = new WeakMap();
  const copy = copier(state, realSubmit, toRGBA);
  const CapturedCanvasContext = capturedContextClass(realGetContext, contexts);

  HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
    if (type !== 'webgpu') return realGetContext.call(this, type, ...rest);
    if (!fakes.has(this)) fakes.set(this, new CapturedCanvasContext(this));
    return fakes.get(this);
  };
  GPUQueue.prototype.submit = function (buffers) {
    const r = realSubmit.call(this, buffers);
    for (const ctx of contexts) {
      if (ctx.handedOut && ctx.config && ctx.config.device.queue === this) {
        ctx.handedOut = false;
        state.frames++;
        copy(ctx);
      }
    }
    return r;
  };
}

/** A mapped copy of a canvas texture (`bytes`, rows `bytesPerRow` apart) as RGBA, bgra8unorm swizzled. */
function toRGBA(ctx, bytes, bytesPerRow) {
  const { width, height } = ctx.texture;
  const out = new Uint8ClampedArray(width * height * 4);
  const bgra = ctx.config.format.startsWith('bgra');
  const opaque = (ctx.config.alphaMode || 'opaque') === 'opaque';
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = y * bytesPerRow + 4 * x, o = 4 * (y * width + x);
      out[o] = bytes[i + (bgra ? 2 : 0)];
      out[o + 1] = bytes[i + 1];
      out[o + 2] = bytes[i + (bgra ? 0 : 2)];
      out[o + 3] = opaque ? 255 : bytes[i + 3];
    }
  }
  return out;
}

/**
 * copy(ctx): ctx's texture as it is now (after the page's last submit) copied into the canvas's 2D
 * context, one copy at a time: a context submitted to while a copy is under way waits for it (each
 * canvas of a page that draws into two is copied, not only the first).
 */
function copier(state, realSubmit, toRGBA) {
  function copy(ctx) {
    if (state.pending) { state.waiting.add(ctx); return; }
    const { device } = ctx.config, texture = ctx.texture;
    const bytesPerRow = Math.ceil((4 * texture.width) / 256) * 256;
    const buffer = device.createBuffer({ label: 'webgpu-capture readback', size: bytesPerRow * texture.height,
      usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const encoder = device.createCommandEncoder({ label: 'webgpu-capture copy' });
    encoder.copyTextureToBuffer({ texture }, { buffer, bytesPerRow }, [texture.width, texture.height]);
    realSubmit.call(device.queue, [encoder.finish()]);
    state.pending = buffer.mapAsync(GPUMapMode.READ).then(() => {
      const pixels = toRGBA(ctx, new Uint8Array(buffer.getMappedRange()), bytesPerRow);
      buffer.unmap();
      buffer.destroy();
      const canvas = ctx.canvas;
      if (canvas.width === texture.width && canvas.height === texture.height) {
        ctx.ctx2d.putImageData(new ImageData(pixels, texture.width, texture.height), 0, 0);
      }
      Object.assign(state, {
        captured: state.captured + 1,
        width: texture.width,
        height: texture.height,
        format: ctx.config.format,
      });
    }, (err) => { state.errors.push(`readback: ${err.message}`); buffer.destroy(); })
      .finally(() => {
        state.pending = null;
        const [next] = state.waiting;
        if (next) { state.waiting.delete(next); copy(next); }
      });
  }
  return copy;
}

/** The stand-in for a canvas's 'webgpu' context: an ordinary texture handed out, the configured ones kept in `contexts`. */
function capturedContextClass(realGetContext, contexts) {
  return class CapturedCanvasContext {
    constructor(canvas) {
      this.canvas = canvas; this.config = null; this.texture = null; this.ctx2d = realGetContext.call(canvas, '2d');
    }
    configure(config) {
      if (!config || !config.device) throw new TypeError("GPUCanvasContext.configure: 'device' is required");
      this.config = { ...config };
      this.texture = null;
      contexts.add(this);
    }
    unconfigure() { this.config = null; this.texture = null; contexts.delete(this); }
    getConfiguration() { return this.config ? { ...this.config } : null; }
    getCurrentTexture() {
      if (!this.config) throw new DOMException('getCurrentTexture: the context is not configured', 'InvalidStateError');
      const { width, height } = this.canvas;
      if (!this.texture || this.texture.width !== width || this.texture.height !== height) {
        if (this.texture) this.texture.destroy();
        this.texture = this.config.device.createTexture({
          label: 'canvas texture (webgpu-capture)',
          size: [width, height],
          format: this.config.format,
          usage:
            (this.config.usage ?? GPUTextureUsage.RENDER_ATTACHMENT) |
            GPUTextureUsage.RENDER_ATTACHMENT |
            GPUTextureUsage.COPY_SRC,
          viewFormats: this.config.viewFormats || [],
        });
      }
      this.handedOut = true;
      return this.texture;
    }
  };
}

/** The init script (a string, for addInitScript / evaluateOnNewDocument, or a frame's script): its parts are its arguments. */
export const webgpuCaptureScript = `(${webgpuCapture})(${toRGBA}, ${copier}, ${capturedContextClass});`;

/**
 * Waits until the last submitted frame has been copied, and says what was captured:
 * { frames, captured, width, height, format, errors } or null on a page without WebGPU capture.
 */
export async function readWebGPUFrame(page) {
  return page.evaluate(async () => {
    const s = window.__webgpuCapture;
    if (!s) return null;
    await s.settled();
    return {
      frames: s.frames,
      captured: s.captured,
      width: s.width,
      height: s.height,
      format: s.format,
      errors: [...s.errors],
    };
  });
}
