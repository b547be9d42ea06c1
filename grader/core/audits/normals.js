// WP04P1/P2: "colour = 0.5·p + 0.5", read back as normals 2c − 1, and (P2) the normals facing the
// viewer: front faces only, the depth test and back-face culling enabled.
import { analyse, samples, normalColours, pictureChange } from '../measure.js';
import { facesViewer } from '../gather/probes.js';

const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));

/** The normals as colours, on the judged picture (`judged`: { img, an }) or the one the page's face controls gave. */
export function auditNormals({ facts, images, T, must, say, numbers }, judged) {
  if (!must.has('normalColours') && !must.has('frontFaces')) return;
  let { img, an } = judged;
  if (facts.facesImage) {
    img = images[facts.facesImage];
    an = analyse(img, T);
  }
  const nc = normalColours(samples(img, an));
  // a reflection of the sphere's normals is the inside of the far side (the front faces culled), or
  // the faces nearest a viewer who looks along +z (clip space, no view matrix): with the depth test
  // on and culling off the nearest faces show; if the picture stays, they were what showed
  let nearest = null;
  const probe = facts.noCull;
  if (must.has('frontFaces') && probe) {
    if (probe.faces.depthTest && probe.faces.culling) {
      const s = probe.image ? images[probe.image] : null;
      const sAn = s && analyse(s, T);
      const nc2 = s && !sAn.blank ? normalColours(samples(s, sAn)) : null;
      nearest = nc2 ? nc2.det < 0 && pictureChange(s, img) <= 0.01 : null;
    } else if (probe.faces.depthTest) nearest = true;
  }
  numbers.normals = nc;
  if (!nc) say('mistake', 'too little of the sphere to read its colours');
  else if (nc.spread < T.normalsSpread) say('mistake', 'the sphere is one colour: the normals are not used for the colour (0.5·n + 0.5)');
  else if (nc.unitError > T.normalsUnitError) {
    say('mistake', `the colours are not 0.5·n + 0.5: 2c − 1 is not a unit vector (off by ${fmt(nc.unitError)} on average)`);
  } else say('pass', `colours decode to unit normals 2c − 1 (off by ${fmt(nc.unitError, 3)})`);
  if (must.has('frontFaces') && nc && nc.spread >= T.normalsSpread) {
    if (facesViewer(nc, T)) say('pass', 'the visible colours are the normals facing the viewer: front faces only');
    else if (nearest) say('pass', 'the visible faces are the nearest ones (the depth test is on, and culling off draws the same picture): the view looks along +z (clip space without a view matrix?), so their normals point away from +z');
    else if (nc.det < 0 && nc.residual <= T.facingResidual) say('mistake', 'the inside of the far side shows (the normals face away from the viewer): the front faces are culled, or the depth test is off and the far side is drawn last');
    else say('mistake', `back faces show through the front (normals do not vary smoothly across the picture, misfit ${fmt(nc.residual)}): depth test or culling missing`);
  }
}

/** P2: the depth test and back-face culling enabled (the slide: "no visible effect of the back face culling"). */
export function auditDepthCulling({ facts, must, say, numbers }) {
  if (!must.has('depthCulling')) return;
  const faces = facts.faces || {};
  const api = facts.api === 'webgpu' ? { depth: 'depthStencil with a depthCompare', cull: "cullMode: 'back'" } : { depth: 'gl.enable(gl.DEPTH_TEST)', cull: 'gl.enable(gl.CULL_FACE)' };
  numbers.faces = faces;
  if (faces.depthTest) say('pass', `the depth test is enabled (${api.depth})`);
  else say('mistake', `the depth test is never enabled (${api.depth}): the slide asks for it`);
  if (faces.culling) say('pass', `back-face culling is enabled (${api.cull}${faces.cullMode && faces.cullMode !== 'back' ? `, culling ${faces.cullMode} faces` : ''})`);
  else say('mistake', `back-face culling is never enabled (${api.cull}): the slide asks for it, though it shows no visible effect`);
}
