// Every audit unit, in the order core/audit.js runs them: the order a teacher reads a part (can
// it be judged at all, the sphere, its geometry, its lighting). A unit runs after the units whose
// results it uses. Adding an audit is a module with its META and its UNITS (audits/unit.js), and
// its id in ORDER below.
import { UNITS as page } from './page.js';
import { UNITS as firstFrame } from './first-frame.js';
import { UNITS as channels } from './channels.js';
import { UNITS as sphere } from './sphere.js';
import { UNITS as geometry } from './geometry.js';
import { UNITS as normals } from './normals.js';
import { UNITS as surface } from './surface.js';
import { UNITS as readings } from './readings.js';
import { UNITS as diffuse } from './diffuse.js';
import { UNITS as orbit } from './orbit.js';
import { UNITS as highlight } from './highlight.js';
import { UNITS as sliders } from './sliders.js';
import { UNITS as shading } from './shading.js';

const ORDER = [
  // can the part be judged: this browser runs it, it left the grader's hooks alone, it was
  // gathered within the bounds, it drew a first frame, the level ladder was climbed
  'not-graded',
  'tamper',
  'too-slow',
  'shown-channels',
  'first-frame',
  'ladder-climbed',
  'heavy-level',
  'orbit-stops-again',
  'level-ladder',
  'level-controls',
  // the sphere at the judged level, its geometry and its normals
  'judged-picture',
  'sphere',
  'closed',
  'all-round',
  'growth',
  'loops-multiply',
  'picture-not-geometry',
  'normal-colours',
  'perspective',
  'per-face',
  'depth-culling',
  'winding',
  // the lighting
  'surface-fit',
  'normals-not-light',
  'shading',
  'unclipped',
  'brightened',
  'lit-views',
  'diffuse',
  'orbit-light',
  'point-light',
  'highlight',
  'sliders',
  'least-s',
  'per-fragment',
  'highlight-place',
  'orbit-not-stopped',
];

const ALL = [
  ...page,
  ...firstFrame,
  ...channels,
  ...sphere,
  ...geometry,
  ...normals,
  ...surface,
  ...readings,
  ...diffuse,
  ...orbit,
  ...highlight,
  ...sliders,
  ...shading,
];

/** The units in ORDER; checks that each is listed once and runs after the units it uses. */
export function orderedUnits(units, order) {
  const byId = new Map();
  for (const u of units) {
    if (byId.has(u.id)) throw new Error(`two audit units have the id ${u.id}`);
    byId.set(u.id, u);
  }
  const unlisted = units.filter((u) => !order.includes(u.id)).map((u) => u.id);
  if (unlisted.length) throw new Error(`audit units not in the list: ${unlisted.join(', ')}`);
  const seen = new Set();
  return order.map((id) => {
    const u = byId.get(id);
    if (!u) throw new Error(`the list names ${id}, which no audit unit declares`);
    const later = u.uses.filter((x) => !seen.has(x));
    if (later.length) throw new Error(`the audit unit ${id} uses ${later.join(', ')}, which run after it (or not at all)`);
    seen.add(id);
    return u;
  });
}

/** Every audit unit, in the order they run. */
export const AUDIT_LIST = orderedUnits(ALL, ORDER);
