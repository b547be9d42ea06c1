// P5's canvas among several of one size (grader/core/gather/step-canvas.js): the one named for
// per-fragment shading, else the one not named for Gouraud shading beside one that is; where the
// names do not tell, the first (the largest, the first of equals), as a page of one canvas is read.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { chooseStepCanvas } from '../../grader/core/gather/step-canvas.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));

/** What the gathering chose on a page with `canvases` ([width, labels] each, all shown), for a step that asks `must`. */
async function choose(canvases, must = ['per-fragment']) {
  let chosen = null;
  const acts = [];
  const session = {
    must: new Set(must), patterns: rubric.controls, facts: {}, act: (a) => acts.push(a),
    page: {
      canvases: async () => canvases.map(([width, labels], index) => ({ index, width, height: width, shown: true, labels })),
      chooseCanvas: async (i) => { chosen = i; return true; },
    },
  };
  await chooseStepCanvas(session);
  return { chosen, canvases: session.facts.canvases, acts };
}

test('captions "Gouraud shading" and "Phong shading": the Phong canvas is judged, with why', async () => {
  const r = await choose([[320, ['left', 'Gouraud shading (per vertex)']], [320, ['right', 'Phong shading (per fragment)']]]);
  assert.equal(r.chosen, 1);
  assert.deepEqual(r.canvases, { largest: 2, judged: 'canvas 2 ("right", "Phong shading (per fragment)")', why: 'named for per-fragment shading' });
});

test('ids "gouraud" and "phong" ("Phong" alone names the reflection model, not the shading): the one beside the Gouraud canvas', async () => {
  const r = await choose([[300, ['gouraud']], [300, ['phong']]]);
  assert.equal(r.chosen, 1);
  assert.match(r.canvases.why, /^the one not named for per-vertex shading, beside canvas 1 \("gouraud"\)$/);
});

test('names that do not tell, a smaller canvas, one canvas, or another step: the first of the largest, as before', async () => {
  const untold = await choose([[300, ['a']], [300, ['b']]]);
  assert.equal(untold.chosen, null);
  assert.match(untold.canvases.why, /^the first: their names do not say/);
  const both = await choose([[300, ['Gouraud']], [300, ['Gouraud shading, then Phong shading']]]);
  assert.equal(both.chosen, null);
  assert.deepEqual((await choose([[100, ['Phong shading']], [300, ['gouraud']]])), { chosen: null, canvases: undefined, acts: [] });
  assert.deepEqual((await choose([[300, ['gouraud']], [300, ['Phong shading']]], ['highlight'])), { chosen: null, canvases: undefined, acts: [] });
});
