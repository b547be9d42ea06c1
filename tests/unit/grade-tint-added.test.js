// A normal colouring added to the lighting (0.5·p + 0.5·L_o) is read as lighting
// with WP04P1's colours mixed in, not as WP04P1's colours, and its light is fitted with them taken
// out; the P1 colour alone, the P1 colour as the material and a plain material are not read so.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { analyse, samples, normalColours, addedTintFit, addedClearly, shadeFit } from '../../grader/core/measure.js';
import { auditNormalsNotLight } from '../../grader/core/audits/units/normals-not-light.js';
import { spherePicture } from './sphere-picture.js';

const thresholds = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const norm = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const degrees = (a, b) => (180 / Math.PI) * Math.acos(Math.min(1, dot(a, b)));

const sphere = spherePicture;
const light = norm([0.4, 0.2, 1]);
const phong = (n, kd = 0.8) => {
  const d = dot(n, light), wr = n.map((v, k) => 2 * d * v - light[k]);
  return kd * 0.2 + kd * Math.max(d, 0) + 0.7 * Math.pow(Math.max(wr[2], 0), 25);
};
// the model's normal seen by a camera orbited 0.6 rad about y: the page colours by the model's
const model = (n) => [Math.cos(0.6) * n[0] + Math.sin(0.6) * n[2], n[1], -Math.sin(0.6) * n[0] + Math.cos(0.6) * n[2]];
const judged = (img) => { const an = analyse(img, thresholds); return { img, an, pts: samples(img, an, thresholds) }; };

const added = judged(sphere((n) => model(n).map((p) => 0.5 * p + 0.5 * phong(n))));
const p1 = judged(sphere((n) => model(n).map((p) => 0.5 * p + 0.5)));
const material = judged(sphere((n) => model(n).map((p) => (0.5 * p + 0.5) * phong(n))));
const plain = judged(sphere((n) => [0.9, 0.5, 0.3].map((c) => c * phong(n, 1))));

test('0.5·p + 0.5·L_o: the added share, the camera\'s turn and the light, fitted with the colouring taken out', () => {
  const fit = addedTintFit(added.pts, thresholds);
  assert.ok(addedClearly(fit, thresholds), JSON.stringify(fit.added));
  assert.ok(Math.abs(fit.added.share - 0.5) < 0.05, `share ${fit.added.share}`);
  assert.ok(Math.abs(fit.added.turn - (180 / Math.PI) * 0.6) < 5, `turn ${fit.added.turn}`);
  assert.ok(degrees(fit.light, light) < 5, `light ${fit.light}`);
  const shade = shadeFit(added.pts, thresholds);
  assert.ok(shade.tint && Math.abs(shade.tint.added - fit.added.share) < 1e-9 && shade.tint.sure);
  assert.ok(degrees(shade.light, light) < 5, `shadeFit's light ${shade.light}`);
});

test('the P1 colour alone, as the material, and a plain material are not a colouring added to the lighting', () => {
  for (const [name, j] of [['the P1 colour', p1], ['the P1 colour as the material', material], ['a plain material', plain]]) {
    assert.ok(!addedClearly(addedTintFit(j.pts, thresholds), thresholds), name);
  }
});

test('auditNormalsNotLight: WP04P1\'s colours alone are no lighting; with the lighting added they are judged as lighting', () => {
  const run = (j) => {
    const said = [];
    const C = { thresholds, must: new Set(['diffuse']), numbers: {}, sayAs: () => (level, reason) => said.push({ level, reason }) };
    return { notLight: auditNormalsNotLight(C, j), said };
  };
  const a = run(p1);
  assert.ok(a.notLight && a.said.some((s) => /normal colouring of WP04P1, not the lighting/.test(s.reason)));
  // lit brightly enough (kd 1, ambient 0.2, the light near the viewer) that 2c − 1 is near a unit vector all over
  const bright = judged(sphere((n) => n.map((p) => 0.5 * p + 0.5 * (0.2 + Math.max(dot(n, light), 0)))));
  assert.ok(normalColours(bright.pts, thresholds).unitError <= thresholds.normalsUnitError, 'the colours decode to unit normals');
  const b = run(bright);
  assert.equal(b.notLight, false, b.said.map((s) => s.reason).join(' | '));
});
