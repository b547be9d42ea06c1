// The audit unit 'normal-colours' (Colours that are the normals, 0.5·n + 0.5): Reads the colours
// inside the outline as normals (colour = 0.5·n + 0.5) and fits them to a sphere's.
import { analyse, samples, normalColours, facesViewer, pictureChange } from '../../measure.js';
import { fmt, pct } from '../../format.js';
import { surfaceOf } from '../../computed/surface.js';
import { sideSeen } from '../../measure/near-side.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'normal-colours': { title: 'Colours that are the normals, 0.5·n + 0.5', slide: SLIDE.normalColour, failureTitle: 'The colours are not the normals, 0.5·n + 0.5', description: 'Reads the colours inside the outline as normals (colour = 0.5·n + 0.5) and fits them to a sphere\'s.', reads: ['images.judged', 'facts.facesImage', 'facts.api'] },
  'front-faces': { title: 'The normals facing the viewer: front faces only', slide: SLIDE.depthCulling, failureTitle: 'The normals shown do not face the viewer', description: 'Reads on the page\'s own surface (of the picture the page\'s own depth and culling controls gave, where they changed it), after its own projection, whether the visible pixels are the near half\'s outside (each pixel\'s normal facing the camera its matrices set up) and, where not, what in the projection turns it; where the surface was not read, checks that the colours show normals facing the viewer, and draws once with culling off to see what culling hides.', reads: ['facts.surface', 'images.judged', 'facts.noCull', 'facts.faces', 'facts.facesImage', 'facts.facesSurface'] },
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
  if (must.has('front-faces') && surfaceFaces(facts, images, thresholds, sayFaces)) return { img, an, nc };
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

/** What makes the far side show, as the page's own matrices say (measure/near-side.js's farSideCause). */
const FAR_SIDE_CAUSE = {
  mirrored: 'its projection turns the picture over (a face toward the camera is wound clockwise on the screen: two projections multiplied, or a negative scale?), so culling the back faces takes away the near ones',
  depth: 'its projection gives nearer points a greater depth, so the depth test keeps the far ones',
};

/**
 * The side seen, read per pixel on the page's own surface after its own projection (where it was
 * read): the near half's outside, or not. Says front-faces and returns true; false where the
 * surface was not read (the colours decide, as before).
 */
function surfaceFaces(facts, images, thresholds, say) {
  // (the picture the page's own face controls gave, where they changed it: its surface)
  const surface = facts.facesImage && facts.facesSurface ? facts.facesSurface : facts.surface;
  const s = surface && surfaceOf(surface, images, thresholds);
  const side = s && !s.why ? sideSeen(s) : null;
  if (!side) return false;
  const controls = surface === facts.facesSurface ? ', with the page\'s own depth and culling controls set as the step asks: they start off' : '';
  const read = `read on the page's own surface${controls}: ${pct(side.share)} of the ${side.samples} pixels read have a normal that faces the camera its matrices (P·V·M) set up`;
  if (side.share >= thresholds.nearSideShare) say('pass', `the visible pixels are the near half's outside (${read})`);
  else if (clockwiseExperiment(facts)) say('pass', `note: the back side of the sphere shows, as the slide's clockwise experiment asks ("You should now see the back side of the sphere"): ${facts.api === 'webgpu' ? "frontFace: 'cw'" : 'gl.frontFace(gl.CW)'} with back-face culling on (${read})`);
  else if (side.share <= 1 - thresholds.nearSideShare) say('mistake', `the inside of the far half shows, not the near half's outside (${read})${side.cause ? `: ${FAR_SIDE_CAUSE[side.cause]}` : ''}`);
  else say('mistake', `part of the far side shows through the near side (${read}): the depth test off, or culling that takes away some near faces?`);
  return true;
}

/** The page set clockwise front faces (gl.frontFace(gl.CW), WebGPU's frontFace: 'cw') with back faces culled. */
function clockwiseExperiment(facts) {
  const faces = facts.faces || (facts.noCull && facts.noCull.faces) || {};
  return faces.frontFace === 'cw' && !!faces.culling && (faces.cullMode || 'back') === 'back';
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'normal-colours', (context, results) => auditNormals(context, results['judged-picture']), { also: ['front-faces'], uses: ['judged-picture'] });
