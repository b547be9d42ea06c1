// The event a slider acted on: the one reading of it, which the gathering (whether to try the
// change event too), the sliders' audit and the roles' words all use.

/**
 * The event a slider (an entry of facts.sliders, or what the gathering has seen of it so far) acted
 * on: 'input', 'change' or 'none'. Where the picture moved by itself while it was tried, a changed
 * picture is no evidence: what the page sent differently on each event (s.sent: the keys it
 * changed) decides; elsewhere how much the picture changed on each event tried (s.changed),
 * against sliderChange (an artifact from before those were kept: the gathering's reading, s.how).
 * The change event was tried only where the input event showed nothing to the gathering's
 * sliderChange: under a rubric that asks more, it is not known (the part is named to gather again).
 */
export function sliderEvent(s, thresholds) {
  if (s.moving && s.sent) {
    if (s.sent.input.length > 0) return 'input';
    return s.sent.change && s.sent.change.length > 0 ? 'change' : 'none';
  }
  if (!s.changed) return s.how;
  if (s.changed.input > thresholds.sliderChange) return 'input';
  return s.changed.change !== null && s.changed.change > thresholds.sliderChange ? 'change' : 'none';
}
