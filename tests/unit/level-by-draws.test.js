// A page whose picture never stands still (an orbit with no toggle) shows its level controls in
// what it draws: a click that makes each frame draw four times the vertices subdivides, one that
// makes it draw a quarter coarsens, whatever the buttons are called (gather/level.js). The page
// here is a stand-in for the page interface: its frames draw 12·4^level vertices.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openSession } from '../../grader/core/gather/session.js';
import { findLevel } from '../../grader/core/gather/level.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const button = (index, id, text) => ({ index, type: 'button', id, name: '', text, value: '', disabled: false, events: ['click'], visible: true });

/** A page at `level` whose buttons (by id) change it as `clicks` says, and whose every frame draws 12·4^level vertices in one call. */
function standIn(clicks, { grows = 0 } = {}) {
  const page = { level: 0, vertices: 0, draws: 0, frames: 0 };
  return Object.assign(page, {
    async click(c) {
      page.level = clicks[c.id](page.level);
      return { ok: true };
    },
    async tick(ms, frames = 0) {
      for (let k = 0; k <= frames; k++) {
        page.frames++;
        page.vertices += 12 * 4 ** page.level + grows * page.frames;
        page.draws++;
      }
      return { vertices: page.vertices, draws: page.draws };
    },
  });
}

async function levelOf(page, controls) {
  const session = openSession(page, { part: 'WP04P2', rubric });
  session.moving = true;
  session.cur = {};
  await session.tick(16, 2);
  await findLevel(session, controls);
  return session;
}

test('while the picture moves, the buttons that change how much is drawn are the level controls, named as they are', async () => {
  const controls = [button(0, 'spin', 'Colours'), button(1, 'split', 'Split triangles'), button(2, 'merge', 'Merge triangles')];
  const page = standIn({ spin: (l) => l, split: (l) => Math.min(l + 1, 6), merge: (l) => Math.max(l - 1, 0) });
  const session = await levelOf(page, controls);
  assert.deepEqual(session.facts.level, { subdivide: true, coarsen: true, slider: false, stopped: false, trials: 0, valued: 0 });
  assert.equal(session.facts.roles.subdivide.found, 'more-drawn');
  assert.equal(session.facts.roles.subdivide.control, 1);
  assert.equal(session.facts.roles.coarsen.control, 2);
  assert.ok(session.facts.actions.includes('  → the page draws 12 → 48 vertices a frame (finer)'), session.facts.actions.join('\n'));
});

test('a mesh that grows a little every frame does not make every button a level control', async () => {
  const controls = [button(0, 'colours', 'Colours'), button(1, 'split', 'Split triangles')];
  const page = standIn({ colours: (l) => l, split: (l) => l + 1 }, { grows: 1 });
  const session = await levelOf(page, controls);
  assert.equal(session.facts.roles.subdivide.control, 1);
  assert.equal(session.facts.level.coarsen, false);
});

test('buttons that change nothing drawn are taken by their names only', async () => {
  const controls = [button(0, 'up', 'Subdivide'), button(1, 'down', 'Coarsen')];
  const page = standIn({ up: (l) => l, down: (l) => l });
  const session = await levelOf(page, controls);
  assert.equal(session.facts.roles.subdivide.found, 'by-name');
  assert.equal(session.facts.roles.coarsen.found, 'by-name');
});
