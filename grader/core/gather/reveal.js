// P4: a page whose sliders are hidden until a button shows them ("Show settings", "Controls"):
// where no slider is visible, the clickable controls named for showing the page's settings are
// clicked in turn, as a teacher who looks for the sliders would, until sliders show;
// facts.slidersShownBy names the control, and the controls that appeared join facts.controls.
import { describe } from '../controls.js';
import { groupsOf, freeClickablesNamed } from './params.js';

/** The page's controls with its sliders shown, where a control named for showing them does it. */
export async function revealSliders(session, controls) {
  if (groupsOf(session, controls).length) return controls;
  const shows = freeClickablesNamed(session, controls, 'reveal').filter((c) => c.type !== 'checkbox');
  if (!shows.length) return controls;
  session.step('showing the page\'s hidden sliders');
  const known = new Set(controls.map((x) => x.index));
  for (const c of shows.slice(0, session.thresholds.maxControlTrials)) {
    if (!await session.press(c, 'a control named for showing the settings, as no slider shows,')) continue;
    const now = await session.page.controls();
    if (groupsOf(session, now).length) {
      session.taken.add(c.index);
      session.facts.controls.push(...now.filter((x) => !known.has(x.index)));
      session.facts.slidersShownBy = describe(c);
      session.act('  → sliders show');
      return now;
    }
    session.act('  → no slider shows');
  }
  return controls;
}
