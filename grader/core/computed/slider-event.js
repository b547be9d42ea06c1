// The event a slider acted on, as the sliders' audit and the roles' words read it.
import { sliderActed } from '../controls.js';

/**
 * The event a slider (an entry of facts.sliders) acted on: 'input', 'change' or 'none'. Where the
 * picture moved by itself while it was tried, what the page sent differently on each event
 * (s.sent) decides; elsewhere how much the picture changed on each event tried (s.changed),
 * against sliderChange (an artifact from before those were kept: the gathering's reading, s.how).
 * The change event was tried only where the input event showed nothing to the gathering's
 * sliderChange: under a rubric that asks more, it is not known (the part is named to gather again).
 */
export function sliderEvent(s, T) {
  if (s.moving && s.sent) {
    if (sliderActed({ moving: true, sent: s.sent.input })) return 'input';
    return s.sent.change && sliderActed({ moving: true, sent: s.sent.change }) ? 'change' : 'none';
  }
  if (!s.changed) return s.how;
  if (s.changed.input > T.sliderChange) return 'input';
  return s.changed.change !== null && s.changed.change > T.sliderChange ? 'change' : 'none';
}
