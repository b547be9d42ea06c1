// The audit unit 'depth-culling' (The depth test and back-face culling enabled): Reads whether
// the page enables the depth test and back-face culling (WebGL calls; WebGPU's depthStencil and
// cullMode).
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'depth-culling': { title: 'The depth test and back-face culling enabled', slide: SLIDE.depthCulling, failureTitle: 'The depth test or back-face culling is not enabled', description: 'Reads whether the page enables the depth test and back-face culling (WebGL calls; WebGPU\'s depthStencil and cullMode), with its own toggles or face-culling menu set as the step asks where they start off.', reads: ['facts.faces', 'facts.api', 'facts.facesSetBy'] },
};

/** P2: the depth test and back-face culling enabled (the slide: "no visible effect of the back face culling"). */
export function auditDepthCulling({ facts, must, sayAs, numbers }) {
  const say = sayAs('depth-culling');
  if (!must.has('depth-culling')) return;
  const faces = facts.faces || {};
  const api = facts.api === 'webgpu' ? { depth: 'depthStencil with a depthCompare', cull: "cullMode: 'back'" } : { depth: 'gl.enable(gl.DEPTH_TEST)', cull: 'gl.enable(gl.CULL_FACE)' };
  numbers.faces = faces;
  // switched on by the page's own control, where it starts off (the step: "now, enable the depth test")
  const by = (r) => (facts.facesSetBy && facts.facesSetBy[r] ? `, by the page's own control ${facts.facesSetBy[r]}: it starts off` : '');
  if (faces.depthTest) say('pass', `the depth test is enabled (${api.depth}${by('depth')})`);
  else say('mistake', `the depth test is never enabled (${api.depth}): the slide asks for it`);
  if (faces.culling) say('pass', `back-face culling is enabled (${api.cull}${faces.cullMode && faces.cullMode !== 'back' ? `, culling ${faces.cullMode} faces` : ''}${by('cull')})`);
  else say('mistake', `back-face culling is never enabled (${api.cull}): the slide asks for it, though it shows no visible effect`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'depth-culling', auditDepthCulling);
