// Every audit by its id (Lighthouse's audit meta): its title, the title a part that misses it gets
// (failureTitle), what it checks (description), the slide's sentence it checks (null
// where a miss names none: the page, not the step), a note shown beside that sentence, and the
// artifacts it reads. A reason carries its audit's id (verdict.js), and the check page, the
// feedback pages, grades.csv and the grader's README find a reason's slide and its column by that
// id, never by its words.
import { META as page } from './page.js';
import { META as firstFrame } from './first-frame.js';
import { META as channels } from './channels.js';
import { META as sphere } from './sphere.js';
import { META as geometry } from './geometry.js';
import { META as normals } from './normals.js';
import { META as diffuse } from './diffuse.js';
import { META as orbit } from './orbit.js';
import { META as highlight } from './highlight.js';
import { META as sliders } from './sliders.js';
import { META as shading } from './shading.js';
import { META as surface } from './surface.js';

const modules = {
  page,
  firstFrame,
  channels,
  sphere,
  geometry,
  normals,
  diffuse,
  orbit,
  highlight,
  sliders,
  shading,
  surface,
};

/** id → { id, title, failureTitle, description, slide, note?, reads, module }. */
export const AUDITS = {};
for (const [module, meta] of Object.entries(modules)) {
  for (const [id, m] of Object.entries(meta)) {
    if (AUDITS[id]) throw new Error(`audit id ${id} is in both ${AUDITS[id].module} and ${module}`);
    AUDITS[id] = { id, ...m, module };
  }
}

/** `id`'s meta; throws for an id no audit declares (a reason must carry a declared id). */
export function auditMeta(id) {
  const m = AUDITS[id];
  if (!m) throw new Error(`no audit has the id ${id}`);
  return m;
}
