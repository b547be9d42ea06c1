// The ambient term's own control (grader/core/audits/units/term-controls.js, measure/terms.js), on
// built pictures of the Phong model: which terms each slider trial moved is read from the dark side
// (the ambient term alone) and the lit side above it, and a page whose sliders move the ambient
// term only together with the diffuse one is a review; where the dark side is not in view, a note.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spherePicture } from './sphere-picture.js';
import { auditTermControls } from '../../grader/core/audits/units/term-controls.js';
import { termMoved } from '../../grader/core/measure/terms.js';
import { checkList } from '../../grader/core/verdict.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const { thresholds } = rubric;
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** The Phong model's picture (orthographic, w_o = +z) for the parameters `p`, the light toward `w_i`. */
function phong(p, w_i) {
  const colour = [0.9, 0.45, 0.25];
  return spherePicture((n) => {
    const c = dot(n, w_i), r = n.map((x, k) => 2 * c * x - w_i[k]);
    const spec = p.ks * p.Le * Math.max(r[2], 0) ** p.s;
    return colour.map((m) => p.ka * m * p.La + p.kd * m * p.Le * Math.max(c, 0) + spec);
  });
}

/**
 * The audit's reasons for a page whose sliders set the parameters they list (e.g. { kd: ['kd', 'ka'] }:
 * one slider for kd and ka together), each tried as the gathering tries it: to 0, and s far up.
 */
function judge(sliders, w_i = unit([0.8, 0.4, -0.1]), sTo = 200, base = { ka: 0.6, kd: 0.6, ks: 0.5, s: 30, Le: 0.7, La: 0.7 }) {
  const images = { before: phong(base, w_i) };
  const facts = { sliders: [], roles: {} };
  Object.entries(sliders).forEach(([role, params], i) => {
    const p = { ...base };
    for (const k of params) p[k] = k === 's' ? sTo : 0;
    images[`slider-${i}`] = phong(p, params.includes('light') ? unit([-0.8, 0.4, 0.2]) : w_i);
    facts.roles[role] = { control: i, what: `range "${role}"`, found: 'shading' };
    facts.sliders.push({ control: i, role, levelSlider: false, target: 0, how: 'input', changed: { input: 0.3, change: null }, before: 'before', image: `slider-${i}` });
  });
  const { checks, sayAs } = checkList(rubric);
  auditTermControls({ facts, images, thresholds, must: new Set(['sliders']), sayAs });
  return checks;
}

test('one slider for kd and ka and one for Le and La: the ambient term has no control of its own (review)', () => {
  const checks = judge({ kd: ['kd', 'ka'], ks: ['ks'], s: ['s'], Le: ['Le', 'La'] });
  assert.equal(checks.length, 1);
  assert.equal(checks[0].level, 'review');
  assert.match(checks[0].reason, /2 sliders each move the ambient and the diffuse term together \(kd: range "kd"; Le: range "Le"\)/);
  assert.match(checks[0].reason, /the ambient term has no control of its own/);
});

test('kd with ka (the slides\' k_a = k_d) and La a slider of its own, or ka its own and Le with La: the ambient term has its control', () => {
  for (const sliders of [
    { kd: ['kd', 'ka'], ks: ['ks'], s: ['s'], Le: ['Le'], La: ['La'] },
    { kd: ['kd'], ka: ['ka'], ks: ['ks'], s: ['s'], Le: ['Le', 'La'] },
  ]) {
    const checks = judge(sliders);
    assert.deepEqual(checks.map((c) => c.level), ['pass'], JSON.stringify(checks));
    assert.match(checks[0].reason, /the ambient term has a control of its own \((La|ka): range/);
  }
});

test('a light from the viewer leaves no dark side in view: a note that it cannot be seen, not a review', () => {
  const checks = judge({ kd: ['kd', 'ka'], ks: ['ks'], s: ['s'], Le: ['Le', 'La'] }, [0, 0, 1]);
  assert.deepEqual(checks.map((c) => c.level), ['pass']);
  assert.match(checks[0].reason, /^note: whether the ambient term has a control of its own cannot be seen/);
});

test('s at 0 (pow(x, 0) = 1: a flat specular term, as even as an ambient one) is not taken for the ambient term\'s own control', () => {
  const checks = judge({ kd: ['kd', 'ka'], ks: ['ks'], s: ['s'], Le: ['Le', 'La'] }, undefined, 0);
  assert.deepEqual(checks.map((c) => c.level), ['review']);
  assert.match(checks[0].reason, /the ambient term has no control of its own/);
});

test('a slider that turns the light lights the dark side unevenly: not read as moving the ambient term', () => {
  // no slider for the ambient term (La 0.3 fixed), one for the light's direction: nothing to review
  const base = { ka: 0.6, kd: 0.6, ks: 0.5, s: 30, Le: 0.7, La: 0.3 };
  const checks = judge({ kd: ['kd'], ks: ['ks'], s: ['s'], Le: ['Le'], dir: ['light'] }, undefined, 200, base);
  assert.deepEqual(checks.map((c) => c.level), ['pass']);
  assert.match(checks[0].reason, /^note: whether the ambient term has a control of its own cannot be seen: 1 slider trial/);
});

test('a term fainter than termChange in both pictures is not seen (null), not unmoved', () => {
  assert.equal(termMoved(0.02, 0.004, thresholds), null);
  assert.equal(termMoved(0.2, 0.19, thresholds), false);
  assert.equal(termMoved(0.2, 0, thresholds), true);
  assert.equal(termMoved(null, 0.2, thresholds), null);
});
