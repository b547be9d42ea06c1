// Every audit unit, in the order core/audit.js runs them: the order a teacher reads a part (can
// it be judged at all, the sphere, its geometry, its lighting). Each is a module of its own under
// units/, named by its id: its META (the ids it says) and one function, declared as a unit
// (audits/unit.js). A unit runs after the units whose results it uses. Adding an audit is a module
// under units/ and its place in ORDER below (with its import).
import { UNIT as notGraded } from './units/not-graded.js';
import { UNIT as tamper } from './units/tamper.js';
import { UNIT as stays } from './units/stays.js';
import { UNIT as tooSlow } from './units/too-slow.js';
import { UNIT as shownChannels } from './units/shown-channels.js';
import { UNIT as firstFrame } from './units/first-frame.js';
import { UNIT as ladderClimbed } from './units/ladder-climbed.js';
import { UNIT as heavyLevel } from './units/heavy-level.js';
import { UNIT as orbitStopsAgain } from './units/orbit-stops-again.js';
import { UNIT as levelLadder } from './units/level-ladder.js';
import { UNIT as levelControls } from './units/level-controls.js';
import { UNIT as judgedPicture } from './units/judged-picture.js';
import { UNIT as sphere } from './units/sphere.js';
import { UNIT as closed } from './units/closed.js';
import { UNIT as allRound } from './units/all-round.js';
import { UNIT as growth } from './units/growth.js';
import { UNIT as loopsMultiply } from './units/loops-multiply.js';
import { UNIT as pictureNotGeometry } from './units/picture-not-geometry.js';
import { UNIT as normalColours } from './units/normal-colours.js';
import { UNIT as perspective } from './units/perspective.js';
import { UNIT as perFace } from './units/per-face.js';
import { UNIT as depthCulling } from './units/depth-culling.js';
import { UNIT as winding } from './units/winding.js';
import { UNIT as surfaceFit } from './units/surface-fit.js';
import { UNIT as normalsNotLight } from './units/normals-not-light.js';
import { UNIT as shading } from './units/shading.js';
import { UNIT as unclipped } from './units/unclipped.js';
import { UNIT as brightened } from './units/brightened.js';
import { UNIT as litViews } from './units/lit-views.js';
import { UNIT as diffuse } from './units/diffuse.js';
import { UNIT as orbitLight } from './units/orbit-light.js';
import { UNIT as pointLight } from './units/point-light.js';
import { UNIT as highlight } from './units/highlight.js';
import { UNIT as sliders } from './units/sliders.js';
import { UNIT as termControls } from './units/term-controls.js';
import { UNIT as leastS } from './units/least-s.js';
import { UNIT as perFragment } from './units/per-fragment.js';
import { UNIT as highlightPlace } from './units/highlight-place.js';
import { UNIT as orbitNotStopped } from './units/orbit-not-stopped.js';

const ORDER = [
  // can the part be judged: this browser runs it, it left the grader's hooks alone (and what it
  // tried that would close or leave it), it was gathered within the bounds, it drew a first frame,
  // the level ladder was climbed
  notGraded,
  tamper,
  stays,
  tooSlow,
  shownChannels,
  firstFrame,
  ladderClimbed,
  heavyLevel,
  orbitStopsAgain,
  levelLadder,
  levelControls,
  // the sphere at the judged level, its geometry and its normals
  judgedPicture,
  sphere,
  closed,
  allRound,
  growth,
  loopsMultiply,
  pictureNotGeometry,
  normalColours,
  perspective,
  perFace,
  depthCulling,
  winding,
  // the lighting
  surfaceFit,
  normalsNotLight,
  shading,
  unclipped,
  brightened,
  litViews,
  diffuse,
  orbitLight,
  pointLight,
  highlight,
  sliders,
  termControls,
  leastS,
  perFragment,
  highlightPlace,
  orbitNotStopped,
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
export const AUDIT_LIST = orderedUnits(ORDER, ORDER.map((u) => u.id));
