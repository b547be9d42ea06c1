// WP04P1 in WebGPU: a solid sphere in perspective; Subdivide / Coarsen rewrite one vertex buffer,
// made once for the largest level.
import { lookAt, perspectiveZO } from '../common/math.js';
import { MAX_LEVEL, sphereMesh, vertexBytes } from '../common/sphere.js';
import { createShaderModule, createUniformBuffer, loadWGSL, setUniforms } from '../common/gpu.js';
import { BACKGROUND } from '../common/course.js';
import { openStep } from '../common/step.js';
import { STEPS } from '../common/steps.js';
import { run } from '../common/page.js';

async function main() {
  // The page: URL parameters, canvas and device, controls, window.scene (common/step.js; the
  // parameters this step reads: common/steps.js)
  const page = await openStep(STEPS.WP04P1, { webgpu: true });
  const { camera } = page;
  const wgsl = await loadWGSL('shader.wgsl');

  // Camera: a perspective view of the unit sphere from 3 units along the +z axis
  const P = perspectiveZO(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = lookAt(camera.eye, camera.at, camera.up);
  const uniforms = { P, V };

  // GPU set-up: the pipeline, the one vertex buffer, the uniform buffer and its bind group. It
  // runs once; again only if the device is lost.
  let device, context, pipeline, vBuffer, uBlock, bindGroup, renderPass;
  async function init(gpu) {
    ({ device, context } = gpu);
    const module = await createShaderModule(device, wgsl);
    pipeline = device.createRenderPipeline({
      label: 'WP04P1 sphere',
      layout: 'auto',
      vertex: { module, entryPoint: 'main_vs', buffers: [{ arrayStride: 12, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x3' }] }] },
      fragment: { module, entryPoint: 'main_fs', targets: [{ format: gpu.format }] },
      primitive: { topology: 'triangle-list' },
    });
    vBuffer = device.createBuffer({ label: 'sphere vertices', size: vertexBytes(MAX_LEVEL), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
    uBlock = createUniformBuffer(device, wgsl.code, 'uniforms');
    bindGroup = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer: uBlock.buffer } }] });
    // The render pass, described once: a frame only names the canvas's texture of the moment
    const [r, g, b, a] = BACKGROUND;
    renderPass = { colorAttachments: [{ view: null, loadOp: 'clear', clearValue: { r, g, b, a }, storeOp: 'store' }] };
  }

  // A level change rewrites the one buffer (slide "Replacing an object")
  let numVertices = 0;
  function setLevel(level) {
    const positions = sphereMesh(level);
    device.queue.writeBuffer(vBuffer, 0, positions);
    numVertices = positions.length / 3;
    return numVertices;
  }

  // ---- set-up ends here; drawing (on demand: nothing moves) ----
  function draw() {
    setUniforms(device, uBlock, uniforms);
    const encoder = device.createCommandEncoder();
    renderPass.colorAttachments[0].view = context.getCurrentTexture().createView();
    const pass = encoder.beginRenderPass(renderPass);
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bindGroup);
    pass.setVertexBuffer(0, vBuffer);
    pass.draw(numVertices);
    pass.end();
    device.queue.submit([encoder.finish()]);
  }
  await page.start({ init, setLevel, draw });
}

run(main);
