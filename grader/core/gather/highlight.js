// P4/P5, feeding audits/highlight.js: the highlight shown by the page's own ks and s sliders where no
// view showed it, and its place judged in a view farther along the orbit. Each records the pictures
// it took; the decisions read the same evidence the audits do (computed/evidence.js).
import { highlightSeen } from '../measure.js';
import { describeGroup } from '../controls.js';
import { lightAngle, fullFit } from '../computed/views.js';
import { highlightIn } from '../computed/evidence.js';
import { searchOrbit } from './orbit.js';
import { readSurface } from './geometry.js';
import { groupsOf, setGroup, greatestValue, groupFacts } from './params.js';

/**
 * P4/P5, no highlight seen: the page's own material sliders show it: ks up to its greatest, then s
 * down to 10 (a broad highlight). facts.raised: [{ role, control, value, image, seen }].
 */
export async function raiseHighlight(session, controls) {
  const { thresholds } = session;
  const set = [];
  // s raised to raisedShininess, within the slider's range
  const s10 = (c) =>
    Math.max(Number(c.min || 0) + 1, Math.min(thresholds.raisedShininess, Number(c.max || thresholds.raisedShininess)));
  const raised = session.facts.raised = [];
  const groups = groupsOf(session, controls).filter((g) =>
    g.controls.every((c) => c.type === 'range' || c.type === 'number' || (g.role === 'ks' && c.type === 'color')),
  );
  const ksTop = (c) => (c.type === 'color' ? greatestValue(c) : Number(c.max === '' || c.max === undefined ? 1 : c.max));
  for (const [r, to] of [['ks', ksTop], ['s', s10]]) {
    const g = groups.find((x) => x.role === r);
    if (!g || raised.some((x) => x.seen)) continue;
    const c = g.controls[0];
    const vs = await setGroup(session, g, to);
    set.push(g);
    await session.tick(session.thresholds.actionTickMs);
    const sh = await session.shot();
    const seen = !!sh && highlightIn(sh.img, thresholds);
    raised.push({
      role: r,
      ...groupFacts(g, vs),
      value: vs[0],
      broad: r === 's' && s10(c) < Number(session.now(c)),
      image: sh ? session.keep(`raised-${r}`, sh.img) : null,
      seen,
    });
    session.act(`set ${describeGroup(g)} to ${vs[0]} to look for a highlight${seen ? ': one shows' : ''}`);
  }
  for (const g of set) await setGroup(session, g, (c) => session.now(c));
  if (set.length) await session.tick(session.thresholds.actionTickMs);
}

/**
 * The highlight's place where the light is at least highlightPlaceLightDegrees from the viewer: the
 * orbit on (with the sliders as they showed the highlight), sampled until such a view shows the
 * highlight over a clean diffuse fit, or orbitSamples positions; then off again.
 */
export async function placeFarther(session, controls) {
  const { thresholds, orbit, facts } = session;
  session.step('looking along the orbit for a view with the light away from the viewer');
  const raised = (facts.raised || []).some((x) => x.seen) ? facts.raised : []; // the sliders as they showed the highlight
  const byIndex = (i) => controls.find((c) => c.index === i);
  const each = async (value) => {
    for (const x of raised) {
      const cs = (x.controls || [x.control]).map(byIndex);
      for (let k = 0; k < cs.length; k++) await session.page.setValue(cs[k], value(x, k, cs[k]), ['input', 'change']);
    }
  };
  await each((x, k) => (x.values ? x.values[k] : x.value));
  let far = { img: null, k: 0 }, surface = null;
  if (await session.tryClick(orbit.start, 'the orbit control', { watchMotion: true }) === 'starts') {
    far = await searchOrbit(session, (img, an) => {
      if (an.blank || an.roundness >= thresholds.orbitCoarseRoundness) return false;
      const f = fullFit(img, thresholds); // (the fit the highlight's place is judged on: audits/highlight.js)
      return (
        !!f &&
        f.r2 >= thresholds.diffuseR2 &&
        highlightSeen(f, thresholds) &&
        lightAngle(f) >= thresholds.highlightPlaceLightDegrees
      );
    });
    // its surface, as the page drew that view (no frame has run since: the orbit is stopped after)
    if (far.img) surface = await readSurface(session, 'place-');
    await session.tryClick(orbit.stop, 'the orbit control again', { watchMotion: true });
  }
  await each((x, k, c) => session.now(c));
  session.act(
    `sampled the orbit at ${far.k} positions for a view with the light ${thresholds.highlightPlaceLightDegrees}° or more from the viewer${raised.length ? `, ${raised.map((x) => `${x.role} at ${x.value}`).join(' and ')}` : ''}: ${far.img ? 'one shows the highlight' : 'none shows the highlight over a clean diffuse fit'}`,
  );
  facts.placeFarther = { image: far.img ? session.keep('highlight-place', far.img) : null, ...(surface ? { surface } : {}) };
}
