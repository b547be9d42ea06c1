// The audit unit 'closed' (A closed mesh: every edge in two triangles): Counts the edges of the
// triangles the page sent: in a closed mesh each lies in two.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { judgedGeometry } from '../geometry.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  closed: { title: 'A closed mesh: every edge in two triangles', slide: SLIDE.sphere, failureTitle: 'The mesh is not closed', description: 'Counts the edges of the triangles the page sent: in a closed mesh each lies in two.', reads: ['facts.geometry', 'facts.geometryAtFirst'] },
};

/** A sphere is closed: every edge of its mesh belongs to two triangles. */
export function auditClosed({ facts, thresholds, sayAs }) {
  const say = sayAs('closed');
  const g = judgedGeometry(facts);
  if (!g || !g.closed || !g.closed.edges) return;
  const { open, edges } = g.closed;
  if (open / edges > thresholds.openEdgeShare) say('mistake', `the sphere is not closed: ${open} of its ${edges} edges belong to one triangle only (read from the triangles the page sent), so it has holes`);
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'closed', auditClosed);
