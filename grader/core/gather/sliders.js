// P4/P5, feeding audits/sliders.js and the least-s audit (audits/shading.js): each parameter's
// sliders set far from where they are, on input (else change), with how much the picture changed on
// each event; s at its least.
import { pictureChange } from '../measure.js';
import { describeGroup, sentChanges } from '../controls.js';
import { sliderEvent } from '../computed/slider-event.js';
import { readSent } from './geometry.js';
import { groupsOf, setGroup, leastValue, freeControlNamed, groupFacts, RANGE_DEFAULT_MAX } from './params.js';

/**
 * P4: each parameter's sliders (one slider, or the three of a colour or vector: parameterGroups)
 * set far from where they are, on input (else change), its picture kept; then back. Each trial is
 * read against the picture (and what the page sent) just before it, in the same state: putting a
 * slider back to its value in the page can leave the page in another state than it started in (a
 * material the page set itself, its slider showing another value), and the next trial must not be
 * credited with that change. Where it did, the entry says how much (`restored`).
 */
export async function trySliders(session, controls) {
  const { thresholds, facts } = session;
  session.step('trying the sliders');
  const groups = groupsOf(session, controls);
  facts.slidersFound = groups.length;
  const animated = facts.sentAnimated;
  // the picture (and what the page sent) as the trial starts: the state the last one was put back to
  const readState = async () => {
    await session.tick(session.thresholds.actionTickMs);
    return { img: await session.page.snap(), sent: session.moving && animated ? await readSent(session) : null };
  };
  let start = await readState();
  for (const g of groups.slice(0, thresholds.maxSliderTrials)) {
    const k = g.role;
    const base = start.img, sentBefore = start.sent;
    const target = (c) => {
      if (c.type === 'color') return leastValue(c);
      const lo = leastValue(c), hi = Number(c.max === '' || c.max === undefined ? RANGE_DEFAULT_MAX : c.max);
      return k === 's' ? (Number(session.now(c)) > (lo + hi) / 2 ? lo : hi) : (Number(session.now(c)) > lo ? lo : hi); // s: far from where it is; others: to the least
    };
    const vs = await setGroup(session, g, target, ['input']);
    await session.tick(session.thresholds.actionTickMs);
    let after = await session.page.snap();
    // what the page sent differently (sentChanges) decides where the picture moves by itself
    const sent = { input: sentChanges(sentBefore, await readSent(session), animated), change: null };
    // how much the picture changed on each event tried; the event it acted on is decided by the
    // one reading the audits use (computed/slider-event.js), on what was seen so far: the change
    // event is tried where the input event showed nothing
    const changed = { input: pictureChange(base, after, thresholds), change: null };
    const seen = () => ({ changed, ...(session.moving && sent.input ? { moving: true, sent } : {}) });
    let how = sliderEvent(seen(), thresholds);
    if (how !== 'input') {
      await setGroup(session, g, target, ['change']);
      await session.tick(session.thresholds.actionTickMs);
      after = await session.page.snap();
      sent.change = sentChanges(sentBefore, await readSent(session), animated);
      changed.change = pictureChange(base, after, thresholds);
      how = sliderEvent(seen(), thresholds);
    }
    const r = k && k !== 'levelSlider' ? k : null;
    session.act(`set ${describeGroup(g)} to ${vs[0]} (${how === 'none' ? 'no visible change' : `the picture changed on the ${how} event`})`);
    if (how !== 'none' && k !== 'levelSlider') {
      facts.roles[r || `slider ${Object.keys(facts.roles).length}`] = {
        control: g.controls[0].index,
        what: describeGroup(g),
        found: 'shading',
      };
    }
    const entry = {
      ...groupFacts(g, vs),
      role: r,
      levelSlider: k === 'levelSlider',
      target: vs[0],
      how,
      ...seen(),
      ...(base ? { before: session.keep(`slider-${facts.sliders.length}-before`, base) } : {}),
      image: session.keep(`slider-${facts.sliders.length}`, after),
    };
    facts.sliders.push(entry);
    // back to where it was; how far the picture is then from the one before the trial
    const back = await setGroup(session, g, (c) => session.now(c));
    start = await readState();
    // (a picture that moves by itself: what the page sends differently, its animation's keys left out)
    if (sentBefore && start.sent) entry.restored = { to: back[0], sent: sentChanges(sentBefore, start.sent, animated) };
    else if (!session.moving && base && start.img) {
      entry.restored = { to: back[0], changed: pictureChange(base, start.img, thresholds) };
    }
  }
}

/** s at its least (where that is 0 or below): one picture, in the judged view; then s back. */
export async function leastShininess(session, controls) {
  const c = freeControlNamed(session, controls, 's', (x) => x.type === 'range' || x.type === 'number');
  if (!c) return;
  const lo = c.min === '' || c.min === undefined || c.min === null ? 0 : Number(c.min); // a range's min defaults to 0
  if (!(lo <= 0)) return;
  await session.page.setValue(c, lo, ['input', 'change']);
  await session.tick(session.thresholds.actionTickMs);
  const after = await session.page.snap();
  await session.page.setValue(c, session.now(c), ['input', 'change']);
  await session.tick(session.thresholds.actionTickMs);
  if (after) session.facts.leastS = { value: lo, image: session.keep('least-s', after) };
}
