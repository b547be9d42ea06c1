// The controls the gathering gave a role, in words: what each is, what it listens to, and what
// showed its role (facts.roles holds the control, its description and a word for what was seen;
// the sentences are written here, for the audits' reasons and the report's "controls found").
import { sliderEvent } from './slider-event.js';

/** What showed a control's role, in words (`r`: its entry of facts.roles; `event`: a slider's, sliderEvent). */
const FOUND = {
  rounder: () => 'the silhouette got rounder',
  coarser: () => 'the silhouette got coarser',
  'rounder-up': () => 'the silhouette got rounder as it went up',
  'by-name': () => 'by its name (the picture kept moving)',
  'more-drawn': () => 'the page drew more triangles after each click (the picture kept moving)',
  'less-drawn': () => 'the page drew fewer triangles after each click (the picture kept moving)',
  stopped: () => 'the picture stopped moving',
  'starts-stops': () => 'starts and stops the picture moving',
  'starts-other-stops': (r) => `starts the picture moving (${r.stopper} stops it)`,
  starts: () => 'starts the picture moving; nothing found stops it',
  shading: (r, event) => (event === 'none' ? 'the picture changed less than this rubric\'s sliderChange asks' : `changes the shading on ${event}`),
};

/** One role in words: "button "Subdivide #up" (listens: click): the silhouette got rounder", "the ArrowUp key: …". */
function roleWords(r, facts, thresholds) {
  if (r.words) return r.words; // (a role kept as a sentence only: core/artifact-schema.js)
  const slider = r.found === 'shading' ? (facts.sliders || []).find((s) => s.control === r.control) : null;
  const found = FOUND[r.found](r, slider ? sliderEvent(slider, thresholds) : null);
  if (r.key) return `the ${r.key} key: ${found}`;
  const listens = r.listens && r.listens.length ? ` (listens: ${r.listens.join(', ')})` : '';
  return `${r.what}${listens}: ${found}`;
}

/** facts.roles in words: { role: sentence }, in the order the roles were given. */
export function rolesInWords(facts, thresholds) {
  return Object.fromEntries(
    Object.entries(facts.roles || {}).map(([role, r]) => [role, roleWords(r, facts, thresholds)]),
  );
}
