// P5 (Phong shading, per fragment): a page that shows the sphere in more than one canvas of one size
// (Gouraud shading beside Phong shading, to compare) is judged on the canvas the step asks about, as
// a teacher looks at it: the one named for per-fragment shading, else the one canvas not named
// for per-vertex (Gouraud) shading beside one that is. Where the names do not tell, the first is judged,
// as before. facts.canvases says how many there were and which was judged, and why.
import { namedIn, namedOnlyIn } from '../controls.js';

/** A canvas in words: its place on the page and its first names. */
const inWords = (c) => `canvas ${c.index + 1}${c.labels.length ? ` (${c.labels.slice(0, 2).map((l) => `"${l}"`).join(', ')})` : ''}`;

/** Chooses the canvas the step asks about among the page's largest, before the first picture is taken. */
export async function chooseStepCanvas(session) {
  const { page, facts } = session;
  if (!session.must.has('per-fragment') || !page.canvases) return;
  const shown = (await page.canvases()).filter((c) => c.shown);
  const area = (c) => c.width * c.height, most = Math.max(0, ...shown.map(area));
  const largest = shown.filter((c) => most > 0 && area(c) === most);
  if (largest.length < 2) return;
  const is = (c, role) => namedIn(c.labels, role, session.patterns);
  const only = (c, role, other) => namedOnlyIn(c.labels, role, other, session.patterns);
  const fragment = largest.filter((c) => only(c, 'perFragment', 'perVertex'));
  const vertex = largest.filter((c) => only(c, 'perVertex', 'perFragment'));
  const rest = largest.filter((c) => !is(c, 'perVertex'));
  const [pick, why] = fragment.length === 1 ? [fragment[0], 'named for per-fragment shading']
    : !fragment.length && vertex.length && rest.length === 1 ? [rest[0], `the one not named for per-vertex shading, beside ${inWords(vertex[0])}`]
      : [largest[0], 'the first: their names do not say which shows per-fragment shading'];
  if (pick !== largest[0]) await page.chooseCanvas(pick.index);
  facts.canvases = { largest: largest.length, judged: inWords(pick), why };
  session.act(`judged ${inWords(pick)} of the ${largest.length} canvases of one size: ${why}`);
}
