// P5 (Phong shading, per fragment): a page that offers its shading as a choice (a checkbox named for
// per-fragment shading, or radio buttons for Gouraud and Phong shading) and starts per vertex is set
// as the step asks before anything is looked at, as a teacher sets up the step; facts.perFragmentSet
// names the control.
import { namedOnly, describe } from '../controls.js';

/** Ticks the page's own per-fragment shading control where the step asks for it and the page starts without it. */
export async function setStepShading(session, controls) {
  if (!session.must.has('per-fragment')) return;
  const c = shadingChoice(controls, session);
  if (!c) return;
  session.step('setting the page\'s own shading control as the step asks');
  if (!await session.press(c, 'the per-fragment shading control')) return;
  session.taken.add(c.index);
  const shot = await session.shot();
  if (shot && !shot.an.blank) session.cur = shot;
  session.facts.perFragmentSet = describe(c);
}

/**
 * The unticked control that sets per-fragment shading, or null: a checkbox named for it (and not
 * for per-vertex shading), or the radio button named for it in a group whose ticked member is
 * named for per-vertex (Gouraud) shading. Words beside a control name it too, so a control named
 * for both is neither.
 */
function shadingChoice(controls, session) {
  const only = (x, role, other) => namedOnly(x, role, other, session.patterns);
  const free = (x) => !x.checked && !x.disabled && !session.taken.has(x.index);
  const box = controls.find((x) => x.type === 'checkbox' && free(x) && only(x, 'perFragment', 'perVertex'));
  if (box) return box;
  return controls.find((x) => x.type === 'radio' && free(x) && only(x, 'perFragment', 'perVertex') &&
    controls.some((y) => y.type === 'radio' && y.name === x.name && y.checked && only(y, 'perVertex', 'perFragment'))) || null;
}
