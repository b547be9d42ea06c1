// The camera as the page sent it (grader/core/computed/camera.js): the view matrix among the animated ones,
// and how far it turned; and the orbit's audit weighing the lit side's turn against it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { cameraOf, cameraTurn, cameraPath } from '../../grader/core/computed/camera.js';
import { auditOrbit } from '../../grader/core/audits/units/orbit-light.js';
import { checkList } from '../../grader/core/verdict.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const thresholds = rubric.thresholds;
const DEG = Math.PI / 180;
const view = (alpha, scale = 1) => {
  const m = mat4.lookAt(mat4.create(), [3 * Math.sin(alpha * DEG), 0.5, 3 * Math.cos(alpha * DEG)], [0, 0, 0], [0, 1, 0]);
  return mat4.scale(m, m, [scale, scale, scale]);
};
const sent = (m, more = {}) => ({ 'uniform V': Array.from(m).join(','), 'uniform kd': '0.8', ...more });

test('the view matrix: read from the animated uniforms, its turn between views', () => {
  const animated = ['uniform V'];
  const cams = [0, 10, 35].map((a) => cameraOf(sent(view(a, 2)), animated));
  assert.deepEqual(Object.keys(cams[0]), ['uniform V']);
  assert.ok(Math.abs(cameraTurn(cams, thresholds.cameraRotationTolerance) - 35) < 1e-3);
  assert.equal(cameraOf(sent(view(0)), []), null);
  assert.equal(cameraTurn([cams[0]], thresholds.cameraRotationTolerance), null, 'one view: no turn');
  // P·V sent as one matrix is no rotation: not read
  const pv = (a) => mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), 45 * DEG, 1, 0.1, 10), view(a));
  assert.equal(cameraTurn([0, 30].map((a) => cameraOf(sent(pv(a)), animated)), thresholds.cameraRotationTolerance), null);
});

test('the camera\'s path: the turns from view to view added up, never more than it went (a full turn is at least once round)', () => {
  const animated = ['uniform V'], tol = thresholds.cameraRotationTolerance;
  const path = (angles) => cameraPath(angles.map((a) => cameraOf(sent(view(a)), animated)), tol);
  // five views 137° apart (fagnig's orbit sampled: 0.05 rad a frame, 48 frames): 548° round
  assert.ok(Math.abs(path([0, 137, 274, 411, 548]) - 548) < 1e-3);
  // the largest turn from the first is no path: it stays under a half turn
  assert.ok(cameraTurn([0, 137, 274, 411, 548].map((a) => cameraOf(sent(view(a)), animated)), tol) <= 180);
  // a step past a half turn reads as the shorter way back: the path is shorter, never longer, than the camera's
  assert.ok(Math.abs(path([0, 270]) - 90) < 1e-3);
  assert.equal(path([0]), null, 'one view: no path');
  assert.equal(cameraPath([cameraOf(sent(view(0)), animated), null], tol), null, 'a view with no camera: unknown');
});

test('the orbit\'s audit: the lit side\'s turn against the camera\'s', () => {
  // (a camera that goes round to +α sees a light fixed in the world turn the other way: -α about y)
  const judge = (lightTurn, cameraDegrees, up = 0) => {
    const { checks, sayAs } = checkList(rubric);
    const lit = [0, 1].map((k) => ({ orbiting: true, fit: { light: [-Math.sin(k * lightTurn * DEG) * Math.cos(up * DEG), Math.sin(up * DEG), Math.cos(k * lightTurn * DEG) * Math.cos(up * DEG)] },
      camera: cameraDegrees === null ? undefined : cameraOf(sent(view(k * cameraDegrees)), ['uniform V']) }));
    auditOrbit({ facts: { orbit: {} }, thresholds, must: new Set(['diffuse']), sayAs, numbers: {} }, lit);
    return checks.map((c) => `${c.level}: ${c.reason}`).join('\n');
  };
  assert.match(judge(40, 40), /^pass: the lit side turns as the camera orbits \(the fitted light turns 40\.0° over 2 views, where a light in the world would have turned 39\.\d° on screen \(the camera turns 40\.0°/);
  assert.match(judge(5, 40), /^pass: note: while the camera orbits, the lit side stays where it is on screen/, 'an eye-space light whose fit wanders 5°');
  assert.match(judge(5, 7), /^pass: note: the camera turned too little between the lit views seen/);
  // a light from straight above: the camera's turn about y leaves it where it is, whatever its space
  assert.match(judge(0, 40, 89.9), /^pass: note: the camera turned too little .* a light in the world would have turned 6\.4° on screen/);
  // a fit that turns clearly where the camera cannot tell (a near point light above, fitted as a direction): no light that moves with the camera
  const wanders = (() => {
    const { checks, sayAs } = checkList(rubric);
    const lit = [[0, 0.996, 0.087], [0, 0.985, -0.174]].map((light, k) => ({ orbiting: true, fit: { light }, camera: cameraOf(sent(view(40 * k)), ['uniform V']) }));
    auditOrbit({ facts: { orbit: {} }, thresholds, must: new Set(['diffuse']), sayAs, numbers: {} }, lit);
    return checks.map((c) => `${c.level}: ${c.reason}`).join('\n');
  })();
  assert.match(wanders, /^pass: the lit side turns as the camera orbits \(the fitted light turns 15\.\d°/);
  assert.match(judge(5, null), /^pass: the lit side turns as the camera orbits \(5°/, 'no view matrix read: the turn alone, as before');
});
