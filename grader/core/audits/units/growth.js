// The audit unit 'growth' (The mesh not built again every frame): Counts the vertices the page
// uploads and draws while nothing is touched: they must not grow.
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  growth: { title: 'The mesh not built again every frame', slide: SLIDE.recycle, failureTitle: 'The mesh is built again every frame', description: 'Counts the vertices the page uploads and draws while nothing is touched: they must not grow.', reads: ['facts.geometryAtFirst'] },
};

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

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'growth', auditGrowth);
