// What the page sent to WebGL, judged where the record is exact (gather/geometry.js reads it):
// the triangles' winding against the culling the page set (the textbook's tetrahedron winds its
// faces clockwise seen from outside, so with back faces culled the near side goes: DESIGN.md, "A
// trap"), a mesh with holes, a colour or normal per face where the slides ask n = p per vertex
// (WP04P1/P2), and a page that draws more every frame while nothing is touched.
import { SLIDE } from './slides.js';
import { unit } from './unit.js';
import { pct } from '../format.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  winding: { title: 'The triangles wound so that the culling keeps the near side', slide: SLIDE.depthCulling, failureTitle: 'The triangles are wound so that culling removes the near side', description: 'Reads the winding of the triangles the page sent, against its frontFace and cullFace.', reads: ['facts.geometry', 'facts.geometryAtFirst', 'facts.faces', 'facts.api'] },
  closed: { title: 'A closed mesh: every edge in two triangles', slide: SLIDE.sphere, failureTitle: 'The mesh is not closed', description: 'Counts the edges of the triangles the page sent: in a closed mesh each lies in two.', reads: ['facts.geometry', 'facts.geometryAtFirst'] },
  'per-face': { title: 'n = p at each vertex, not a colour per face', slide: SLIDE.normalColour, failureTitle: 'A colour per face, not n = p at each vertex', description: 'Reads whether the page\'s colour or normal attribute is the same at the three corners of most triangles: n = p is per vertex, not per face.', reads: ['facts.geometry', 'facts.geometryAtFirst'] },
  growth: { title: 'The mesh not built again every frame', slide: SLIDE.recycle, failureTitle: 'The mesh is built again every frame', description: 'Counts the vertices the page uploads and draws while nothing is touched: they must not grow.', reads: ['facts.geometryAtFirst'] },
  'loops-multiply': { title: 'One animation loop, however often a control is used', slide: null, failureTitle: 'Each click starts another animation loop', description: 'Counts the animation loops and the draws a frame before and after the grader\'s clicks; a note, never a change of verdict.', reads: ['facts.frameDraws'] },
  'picture-not-geometry': { title: 'A sphere of triangles, not a picture', slide: SLIDE.sphere, failureTitle: 'A picture, not a sphere of triangles', description: 'A round sphere on screen drawn from fewer than pictureTriangles triangles (counted from what the page sent) is a picture, not a subdivided tetrahedron.', reads: ['facts.geometry', 'images.judged', 'facts.geometryAtFirst'] },
  'all-round': { title: 'Closed from every side seen along the orbit', slide: SLIDE.sphere, failureTitle: 'Not closed from every side along the orbit', description: 'Where the mesh cannot be read, looks at the outline at counted positions while the camera turns all the way round.', reads: ['facts.allRound'] },
};

/** The geometry judged: the judged level's, else the first level's (where the page went blank later). */
const judgedGeometry = (facts) =>
  [facts.geometry, facts.geometryAtFirst].find((g) => g && !g.why && g.analysed > 0) || null;

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
  } else say('pass', `the triangles are wound so that the culling keeps the near side: ${pct(1 - g.cw)} of them counter-clockwise seen from outside (${read})`);
}

/** A sphere is closed: every edge of its mesh belongs to two triangles. */
export function auditClosed({ facts, thresholds, sayAs }) {
  const say = sayAs('closed');
  const g = judgedGeometry(facts);
  if (!g || !g.closed || !g.closed.edges) return;
  const { open, edges } = g.closed;
  if (open / edges > thresholds.openEdgeShare) say('mistake', `the sphere is not closed: ${open} of its ${edges} edges belong to one triangle only (read from the triangles the page sent), so it has holes`);
}

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

/** A page whose vertices a frame grow while no control is touched builds its mesh again and appends it. */
export function auditGrowth({ facts, thresholds, sayAs, numbers }) {
  const say = sayAs('growth');
  const g = facts.geometryAtFirst;
  const f = g && g.frames;
  if (!f || f.length < thresholds.growthFrames) return;
  const last = f.slice(-thresholds.growthFrames);
  const grows =
    last.every((v, k) => k === 0 || v > last[k - 1]) && last[last.length - 1] >= thresholds.growthRatio * last[0];
  if (!grows) return;
  numbers.growth = f;
  say('mistake', `the page draws more every frame (${f[0]} → ${f[f.length - 1]} vertices over ${f.length} frames, no control touched): the mesh is built again and appended to its arrays, and the page slows until it stalls`);
}

/**
 * A page whose controls each start another animation loop (a click runs init() again, or calls the
 * loop's function that asks for the next frame): after the grader's clicks it runs several loops a
 * frame and draws its sphere as many times. Said to the student as a note; the verdict stands on the
 * pictures.
 */
export function auditLoopsMultiply({ facts, thresholds, sayAs, numbers }) {
  const f = facts.frameDraws;
  if (!f || !f.first || !f.last || !f.clicks || !(f.first.loops >= 1) || !(f.first.draws > 0)) return;
  if (
    f.last.loops < thresholds.loopsMultiplied * f.first.loops ||
    f.last.draws < thresholds.loopsMultiplied * f.first.draws
  ) {
    return;
  }
  numbers.frameDraws = f;
  // (the loops are counted exactly; the draws a frame also hold a click's own drawing)
  sayAs('loops-multiply')('pass', `note: the page draws its sphere ${f.last.loops} times a frame after ${f.clicks} click${f.clicks === 1 ? '' : 's'} (${f.last.loops} animation loops, where it started with ${f.first.loops}; ${f.last.draws} draw calls a frame, ${f.first.draws} at first): each click starts another animation loop, so the orbit speeds up and the page slows`);
}

/** A round sphere in the picture drawn with no more than a few triangles is a picture, not geometry (a textured quad, a sphere traced per pixel). */
export function auditPictureNotGeometry({ facts, thresholds, sayAs }, judged) {
  const say = sayAs('picture-not-geometry');
  // (the triangles are counted whether or not their positions could be read)
  const g = [facts.geometry, facts.geometryAtFirst].find((x) => x && Number.isFinite(x.triangles));
  if (
    !g ||
    !g.draws ||
    3 * g.triangles + (g.otherVertices || 0) > 3 * thresholds.pictureTriangles ||
    judged.an.blank ||
    !(judged.an.roundness <= thresholds.roundness)
  ) {
    return;
  }
  say('review', `the sphere is a picture, not geometry: a round sphere shows, but the page draws ${g.triangles} triangle${g.triangles === 1 ? '' : 's'} (read from what it sent to WebGL): the slide asks for a tetrahedron subdivided into a sphere`);
}

/**
 * Where the mesh could not be read (positions made in a shader), the outlines seen all round the
 * orbit (gather/all-round.js): a round outline with a gap in it is a hole on that side. Views whose
 * outline is not round (an unlit side merging with the background) tell nothing and are left out.
 */
export function auditAllRound({ facts, thresholds, sayAs, numbers, imagesShown }) {
  const say = sayAs('all-round');
  const r = facts.allRound;
  if (!r) return;
  const round = r.views.filter((v) => !v.blank && v.roundness <= thresholds.roundness);
  const gaps = round.filter((v) => v.fill < thresholds.fill);
  numbers.allRound = { views: r.views.length, round: round.length, gaps: gaps.length, turned: r.turned };
  const where = r.turned !== null ? `at ${r.views.length} positions along the orbit, the camera turning ${Math.round(r.turned)}°` : `at ${r.views.length} positions along the orbit (the page sends no view matrix the grader could read: how far it turned is not known)`;
  const why = `the mesh could not be read from what the page sent (${r.why})`;
  if (gaps.length) {
    if (r.gap) imagesShown.allRoundGap = r.gap;
    say('mistake', `a hole shows from some side: looked ${where}, ${gaps.length} of ${round.length} round outlines are not filled (down to ${pct(Math.min(...gaps.map((v) => v.fill)))}: the background shows through the sphere) (${why})`);
  } else if (round.length) {
    say('pass', `closed from every side it was seen from: ${round.length} round, filled outlines ${where} (${why}, so it was looked at all round)`);
  } else say('pass', `note: could not see whether the sphere is closed all round: no view ${where} showed a round outline (${why})`);
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  unit(META, 'closed', auditClosed),
  unit(META, 'all-round', auditAllRound),
  unit(META, 'growth', auditGrowth),
  unit(META, 'loops-multiply', auditLoopsMultiply),
  unit(META, 'picture-not-geometry', (context, results) => auditPictureNotGeometry(context, results['judged-picture']), { uses: ['judged-picture'] }),
  unit(META, 'per-face', auditPerFace),
  unit(META, 'winding', auditWinding),
];
