// The audit unit 'per-face' (n = p at each vertex, not a colour per face): Reads whether the
// page's colour or normal attribute is the same at the three corners of most triangles: n = p is
// per vertex, not per face.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { pct } from '../../format.js';
import { judgedGeometry } from '../geometry.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'per-face': { title: 'n = p at each vertex, not a colour per face', slide: SLIDE.normalColour, failureTitle: 'A colour per face, not n = p at each vertex', description: 'Reads whether the page\'s colour or normal attribute is the same at the three corners of most triangles: n = p is per vertex, not per face.', reads: ['facts.geometry', 'facts.geometryAtFirst'] },
};

/** WP04P1/P2: n = p at each vertex, not a colour or normal per face. */
export function auditPerFace({ facts, thresholds, must, sayAs }) {
  const say = sayAs('per-face');
  if (!must.has('normal-colours')) return;
  const g = judgedGeometry(facts);
  if (!g || !g.perFace) return;
  const face = g.perFace.find(
    (a) => /norm|col/i.test(a.name) && a.share >= thresholds.perFaceShare && a.distinct >= thresholds.perFaceDistinct,
  );
  if (face) say('mistake', `a colour per face, not per vertex: the attribute ${face.name} is the same at the three corners of ${pct(face.share)} of the triangles (a face's normal or colour; the slide: "vertex positions p are also vertex normals n: n = p")`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'per-face', auditPerFace);
