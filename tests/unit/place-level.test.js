// The highlight's place is read at the judged level (grader/core/computed/evidence.js): a lit view
// along the orbit taken at a coarser level (its frame drew levelWorkRatio times fewer vertices than
// the judged level's, the page's draws) shows that there is a highlight, but is no view to place
// it in: the gatherer looks along the orbit at the judged level instead (farther).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { coarserView, highlightEvidence } from '../../grader/core/computed/evidence.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const facts = { judgedVertices: 12288 };

/** A lit view's fit: a highlight (peak 0.9) over a clean diffuse fit, the light `degrees` from the viewer. */
const lit = (degrees) => {
  const a = (degrees * Math.PI) / 180;
  return { r2: 0.98, highlightPeak: 0.9, highlightRise: 0.3, highlightShare: 0.01, rms: 0.01, light: [Math.sin(a), 0, Math.cos(a)] };
};
const dull = { r2: 0.98, highlightPeak: 0, highlightRise: 0, highlightShare: 0, rms: 0.01, light: [0, 0, 1] };
const shading = { judgedFit: dull, nearModel: null, img: null };

test('a view is coarser where the judged level draws levelWorkRatio times its vertices or more', () => {
  assert.deepEqual(coarserView({ vertices: 768 }, facts, T), { vertices: 768, judged: 12288 });
  assert.equal(coarserView({ vertices: 12288 }, facts, T), null);
  assert.equal(coarserView({ vertices: 6000 }, facts, T), null, 'within a level');
  // an artifact recorded before the views kept their vertices is read as before
  assert.equal(coarserView({}, facts, T), null);
  assert.equal(coarserView({ vertices: 768 }, {}, T), null);
});

test('a highlight seen only at a coarser level is not placed there: it is looked for farther along the orbit', () => {
  const coarse = { fit: lit(70), coarser: coarserView({ vertices: 768 }, facts, T) };
  const e = highlightEvidence(shading, [coarse], null, {}, T);
  assert.ok(e.seen, 'the highlight is seen');
  assert.equal(e.place, null);
  assert.equal(e.coarse, true);
  assert.equal(e.farther, true);
});

test('a view at the judged level is the place, before a coarser one farther from the light', () => {
  const coarse = { fit: lit(100), coarser: coarserView({ vertices: 768 }, facts, T) };
  const judged = { fit: lit(70), coarser: null };
  const e = highlightEvidence(shading, [coarse, judged], null, {}, T);
  assert.equal(e.place.fit, judged.fit);
  assert.equal(e.coarse, false);
  assert.equal(e.farther, false, 'the light 70° from the viewer tells w_h from w_i');
  // as before where no view is coarser: the one with the light farthest from the viewer
  const both = highlightEvidence(shading, [{ ...coarse, coarser: null }, judged], null, {}, T);
  assert.equal(both.place.fit, coarse.fit);
});
