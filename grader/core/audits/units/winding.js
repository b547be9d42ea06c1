// The audit unit 'winding' (The triangles wound so that the culling keeps the near side): Reads
// the winding of the triangles the page sent, against its frontFace and cullFace.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { pct } from '../../format.js';
import { judgedGeometry } from '../geometry.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  winding: { title: 'The triangles wound so that the culling keeps the near side', slide: SLIDE.depthCulling, failureTitle: 'The triangles are wound so that culling removes the near side', description: 'Reads the winding of the triangles the page sent, against its frontFace and cullFace.', reads: ['facts.geometry', 'facts.geometryAtFirst', 'facts.faces', 'facts.api'] },
};

/** The share of the triangles, wound as read, that the culling the page set takes away seen from outside. */
function culledOutward(cull, cw) {
  const [mode, front] = cull.split('/');
  if (mode === 'both') return 1;
  const outwardIsFront = front === 'cw' ? cw : 1 - cw; // (seen from outside, a face is front where its winding is the front one)
  return mode === 'front' ? outwardIsFront : 1 - outwardIsFront;
}

/** Every step that culls: the triangles wound against the culling show the inside of the far side, or a hole. */
export function auditWinding({ facts, thresholds, must, sayAs, numbers }) {
  const say = sayAs('winding');
  const g = judgedGeometry(facts);
  const any = facts.geometry || facts.geometryAtFirst;
  if (!g) {
    if (any && any.why && facts.faces && facts.faces.culling) say('pass', `note: which way the triangles are wound was not read from what the page sent to WebGL (${any.why}); the faces are judged from the pictures`);
    return;
  }
  numbers.geometry = { triangles: g.triangles, analysed: g.analysed, cw: g.cw, cull: g.cull, closed: g.closed };
  if (!g.cull || g.cull === 'off') return;
  const webgpu = facts.api === 'webgpu';
  const [mode, front] = g.cull.split('/');
  const setting = webgpu ? `cullMode '${mode}' with frontFace '${front}'` : `gl.enable(gl.CULL_FACE) with gl.cullFace(gl.${mode === 'both' ? 'FRONT_AND_BACK' : mode.toUpperCase()}) and ${front === 'cw' ? 'gl.frontFace(gl.CW)' : 'the default gl.frontFace(gl.CCW)'}`;
  const share = culledOutward(g.cull, g.cw);
  const read = `read from the ${g.analysed} triangles the page sent`;
  if (share >= thresholds.windingCulledShare) {
    // (P2: clockwise front faces over a counter-clockwise mesh is the slide's own experiment, said by the normals' audit)
    if (must.has('front-faces') && mode === 'back' && front === 'cw' && g.cw <= 1 - thresholds.windingCulledShare) return;
    say('mistake', `the near side of the sphere is culled and the inside of the far side shows: ${pct(g.cw)} of its triangles are wound clockwise seen from outside (${read}; the textbook's tetrahedron winds its faces so), and ${setting} culls the faces that point toward the viewer`);
  } else if (share >= thresholds.windingHoleShare) {
    say('mistake', `a hole shows from some side: ${pct(share)} of the triangles are wound the other way from the rest (${read}), and ${setting} takes them away where they face the viewer`);
  } else say('pass', `the triangles are wound so that the culling keeps the near side, in the model's space: ${pct(1 - g.cw)} of them counter-clockwise seen from outside (${read})`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'winding', auditWinding);
