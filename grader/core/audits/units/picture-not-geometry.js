// The audit unit 'picture-not-geometry' (A sphere of triangles, not a picture): A round sphere on
// screen drawn from fewer than pictureTriangles triangles (counted from what the page sent) is a
// picture, not a subdivided tetrahedron.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'picture-not-geometry': { title: 'A sphere of triangles, not a picture', slide: SLIDE.sphere, failureTitle: 'A picture, not a sphere of triangles', description: 'A round sphere on screen drawn from fewer than pictureTriangles triangles (counted from what the page sent) is a picture, not a subdivided tetrahedron.', reads: ['facts.geometry', 'images.judged', 'facts.geometryAtFirst'] },
};

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

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'picture-not-geometry', (context, results) => auditPictureNotGeometry(context, results['judged-picture']), { uses: ['judged-picture'] });
