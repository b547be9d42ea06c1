// WP04P2 in WebGPU: WP04P1 plus hidden surface removal. The depth test, culling and the winding
// of front faces are pipeline state: one pipeline per combination, made on first use and kept.
// The depth texture (and, with ?msaa=4, the multisampled colour target) is made once.
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
  const page = await openStep(STEPS.WP04P2, { webgpu: true });
  const { canvas, state, camera } = page;
  const wgsl = await loadWGSL('shader.wgsl');

  // Camera: a perspective view of the unit sphere from 3 units along the +z axis
  const P = perspectiveZO(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = lookAt(camera.eye, camera.at, camera.up);
  const uniforms = { P, V };

  // GPU set-up: the pipeline, the one vertex buffer, the uniform buffer and its bind group. It
  // runs once; again only if the device is lost.
  const msaaCount = Number(state.msaa);
  let device, context, module, format, layout, vBuffer, uBlock, bindGroup, msaaTexture, renderPass;
  const pipelines = []; // by depth · 4 + cull · 2 + cw
  async function init(gpu) {
    ({ device, context, format } = gpu);
    module = await createShaderModule(device, wgsl);
    pipelines.length = 0;
    // one bind group layout (the uniform buffer) shared by every pipeline
    const bindGroupLayout = device.createBindGroupLayout({ label: 'uniforms', entries: [
      { binding: 0, visibility: GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT, buffer: {} }] });
    layout = device.createPipelineLayout({ bindGroupLayouts: [bindGroupLayout] });
    vBuffer = device.createBuffer({ label: 'sphere vertices', size: vertexBytes(MAX_LEVEL), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
    uBlock = createUniformBuffer(device, wgsl.code, 'uniforms');
    bindGroup = device.createBindGroup({ layout: bindGroupLayout, entries: [{ binding: 0, resource: { buffer: uBlock.buffer } }] });
    // A canvas-sized depth texture (and colour target, when multisampling), as the slides make them
    const depthTexture = device.createTexture({ label: 'depth', size: [canvas.width, canvas.height], format: 'depth24plus', sampleCount: msaaCount, usage: GPUTextureUsage.RENDER_ATTACHMENT });
    msaaTexture = msaaCount > 1 ? device.createTexture({ label: 'multisampled colour', size: [canvas.width, canvas.height], format, sampleCount: msaaCount, usage: GPUTextureUsage.RENDER_ATTACHMENT }) : null;
    // The render pass, described once: a frame only names the canvas's texture of the moment
    const [r, g, b, a] = BACKGROUND;
    renderPass = {
      colorAttachments: [{ view: msaaTexture?.createView(), loadOp: 'clear', clearValue: { r, g, b, a }, storeOp: 'store' }],
      depthStencilAttachment: { view: depthTexture.createView(), depthLoadOp: 'clear', depthClearValue: 1.0, depthStoreOp: 'store' },
    };
  }
  // Hidden surface removal: keep the nearest fragment (depthCompare 'less'), skip triangles facing
  // away (cullMode 'back'); frontFace says which winding faces the viewer
  function pipelineFor(depth, cull, cw) {
    const key = (depth ? 4 : 0) + (cull ? 2 : 0) + (cw ? 1 : 0);
    if (!pipelines[key]) {
      pipelines[key] = device.createRenderPipeline({
        label: `WP04P2 sphere: depth test ${depth ? 'on' : 'off'}, cull ${cull ? 'back' : 'none'}, front ${cw ? 'cw' : 'ccw'}`,
        layout,
        vertex: { module, entryPoint: 'main_vs', buffers: [{ arrayStride: 12, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x3' }] }] },
        fragment: { module, entryPoint: 'main_fs', targets: [{ format }] },
        primitive: { topology: 'triangle-list', frontFace: cw ? 'cw' : 'ccw', cullMode: cull ? 'back' : 'none' },
        multisample: { count: msaaCount },
        depthStencil: { depthWriteEnabled: depth, depthCompare: depth ? 'less' : 'always', format: 'depth24plus' },
      });
    }
    return pipelines[key];
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
    const colour = renderPass.colorAttachments[0];
    // with multisampling the pass resolves into the canvas; without, it draws there
    colour[msaaTexture ? 'resolveTarget' : 'view'] = context.getCurrentTexture().createView();
    const pass = encoder.beginRenderPass(renderPass);
    pass.setPipeline(pipelineFor(state.depth, state.cull, state.cw));
    pass.setBindGroup(0, bindGroup);
    pass.setVertexBuffer(0, vBuffer);
    pass.draw(numVertices);
    pass.end();
    device.queue.submit([encoder.finish()]);
  }
  await page.start({ init, setLevel, draw });
}

run(main);
