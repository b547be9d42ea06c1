// WP04P1/P2: "colour = 0.5·p + 0.5", read back as normals 2c − 1, the sphere "in perspective view"
// (how far those normals reach at the rim), and (P2) the normals facing the viewer: front faces
// only, the depth test and back-face culling enabled, or the slide's clockwise experiment. P3–P5:
// the same colours where lighting is asked are not lighting.
import { analyse, samples, normalColours, facesViewer, pictureChange, addedTintFit, addedClearly } from '../measure.js';
import { rimAngle } from '../measure/perspective.js';
import { fmt } from '../format.js';
import { SLIDE } from './slides.js';
import { unit } from './unit.js';
import { RIGHT_ANGLE } from '../units.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'normal-colours': { title: 'Colours that are the normals, 0.5·n + 0.5', slide: SLIDE.normalColour, failureTitle: 'The colours are not the normals, 0.5·n + 0.5', description: 'Reads the colours inside the outline as normals (colour = 0.5·n + 0.5) and fits them to a sphere\'s.', reads: ['images.judged', 'facts.facesImage', 'facts.api'] },
  'front-faces': { title: 'The normals facing the viewer: front faces only', slide: SLIDE.depthCulling, failureTitle: 'The normals shown do not face the viewer', description: 'Checks that the colours show normals facing the viewer, and draws once with culling off to see what culling hides.', reads: ['images.judged', 'facts.noCull', 'facts.faces'] },
  perspective: { title: 'In perspective view (how far the normals reach at the rim)', slide: SLIDE.sphere, note: 'an orthographic view shows the normals out to 90° at the rim', failureTitle: 'Not in perspective view', description: 'Measures how far the normals the colours show reach at the rim: 90° in an orthographic view, less in perspective.', reads: ['images.judged'] },
  'normals-not-light': { title: 'A lit step shows lighting, not the normal colouring of WP04P1', slide: SLIDE.gouraud, failureTitle: 'A lit step that shows the normal colouring, not lighting', description: 'Tells WP04P1\'s colours (0.5·n + 0.5) from shading in a step that should be lit.', reads: ['images.judged'] },
  'depth-culling': { title: 'The depth test and back-face culling enabled', slide: SLIDE.depthCulling, failureTitle: 'The depth test or back-face culling is not enabled', description: 'Reads whether the page enables the depth test and back-face culling (WebGL calls; WebGPU\'s depthStencil and cullMode).', reads: ['facts.faces', 'facts.api'] },
};

/**
 * The normals as colours, on the judged picture (`judged`: { img, an }) or the one the page's face
 * controls gave. Returns what was read ({ img, an, nc }) for auditPerspective, or null.
 */
export function auditNormals({ facts, images, thresholds, must, sayAs, numbers }, judged) {
  const say = sayAs('normal-colours');
  if (!must.has('normal-colours') && !must.has('front-faces')) return null;
  let { img, an } = judged;
  if (facts.facesImage) {
    img = images[facts.facesImage];
    an = analyse(img, thresholds);
  }
  const nc = normalColours(samples(img, an, thresholds), thresholds);
  // a reflection of the sphere's normals is the inside of the far side (the front faces culled), or
  // the faces nearest a viewer who looks along +z (clip space, no view matrix): with the depth test
  // on and culling off the nearest faces show; if the picture stays, they were what showed
  let nearest = null;
  const probe = facts.noCull;
  if (must.has('front-faces') && probe) {
    if (probe.faces.depthTest && probe.faces.culling) {
      // (a page that drew nothing while culling was off shows its last frame: that tells nothing)
      const s = probe.image && probe.draws !== 0 ? images[probe.image] : null;
      const sAn = s && analyse(s, thresholds);
      const nc2 = s && !sAn.blank ? normalColours(samples(s, sAn, thresholds), thresholds) : null;
      nearest = nc2 ? nc2.det < 0 && pictureChange(s, img, thresholds) <= thresholds.noCullSame : null;
    } else if (probe.faces.depthTest) nearest = true;
  }
  numbers.normals = nc;
  if (!nc) say('mistake', 'too little of the sphere to read its colours');
  else if (nc.spread < thresholds.normalsSpread) say('mistake', 'the sphere is one colour: the normals are not used for the colour (0.5·n + 0.5)');
  else if (nc.unitError > thresholds.normalsUnitError) {
    say('mistake', `the colours are not 0.5·n + 0.5: 2c − 1 is not a unit vector (off by ${fmt(nc.unitError)} on average)`);
  } else say('pass', `colours decode to unit normals 2c − 1 (off by ${fmt(nc.unitError, 3)})`);
  const sayFaces = sayAs('front-faces');
  if (must.has('front-faces') && nc && nc.spread >= thresholds.normalsSpread) {
    if (facesViewer(nc, thresholds)) sayFaces('pass', 'the visible colours are the normals facing the viewer: front faces only');
    else if (nearest) sayFaces('pass', 'the visible faces are the nearest ones (the depth test is on, and culling off draws the same picture): the view looks along +z (clip space without a view matrix?), so their normals point away from +z');
    else if (nc.det < 0 && nc.residual <= thresholds.facingResidual) {
      if (clockwiseExperiment(facts)) sayFaces('pass', `note: the back side of the sphere shows, as the slide's clockwise experiment asks ("Try changing the convention to having clockwise wound triangles being front facing … You should now see the back side of the sphere"): ${facts.api === 'webgpu' ? "frontFace: 'cw'" : 'gl.frontFace(gl.CW)'} with back-face culling on; the default, counter-clockwise, shows the front`);
      else sayFaces('mistake', 'the inside of the far side shows (the normals face away from the viewer): the front faces are culled, or the depth test is off and the far side is drawn last');
    } else sayFaces('mistake', `back faces show through the front (normals do not vary smoothly across the picture, misfit ${fmt(nc.residual)}): depth test or culling missing`);
  }
  return { img, an, nc };
}

/** The page set clockwise front faces (gl.frontFace(gl.CW), WebGPU's frontFace: 'cw') with back faces culled. */
function clockwiseExperiment(facts) {
  const faces = facts.faces || (facts.noCull && facts.noCull.faces) || {};
  return faces.frontFace === 'cw' && !!faces.culling && (faces.cullMode || 'back') === 'back';
}

/** The colours decode to unit normals (2c − 1) that vary over the picture as one side of a sphere's do. */
const smoothUnitNormals = (nc, thresholds) =>
  !!nc &&
  !(
    nc.spread < thresholds.normalsSpread ||
    nc.unitError > thresholds.normalsUnitError ||
    nc.residual > thresholds.facingResidual
  );

/**
 * WP04P1/P2: "Draw a solid sphere in perspective view". Where the colours decode to the normals of
 * one side of the sphere (`seen`: what auditNormals read), the rim's angle tells the projection: an
 * orthographic view shows normals out to 90° from the view direction, a perspective view from a
 * distance d none past acos(1/d). Where front and back faces mix, the picture cannot tell: not said.
 */
export function auditPerspective({ thresholds, must, sayAs, numbers }, seen) {
  const say = sayAs('perspective');
  if (!must.has('perspective') || !seen || !seen.nc) return;
  const { img, an, nc } = seen;
  if (!smoothUnitNormals(nc, thresholds)) return;
  const far = nc.det < 0;
  if (!far && nc.det < thresholds.facingDeterminant) return;
  const rim = rimAngle(samples(img, an, thresholds, { maxRho: thresholds.rimSampleRadius }), far, thresholds);
  if (!rim || rim.rms > thresholds.perspectiveFitDegrees) return;
  numbers.perspective = rim;
  const short = Math.abs(RIGHT_ANGLE - rim.rimDegrees);
  const side = far ? 'the inside of the far side, whose normals' : 'the normals';
  if (short >= RIGHT_ANGLE - thresholds.orthographicRimDegrees) {
    say('pass', `in perspective view: ${side} reach ${fmt(rim.rimDegrees, 0)}° from the view direction at the rim, an eye about ${fmt(rim.distance, 1)} sphere radii from the centre (acos(1/d) = ${fmt(RIGHT_ANGLE - short, 0)}°; an orthographic view reaches 90°)`);
  } else {
    say('mistake', `not in perspective view (the slide: "Draw a solid sphere in perspective view"): ${side} reach ${fmt(rim.rimDegrees, 0)}° from the view direction at the rim, as an orthographic view shows them (90°); a perspective view from a distance d shows none past acos(1/d) (71° at d = 3): an orthographic projection, or an eye so far away that it looks the same?`);
  }
}

/**
 * P3–P5: a lit step whose colours still decode to unit normals everywhere (WP04P1's 0.5·n + 0.5,
 * which a diffuse fit accepts: its brightness is linear in n, and it turns with the orbit) shows no
 * lighting, unless the lighting is added on top (0.5·p + 0.5·L_o decodes to unit normals where L_o
 * is near 1): then the channels show a light common to all three beside the normal colouring
 * (addedClearly), and the shading is judged with the colouring taken out. Returns true when it
 * says the picture is no lighting (the shading is then not judged as lighting).
 */
export function auditNormalsNotLight({ thresholds, must, sayAs, numbers }, judged) {
  const say = sayAs('normals-not-light');
  if (!must.has('diffuse') && !must.has('highlight')) return false;
  const pts = samples(judged.img, judged.an, thresholds);
  const nc = normalColours(pts, thresholds);
  if (!smoothUnitNormals(nc, thresholds) || Math.abs(nc.det) < thresholds.facingDeterminant) return false;
  if (addedClearly(addedTintFit(pts, thresholds), thresholds)) return false;
  numbers.normalColouring = nc;
  say('mistake', `shows the normal colouring of WP04P1, not the lighting: its colours decode to unit normals 2c − 1 all over the sphere (off by ${fmt(nc.unitError, 3)}), which is 0.5·n + 0.5, not kd·Le·max(n·w_i, 0) + ambient`);
  return true;
}

/** P2: the depth test and back-face culling enabled (the slide: "no visible effect of the back face culling"). */
export function auditDepthCulling({ facts, must, sayAs, numbers }) {
  const say = sayAs('depth-culling');
  if (!must.has('depth-culling')) return;
  const faces = facts.faces || {};
  const api = facts.api === 'webgpu' ? { depth: 'depthStencil with a depthCompare', cull: "cullMode: 'back'" } : { depth: 'gl.enable(gl.DEPTH_TEST)', cull: 'gl.enable(gl.CULL_FACE)' };
  numbers.faces = faces;
  if (faces.depthTest) say('pass', `the depth test is enabled (${api.depth})`);
  else say('mistake', `the depth test is never enabled (${api.depth}): the slide asks for it`);
  if (faces.culling) say('pass', `back-face culling is enabled (${api.cull}${faces.cullMode && faces.cullMode !== 'back' ? `, culling ${faces.cullMode} faces` : ''})`);
  else say('mistake', `back-face culling is never enabled (${api.cull}): the slide asks for it, though it shows no visible effect`);
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  unit(META, 'normal-colours', (context, results) => auditNormals(context, results['judged-picture']), { also: ['front-faces'], uses: ['judged-picture'] }),
  unit(META, 'perspective', (context, results) => auditPerspective(context, results['normal-colours']), { uses: ['normal-colours'] }),
  unit(META, 'depth-culling', auditDepthCulling),
  // a lit step that shows WP04P1's colours has no shading to judge (true then): its colours are not lighting
  unit(META, 'normals-not-light', (context, results) => context.litStep && auditNormalsNotLight(context, results['judged-picture']), { uses: ['judged-picture'] }),
];
