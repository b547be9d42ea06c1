// WP04P3 in WebGPU: Gouraud shading. The diffuse reflection per vertex, lit by a directional or a
// point light; the camera orbits the sphere, animated by a tick() function on requestAnimationFrame.
import { lookAt, mat4, perspectiveZO } from '../common/math.js';
import { MAX_LEVEL, sphereMesh, vertexBytes } from '../common/sphere.js';
import { createShaderModule, createUniformBuffer, loadWGSL, setUniforms } from '../common/gpu.js';
import { BACKGROUND, EYE_DISTANCE } from '../common/course.js';
import { openStep } from '../common/step.js';
import { STEPS } from '../common/steps.js';
import { run } from '../common/page.js';

async function main() {
  // The page: URL parameters, canvas and device, controls, window.scene (common/step.js; the
  // parameters this step reads: common/steps.js)
  const page = await openStep(STEPS.WP04P3, { webgpu: true });
  const { canvas, state, camera, scene } = page;
  const wgsl = await loadWGSL('shader.wgsl');

  // Camera: the eye orbits at radius r in the xz-plane; V follows it in every frame
  const P = perspectiveZO(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = mat4();
  // The uniforms by their names in the shader; kd and Le are the sliders' own values (state).
  // The light in world space: [x, y, z, w] with w = 0 a direction, w = 1 a point.
  const uniforms = { P, V, lightPos: scene.light.position };

  // GPU set-up: the pipeline, the one vertex buffer, the uniform buffer and its bind group. It
  // runs once; again only if the device is lost.
  const msaaCount = Number(state.msaa);
  let device, context, pipeline, vBuffer, uBlock, bindGroup, msaaTexture, renderPass;
  async function init(gpu) {
    ({ device, context } = gpu);
    const module = await createShaderModule(device, wgsl);
    // The depth test and back-face culling of WP04P2, now fixed in the one pipeline
    pipeline = device.createRenderPipeline({
      label: 'WP04P3 sphere',
      layout: 'auto',
      vertex: { module, entryPoint: 'main_vs', buffers: [{ arrayStride: 12, attributes: [{ shaderLocation: 0, offset: 0, format: 'float32x3' }] }] },
      fragment: { module, entryPoint: 'main_fs', targets: [{ format: gpu.format }] },
      primitive: { topology: 'triangle-list', frontFace: 'ccw', cullMode: 'back' },
      multisample: { count: msaaCount },
      depthStencil: { depthWriteEnabled: true, depthCompare: 'less', format: 'depth24plus' },
    });
    vBuffer = device.createBuffer({ label: 'sphere vertices', size: vertexBytes(MAX_LEVEL), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
    uBlock = createUniformBuffer(device, wgsl.code, 'uniforms');
    bindGroup = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer: uBlock.buffer } }] });
    // A canvas-sized depth texture (and colour target, when multisampling), as the slides make them
    const depthTexture = device.createTexture({ label: 'depth', size: [canvas.width, canvas.height], format: 'depth24plus', sampleCount: msaaCount, usage: GPUTextureUsage.RENDER_ATTACHMENT });
    msaaTexture = msaaCount > 1 ? device.createTexture({ label: 'multisampled colour', size: [canvas.width, canvas.height], format: gpu.format, sampleCount: msaaCount, usage: GPUTextureUsage.RENDER_ATTACHMENT }) : null;
    // The render pass, described once: a frame only names the canvas's texture of the moment
    const [r, g, b, a] = BACKGROUND;
    renderPass = {
      colorAttachments: [{ view: msaaTexture?.createView(), loadOp: 'clear', clearValue: { r, g, b, a }, storeOp: 'store' }],
      depthStencilAttachment: { view: depthTexture.createView(), depthLoadOp: 'clear', depthClearValue: 1.0, depthStoreOp: 'store' },
    };
  }

  // A level change rewrites the one buffer (slide "Replacing an object")
  let numVertices = 0;
  function setLevel(level) {
    const positions = sphereMesh(level);
    device.queue.writeBuffer(vBuffer, 0, positions);
    numVertices = positions.length / 3;
    return numVertices;
  }

  // ---- set-up ends here; drawing: tick() calls draw() in every animation frame while orbiting ----
  function draw() {
    // e = (r sin α, 0, r cos α); V = lookAt(e, at, up)
    camera.eye[0] = EYE_DISTANCE * Math.sin(state.angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(state.angle);
    lookAt(camera.eye, camera.at, camera.up, V);
    setUniforms(device, uBlock, uniforms, state);
    const encoder = device.createCommandEncoder();
    const colour = renderPass.colorAttachments[0];
    // with multisampling the pass resolves into the canvas; without, it draws there
    colour[msaaTexture ? 'resolveTarget' : 'view'] = context.getCurrentTexture().createView();
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
