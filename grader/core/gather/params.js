// The page's own parameter controls, as the gatherers set them: a slider's least and greatest values,
// the parameters its free sliders set (ks r, g, b as one group), a group set and described in facts,
// and a free control found by its name. Shared by faces.js, highlight.js, sliders.js and visible.js.
import { nameRole, parameterGroups, named, isClickable, trialOrder } from '../controls.js';

const role = (session, c) => nameRole(c, session.patterns);

/** The first of `controls` not yet given a role whose name says `r` (and `pred` holds). */
export const freeControlNamed = (session, controls, r, pred = () => true) =>
  controls.find((x) => !session.taken.has(x.index) && pred(x) && role(session, x) === r);

/** The clickable controls (buttons, links, checkboxes) not yet given a role whose name says `r`, in trial order. */
export const freeClickablesNamed = (session, controls, r) => {
  const { patterns, taken } = session;
  return trialOrder(controls.filter(isClickable), r, patterns, taken).filter((c) => named(c, r, patterns));
};

/** An <input type=range> without min or max runs from 0 to 100: HTML's defaults. */
export const RANGE_DEFAULT_MAX = 100;

/** A slider's least and greatest values (a colour picker's: black and white). */
export const leastValue = (c) => (c.type === 'color' ? '#000000' : Number(c.min || 0));
export const greatestValue = (c) =>
  c.type === 'color'
    ? '#ffffff'
    : Number(c.max === '' || c.max === undefined ? (c.type === 'range' ? RANGE_DEFAULT_MAX : 1) : c.max);

/** The parameters the page's free sliders set (parameterGroups: ks r, g, b as one). */
export const groupsOf = (session, controls) =>
  parameterGroups(
    controls.filter((c) => !session.taken.has(c.index)),
    session.patterns,
  );

/** Sets every slider of a parameter group (`value(c)` each), on `events`; returns the values set. */
export async function setGroup(session, g, value, events = ['input', 'change']) {
  const vs = g.controls.map(value);
  for (let k = 0; k < vs.length; k++) await session.page.setValue(g.controls[k], vs[k], events);
  return vs;
}

/** A group's entry in facts: its first control, and the others (and their values) where it has more. */
export const groupFacts = (g, vs) => ({
  control: g.controls[0].index,
  ...(g.controls.length > 1 ? { controls: g.controls.map((c) => c.index), values: vs, channels: g.channels } : {}),
});
