// Each term of the Phong model its own control (grader/core/audits/units/term-controls.js,
// computed/trial-reading.js, measure/surface-terms.js), on pictures made here of the slides' model
// on the exact sphere with its surface: each slider trial is read on the page's own surface (the
// ambient, diffuse and specular term and the shininess fitted before and after on the same pixels),
// and sliders that move a term only together with another are a review naming them.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { auditTermControls, auditOwnControls, readTrials } from '../../grader/core/audits/units/term-controls.js';
import { exactLighting } from '../../grader/core/computed/lighting.js';
import { analyse } from '../../grader/core/measure.js';
import { checkList } from '../../grader/core/verdict.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const T = rubric.thresholds;
const eye = [0, 0, 3.5];
const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const w_i = unit([0.6, 0.5, 0.6]);
const BASE = { ka: 0.3, kd: 0.6, ks: 0.4, s: 20, Le: 0.8, La: 0.6 };

/** The slides' model: L_o = k_a L_a + k_d L_e max(n · w_i, 0) + k_s L_e max(w_r · w_o, 0)^s, w_o = normalize(e − p). */
function phong(p) {
  const colour = [0.9, 0.5, 0.3];
  return (q, k) => {
    const n = q, c = dot(n, w_i), w_r = n.map((x, j) => 2 * c * x - w_i[j]), w_o = unit(eye.map((e, j) => e - q[j]));
    const spec = c > 0 ? p.ks * p.Le * Math.max(dot(w_r, w_o), 0) ** p.s : 0;
    return colour[k] * (p.ka * p.La + p.kd * p.Le * Math.max(c, 0)) + spec;
  };
}

/** A picture of parameters `p`, on black outside the sphere. */
function picture(p) {
  const u = surfaceUnder(pv, eye, { shade: phong(p) });
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  return u;
}

/**
 * What the two audits say of a page whose sliders set the parameters they list (e.g. { kd: ['kd',
 * 'ks'] }: one slider named kd sets kd and ks), each tried as the gathering tries it: to 0, s far up.
 * `moving`: the trials' pictures move by themselves (read on the pictures alone).
 */
function judge(sliders, { moving = false } = {}) {
  const base = picture(BASE);
  const images = { ...base.images, before: base.picture };
  const facts = { sliders: [], roles: {}, surface: base.facts };
  Object.entries(sliders).forEach(([role, params], i) => {
    const p = { ...BASE };
    for (const k of params) p[k] = k === 's' ? 200 : 0;
    images[`slider-${i}`] = picture(p).picture;
    facts.roles[role] = { control: i, what: `range "${role}"`, found: 'shading' };
    facts.sliders.push({ control: i, role: role.replace(/[0-9]/g, ''), levelSlider: false, target: 0, how: 'input', changed: { input: 0.3, change: null },
      before: 'before', image: `slider-${i}`, ...(moving ? { moving: true, sent: { input: ['u'], change: null } } : {}) });
  });
  const exact = exactLighting(facts, images, { img: base.picture, an: analyse(base.picture, T) }, T);
  const { checks, sayAs } = checkList(rubric);
  const context = { facts, images, thresholds: T, must: new Set(['sliders']), sayAs };
  const read = readTrials(context, exact);
  auditTermControls(context, read);
  auditOwnControls(context, read);
  return { checks, read, exact };
}

const said = (checks, id) => checks.filter((c) => c.id === id).map((c) => `${c.level}: ${c.reason}`).join('\n');

test('a slider for each parameter: each trial read on the surface, each term its own control', () => {
  const { checks, read, exact } = judge({ kd: ['kd'], ks: ['ks'], s: ['s'], Le: ['Le'], La: ['La'] });
  assert.ok(exact && !exact.why && exact.best.rms <= T.surfaceResidual, JSON.stringify(exact && exact.best));
  const moved = Object.fromEntries(read.map(({ s, r }) => [s.role, ['ambient', 'diffuse', 'specular', 'shininess'].filter((k) => r[k]).join(' ')]));
  assert.deepEqual(moved, { kd: 'diffuse', ks: 'specular', s: 'shininess', Le: 'diffuse specular', La: 'ambient' });
  assert.ok(read.every(({ r }) => r.on === 'surface'));
  assert.deepEqual(checks.map((c) => c.level), ['pass', 'pass'], JSON.stringify(checks));
  assert.match(said(checks, 'term-controls'), /the ambient term has a control of its own \(La: range "La": read on the page's own surface/);
  assert.match(said(checks, 'own-controls'), /^pass: the diffuse term, the specular term and the shininess each have a control of their own \(kd: range "kd": the diffuse term moved, the specular term did not, on the page's own surface; ks: .*; s: range "s": the shininess moved/);
});

test('one slider for kd and ks together and one for Le: neither the diffuse nor the specular term has a control of its own (review)', () => {
  const { checks } = judge({ kd: ['kd', 'ks'], s: ['s'], Le: ['Le'], La: ['La'] });
  const own = checks.filter((c) => c.id === 'own-controls');
  assert.deepEqual(own.map((c) => c.level), ['review', 'review', 'pass'], JSON.stringify(own));
  assert.match(own[0].reason, /^2 sliders each move the diffuse term only together with the specular term \(kd: range "kd"; Le: range "Le"\) and no slider moves it apart: the diffuse term has no control of its own \(kd\)/);
  assert.match(own[1].reason, /the specular term has no control of its own \(ks\)/);
  assert.match(own[2].reason, /^the shininess has a control of its own/);
});

test('no ks slider, Le for the highlight: the specular term has no control of its own; kd still has its own', () => {
  const { checks } = judge({ kd: ['kd'], s: ['s'], Le: ['Le'], La: ['La'] });
  const own = said(checks, 'own-controls');
  assert.match(own, /review: one slider moves the specular term only together with the diffuse term \(Le: range "Le"\) and no slider moves it apart: the specular term has no control of its own \(ks\)/);
  assert.match(own, /pass: the diffuse term and the shininess each have a control of their own/);
});

test('kd with ka and Le with La, read on the surface: the ambient term has no control of its own (review)', () => {
  const { checks } = judge({ kd: ['kd', 'ka'], ks: ['ks'], s: ['s'], Le: ['Le', 'La'] });
  assert.match(said(checks, 'term-controls'), /^review: 2 sliders each move the ambient and the diffuse term together \(kd: range "kd"; Le: range "Le"\)/);
  assert.match(said(checks, 'own-controls'), /^pass: the diffuse term, the specular term and the shininess each have a control/);
});

test('a picture that moves by itself is read on the pictures alone: the names break the tie, and the note says why', () => {
  const { checks, read } = judge({ kd: ['kd', 'ks'], ks2: ['ks'], s: ['s'], Le: ['Le'], La: ['La'] }, { moving: true });
  assert.ok(read.every(({ r }) => r.on === 'picture' && /moves by itself/.test(r.why)));
  const own = said(checks, 'own-controls');
  assert.doesNotMatch(own, /review/);
  assert.match(own, /the picture moves by itself while a slider is tried/);
});

test('ks used in the specular term, judged on the surface: a ks slider wired to the ambient term leaves the specular term as it was (review)', async () => {
  const { auditSliders } = await import('../../grader/core/audits/units/sliders.js');
  const ksUsed = (params) => {
    const base = picture(BASE), p = { ...BASE };
    for (const k of params) p[k] = 0;
    const images = { ...base.images, before: base.picture, after: picture(p).picture };
    const facts = { sliders: [{ control: 0, role: 'ks', levelSlider: false, target: 0, how: 'input', changed: { input: 0.2, change: null }, before: 'before', image: 'after' }], slidersFound: 1, surface: base.facts };
    const exact = exactLighting(facts, images, { img: base.picture, an: analyse(base.picture, T) }, T);
    const { checks, sayAs } = checkList(rubric);
    auditSliders({ facts, images, thresholds: T, must: new Set(['sliders']), sayAs, rubric, part: 'WP04P4' }, null, {}, exact);
    return checks.filter((c) => c.id === 'ks-used');
  };
  const wired = ksUsed(['ka']);
  assert.deepEqual(wired.map((c) => c.level), ['review']);
  assert.match(wired[0].reason, /^ks at 0 leaves the specular term as it was on the page's own surface \(k_s L_e [0-9., ]+ before, [0-9., ]+ after\): is ks used in the specular term\?/);
  assert.deepEqual(ksUsed(['ks']), []);
});

test('the shininess set only with kd (one slider for both): the shininess has no control of its own (review); ks taking the highlight away leaves nothing unread', () => {
  const { checks, read } = judge({ kd: ['kd'], ks: ['ks'], s: ['s', 'kd'], Le: ['Le'], La: ['La'] });
  const s = read.find(({ s: t }) => t.role === 's').r;
  assert.equal(s.shininess, true);
  assert.equal(s.diffuse, true);
  assert.match(said(checks, 'own-controls'), /review: one slider moves the shininess only together with the diffuse or the ambient term \(s: range "s"\) and no slider moves it apart: the shininess has no control of its own \(s\)/);
});
