// Whether the light stays in the world while the camera orbits, read on the page's own surface in
// a lit view along the orbit and in the judged view (grader/core/computed/light-space.js,
// audits/units/orbit-light.js): surfaces and pictures made here of the exact sphere seen from two
// cameras on an orbit, lit by the slide's model with a light fixed in the world, or fixed in the
// eye's space (turning with the camera).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { lightSpaceOnSurface } from '../../grader/core/computed/light-space.js';
import { auditOrbit } from '../../grader/core/audits/units/orbit-light.js';
import { exactLighting } from '../../grader/core/computed/lighting.js';
import { analyse } from '../../grader/core/measure.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };

/** A camera on the orbit (radius 3.5 about y), `degrees` round: its eye, V and P·V. */
function cameraAt(degrees) {
  const a = (degrees * Math.PI) / 180, eye = [3.5 * Math.sin(a), 0.8, 3.5 * Math.cos(a)];
  const V = mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]);
  return { eye, V, pv: mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), V) };
}

/** The light in the model's space: fixed there (`world`), or the eye space's l taken back by Vᵀ. */
const lightOf = ({ V }, world) => {
  if (world) return unit([0.6, 0.5, 0.7]);
  const l = unit([0.5, 0.4, 0.8]);
  return [0, 1, 2].map((k) => V[4 * k] * l[0] + V[4 * k + 1] * l[1] + V[4 * k + 2] * l[2]);
};

/**
 * A lit view along the orbit (facts.views, with its surface) and the judged view `turn` degrees on
 * (facts.surface), with their pictures; `exact`, the judged view's fit as the surface-fit unit gives it.
 */
function views(world, turn) {
  const facts = { views: [] }, images = {};
  [20, 20 + turn].forEach((deg, i) => {
    const cam = cameraAt(deg), wi = lightOf(cam, world);
    const u = surfaceUnder(cam.pv, cam.eye, { shade: (p) => 0.1 + 0.8 * Math.max(dot(p, wi), 0) });
    for (let k = 3; k < u.picture.data.length; k += 4) if (!u.images.n.data[k]) u.picture.data.fill(0, k - 3, k);
    images[`view-${i}`] = u.picture;
    images[`n${i}`] = u.images.n;
    images[`p${i}`] = u.images.p;
    const surface = { ...u.facts, normals: `n${i}`, points: `p${i}` };
    if (i === 0) facts.views.push({ image: `view-${i}`, orbiting: true, surface });
    else Object.assign(facts, { surface, judged: `view-${i}` });
  });
  const judged = images[facts.judged];
  return { facts, images, thresholds: T, exact: exactLighting(facts, images, { img: judged, an: analyse(judged, T) }, T) };
}

/** What orbit-light says, with two lit views seen along the orbit (their pictures' fits are the fallback, not read here). */
const said = (context) => {
  const out = [];
  const lit = [0, 1].map(() => ({ orbiting: true, fit: { light: [0, 0, 1], r2: 1 } }));
  auditOrbit({ ...context, must: new Set(['diffuse']), numbers: {}, sayAs: (id) => (level, reason) => out.push(`${id} ${level}: ${reason}`) }, lit, context.exact);
  return out.join('\n');
};

test('a light in the world keeps its direction in the space of the normals; one in the eye\'s space turns with the camera', () => {
  const on = (x) => lightSpaceOnSurface(x, x.exact);
  const world = on(views(true, 40)), eye = on(views(false, 40));
  assert.ok(world.turn < 3, `world: ${JSON.stringify(world)}`);
  assert.ok(Math.abs(world.eyeTurn - 40) < 8 && world.fromEye > 30, `world: ${JSON.stringify(world)}`);
  assert.ok(eye.fromEye < 3 && eye.turn > 30, `eye: ${JSON.stringify(eye)}`);
  assert.ok(Math.abs(eye.cameraTurn - 40) < 3, `the camera turned ${eye.cameraTurn}`);
});

test('the orbit-light audit says so from the surfaces, and the camera turned too little where it did', () => {
  assert.match(said(views(true, 40)), /^orbit-light pass: the lit side turns as the camera orbits \(on the page's own surface in a lit view along the orbit and in the judged view.*\): the light stays in the world$/);
  assert.match(said(views(false, 40)), /^orbit-light pass: note: while the camera orbits, the lit side stays where it is on screen \(on the page's own surface.*the light moves with the camera/);
  assert.match(said(views(false, 4)), /^orbit-light pass: note: the camera turned too little between the lit views seen/);
  // the judged view's surface not read (a page that never stood still): the pictures judge it
  const moving = views(true, 40);
  assert.deepEqual(lightSpaceOnSurface(moving, { why: 'the view moved' }), { why: 'the view moved' });
  assert.equal(lightSpaceOnSurface({ ...moving, facts: { views: [] } }, moving.exact), null);
});
