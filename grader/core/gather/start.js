// A page that draws nothing at first, with no shader or GPU error, but a control named for starting
// it (a "Start" or "Draw" button): a teacher clicks it, and the page is judged from what it draws
// then. Only controls named so are tried, each followed by the first frame's counted frames.
import { describe } from '../controls.js';
import { freeClickablesNamed } from './params.js';
import { drewAFrame } from './session.js';

/** Clicks the controls named for starting the page until it draws: the control's description, or null. */
export async function startToDraw(session) {
  const { thresholds } = session;
  session.step('starting the page with its own start control');
  const starts = freeClickablesNamed(session, await session.page.controls(), 'start');
  for (const c of starts.slice(0, thresholds.maxControlTrials)) {
    session.trialsMade++;
    if (!await session.press(c, 'a control named for starting the page, as it drew nothing,')) continue;
    for (let k = 0; k < thresholds.firstFrameTicks; k++) {
      await session.tick(thresholds.frameMs);
      if (drewAFrame(await session.settle())) {
        session.act('  → the page draws');
        return describe(c);
      }
    }
    session.act(`  → still no draw call after ${thresholds.firstFrameTicks} frames`);
  }
  return null;
}
