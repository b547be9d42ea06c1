// When a property of the step cannot be seen, the page's own controls make it visible, as a
// teacher does by hand: a picture that clips to white over much of the sphere hides its diffuse
// shading and its highlight, so the page's own kd, Le and La sliders are lowered (halved toward
// their least, one at a time) until it no longer does. The sliders stay where they were lowered for
// the rest of the part (the slider trials, the highlight's search), and facts.unclipped says what
// was changed, so that the reasons can name it. A picture too dim to show its diffuse shading (a
// dark light) is read again with the page's own Le slider (else kd) at its greatest.
import { samples, luminance, clippedShare } from '../measure/samples.js';
import { groupsOf, setGroup, leastValue, greatestValue } from './params.js';
import { PERCENT, THOUSANDTHS } from '../units.js';

/** The page's free parameter groups for `roles` that are sliders or numbers (not colour pickers), in the order of `roles`. */
function numericGroups(session, controls, roles) {
  const groups = groupsOf(session, controls);
  return roles.map((r) => groups.find((g) => g.role === r && g.controls.every((c) => c.type !== 'color'))).filter(Boolean);
}

/**
 * The judged picture `img` (outline `an`) clips over clippedShare or more of the sphere: the page's
 * kd, Le and La sliders halved in turn (at most maxUnclipSteps settings) until at most
 * unclippedShare clips. facts.unclipped: { before, after, steps: [{ role, control, value }], image };
 * returns the picture to read the shading from, or null (nothing lowered).
 */
export async function unclip(session, controls, img, an) {
  const { thresholds, facts } = session;
  const before = clippedShare(img, an, thresholds);
  if (before < thresholds.clippedShare) return null;
  const groups = numericGroups(session, controls, ['kd', 'Le', 'La']);
  if (!groups.length) return null;
  session.step('lowering the page\'s own sliders: the picture clips to white');
  const steps = [];
  let share = before, shot = null;
  for (let k = 0; k < thresholds.maxUnclipSteps && share > thresholds.unclippedShare; k++) {
    const g = groups[k % groups.length];
    const vs = await setGroup(session, g, (c) => {
      const lo = leastValue(c), v = Number(session.now(c));
      return Math.round(THOUSANDTHS * (lo + (v - lo) / 2)) / THOUSANDTHS;
    });
    g.controls.forEach((c, i) => session.values.set(c.index, vs[i]));
    await session.tick(session.thresholds.actionTickMs);
    const sh = await session.shot();
    if (!sh || sh.an.blank) break;
    shot = sh;
    share = clippedShare(sh.img, an, thresholds);
    steps.push({ role: g.role, control: g.controls[0].index, value: vs[0] });
    session.act(`set the ${g.role} slider to ${vs[0]} (the picture clipped to white over ${Math.round(PERCENT * before)}% of the sphere; now ${Math.round(PERCENT * share)}%)`);
  }
  if (!shot) return null;
  facts.unclipped = { before, after: share, steps, image: session.keep('unclipped', shot.img) };
  facts.shadingImage = facts.unclipped.image;
  return shot.img;
}

/** The spread (standard deviation) of the brightness over the sphere's samples (the judged view's outline `an`). */
export function brightnessSpread(img, an, thresholds) {
  const ys = samples(img, an, thresholds).map((s) => luminance(s.c));
  if (!ys.length) return 0;
  const mean = ys.reduce((a, y) => a + y, 0) / ys.length;
  return Math.sqrt(ys.reduce((a, y) => a + (y - mean) ** 2, 0) / ys.length);
}

/**
 * The judged picture `img` (outline `an`) is too dim to show diffuse shading (its brightness
 * spread under evenSpread, where the diffuse audit says "evenly bright"): the page's own Le
 * slider (else kd) set to its greatest, and left there; read again where that spreads its
 * brightness to litSpread at least. facts.brightened: { before, after, steps: [{ role, control,
 * value }], image }; returns the picture to read the shading from, or null.
 */
export async function brighten(session, controls, img, an) {
  const { thresholds, facts } = session;
  const before = brightnessSpread(img, an, thresholds);
  if (before >= thresholds.evenSpread) return null;
  const [g] = numericGroups(session, controls, ['Le', 'kd']);
  if (!g || g.controls.every((c) => Number(session.now(c)) >= greatestValue(c))) return null;
  session.step('raising the page\'s own light: the picture is too dim to show its shading');
  const vs = await setGroup(session, g, greatestValue);
  await session.tick(session.thresholds.actionTickMs);
  const sh = await session.shot();
  const after = sh && !sh.an.blank ? brightnessSpread(sh.img, an, thresholds) : 0;
  if (after < thresholds.litSpread) {
    // raised as far as the page lets it and still too dim to read: set back, and read as it was seen
    await setGroup(session, g, (c) => session.now(c));
    await session.tick(session.thresholds.actionTickMs);
    return null;
  }
  g.controls.forEach((c, i) => session.values.set(c.index, vs[i]));
  session.act(`set the ${g.role} slider to ${vs[0]} (the sphere was too dim to show its shading: brightness spread ${before.toFixed(3)}; now ${after.toFixed(3)})`);
  facts.brightened = {
    before,
    after,
    steps: [{ role: g.role, control: g.controls[0].index, value: vs[0] }],
    image: session.keep('brightened', sh.img),
  };
  facts.shadingImage = facts.brightened.image;
  return sh.img;
}
