// Gathering rules without a browser: the sliders of one parameter (ks r, g, b; a colour
// picker) found as one; a picture tinted by the normal colour told from one whose hue changes with
// the lighting only, and fitted with the tint divided out; a washed-out picture's white share.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { channelOf, parameterGroups, handlerChannelOf } from '../../grader/core/controls.js';
import { analyse, samples, diffuseFit, hueByNormal, tintedByNormal, shadeFit } from '../../grader/core/measure.js';
import { clippedShare } from '../../grader/core/measure/samples.js';
import { spherePicture } from './sphere-picture.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const thresholds = rubric.thresholds;
const P = rubric.controls;

const slider = (index, id, text = '') => ({ index, type: 'range', id, name: '', text, min: '0', max: '1', value: '0.5' });

test('channelOf reads a parameter and its channel from the names students give per-channel sliders', () => {
  for (const [s, stem, ch] of [['ksR', 'ks', 'r'], ['ks_r', 'ks', 'r'], ['kd-red', 'kd', 'red'], ['lightX', 'light', 'x'], ['ks0', 'ks', '0'], ['k_s (g)', 'k_s', 'g'], ['Specular B:', 'specular', 'b']]) {
    const c = channelOf(s);
    assert.ok(c, s);
    assert.equal(c.stem, stem, s);
    assert.equal(c.channel, ch, s);
  }
  for (const s of ['kd', 'ks', 'La', 'Le', 'shininess', 'kdSlider', 'color', '']) assert.equal(channelOf(s), null, s);
});

test('parameterGroups: three sliders of one stem and r/g/b (or x/y/z, 0/1/2) are one parameter with its role; a numbering is not', () => {
  const cs = ['kd_r', 'kd_g', 'kd_b', 'ks_r', 'ks_g', 'ks_b', 'shine', 'Le', 'La'].map((id, k) => slider(k, id));
  const g = parameterGroups(cs, P);
  assert.deepEqual(g.map((x) => [x.role, x.controls.length]), [['kd', 3], ['ks', 3], ['s', 1], ['Le', 1], ['La', 1]]);
  assert.equal(g[1].channels, 'r, g, b');
  // ids s1 … s5 (bjorn's sliders) are five parameters, not channels
  assert.equal(parameterGroups(['s1', 's2', 's3', 's4', 's5'].map((id, k) => slider(k, id)), P).length, 5);
  // named by the words beside them when the ids say nothing
  const byText = parameterGroups(['a', 'b', 'c'].map((id, k) => slider(k, `x${id}q`, `Specular ${'RGB'[k]}`)), P);
  assert.deepEqual(byText.map((x) => [x.role, x.controls.length]), [['ks', 3]]);
  // a colour picker is one parameter, its role from its name
  const pick = parameterGroups([{ index: 0, type: 'color', id: 'ksColor', text: 'ks', value: '#ffffff' }], P);
  assert.deepEqual(pick.map((x) => [x.role, x.controls.length]), [['ks', 1]]);
  // two channels only are not read as one parameter
  assert.equal(parameterGroups(['ks_r', 'ks_g'].map((id, k) => slider(k, id)), P).length, 2);
});

test('parameterGroups: three sliders whose handlers call one function with 0, 1, 2 first are one parameter, where its name or their words agree', () => {
  const h = (f, k) => ({ ...slider(k, `slider${k + 1}`, 'Specular'), handler: `function oninput(event) {\n${f}(${k % 3}, this.value)\n}` });
  const ks = [0, 1, 2].map((k) => h('changeKs', k));
  assert.deepEqual(parameterGroups(ks, P).map((x) => [x.role, x.controls.length]), [['ks', 3]]);
  // one function for three parameters (setParam(0, …) for kd, (1, …) for ks, (2, …) for s) is no colour
  const params = ['kd', 'ks', 'shininess'].map((w, k) => ({ ...slider(k, `${w}Slider`, w), handler: `(e) => setParam(${k}, e.target.value)` }));
  assert.deepEqual(parameterGroups(params, P).map((x) => x.controls.length), [1, 1, 1]);
  // a stem that names nothing: the words beside them must agree (they do: "Light colour")
  const light = [0, 1, 2].map((k) => ({ ...slider(k, `q${k}`, 'Light colour'), handler: `(e) => update(${k}, e.target.value)` }));
  assert.deepEqual(parameterGroups(light, P).map((x) => x.controls.length), [3]);
  assert.equal(handlerChannelOf('function () { render(); }'), null);
  assert.equal(handlerChannelOf('parseFloat(0, 1)'), null);
});

const norm = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const sphere = spherePicture;
const wi = norm([-1, 0.4, 0.8]);
const phong = (n, { kd = 0.9, ks = 0.7, s = 25, La = 0.15 } = {}) => {
  const d = dot(n, wi), wr = n.map((v, k) => 2 * d * v - wi[k]);
  return { lit: kd * Math.max(d, 0) + kd * La, spec: ks * Math.pow(Math.max(wr[2], 0), s) };
};
const turn = (n) => [Math.cos(1) * n[0] + Math.sin(1) * n[2], n[1], -Math.sin(1) * n[0] + Math.cos(1) * n[2]]; // the world's normal, the camera orbited 1 rad
const pts = (img) => samples(img, analyse(img, thresholds), thresholds);

test('the hue turns with the normal where the P1 colour is the material or mixed in; not where only the lighting changes it', () => {
  const tintedTimes = sphere((n) => { const p = phong(n); return turn(n).map((v) => (0.5 * v + 0.5) * p.lit + p.spec); });
  const tintedMix = sphere((n) => { const p = phong(n); return turn(n).map((v) => 0.5 * (0.5 * v + 0.5) + 0.5 * (p.lit + p.spec)); });
  const plain = sphere((n) => { const p = phong(n); return [0.8, 0.3, 0.2].map((c) => c * p.lit + p.spec); });
  // magenta ambient, yellow diffuse: the hue follows n·w_i, one direction only
  const twoColours = sphere((n) => { const d = Math.max(dot(n, wi), 0); return [0.3 + 0.6 * d, 0.1 + 0.8 * d, 0.3]; });
  assert.ok(tintedByNormal(hueByNormal(pts(tintedTimes), thresholds), thresholds));
  assert.ok(tintedByNormal(hueByNormal(pts(tintedMix), thresholds), thresholds));
  assert.ok(!tintedByNormal(hueByNormal(pts(plain), thresholds), thresholds));
  const h = hueByNormal(pts(twoColours), thresholds);
  assert.ok(h.spread > 0.04 && !tintedByNormal(h, thresholds), JSON.stringify(h));
  // the plain picture's fit is diffuseFit's, untouched
  assert.deepEqual(shadeFit(pts(plain), thresholds), diffuseFit(pts(plain), thresholds));
});

test('a picture tinted by the normal is fitted with the tint divided out where the brightness alone does not fit', () => {
  // the P1 colour as the albedo, lit from below in front (40° from the viewer), the camera orbited 4 rad
  const below = norm([0, -Math.sin(0.7), Math.cos(0.7)]);
  const orbit4 = (n) => [Math.cos(4) * n[0] + Math.sin(4) * n[2], n[1], -Math.sin(4) * n[0] + Math.cos(4) * n[2]];
  const img = sphere((n) => {
    const d = dot(n, below), wr = n.map((v, k) => 2 * d * v - below[k]);
    const lit = 0.9 * Math.max(d, 0) + 0.18, spec = 0.7 * Math.pow(Math.max(wr[2], 0), 25);
    return orbit4(n).map((v) => (0.5 * v + 0.5) * lit + spec);
  });
  const plain = diffuseFit(pts(img), thresholds), fit = shadeFit(pts(img), thresholds);
  assert.ok(plain.r2 < thresholds.diffuseR2, `the brightness alone: R² ${plain.r2}`);
  assert.ok(fit.tint && fit.r2 >= thresholds.diffuseR2, `with the tint divided out: R² ${fit.r2}`);
  assert.ok((180 / Math.PI) * Math.acos(dot(fit.light, below)) < 15, `the light ${fit.light}`);
  // the P1 albedo's brightness varies by ±58% over the sphere: the fitted light cannot place a highlight
  assert.ok(fit.tint.slope >= thresholds.tintSlope && !fit.tint.sure, JSON.stringify(fit.tint, (k, v) => (k === 'plain' ? undefined : v)));
});

test('clippedShare: the share of the sphere washed out to white', () => {
  const washed = sphere((n) => { const d = Math.max(dot(n, wi), 0); return [1, 0.96, 0.9].map((c) => c * 1.44 * (0.5 + 1.5 * d)); });
  const fine = sphere((n) => { const d = Math.max(dot(n, wi), 0); return [1, 0.96, 0.9].map((c) => c * 0.72 * (0.5 + 0.75 * d)); });
  const a = analyse(washed, thresholds), b = analyse(fine, thresholds);
  assert.ok(clippedShare(washed, a, thresholds) >= thresholds.clippedShare, String(clippedShare(washed, a, thresholds)));
  assert.ok(clippedShare(fine, b, thresholds) <= thresholds.unclippedShare, String(clippedShare(fine, b, thresholds)));
});

test('a highlight at the light is a review on a plain material, and a note where the tint makes the fitted light unsure', async () => {
  const { auditHighlight } = await import('../../grader/core/audits/units/highlight.js');
  const { shadingOf } = await import('../../grader/core/computed/evidence.js');
  const light = norm([0.9, 0.2, 0.35]); // 68° from the viewer
  const atLight = (n, albedo) => {
    const d = Math.max(dot(n, light), 0);
    const spec = 0.8 * Math.pow(d, 60); // peaks at the light, not at the halfway normal
    return albedo.map((c) => c * (0.1 + 0.8 * d) + spec);
  };
  const judge = (img) => {
    const checks = [];
    const an = analyse(img, thresholds);
    auditHighlight({ facts: {}, images: {}, thresholds, must: new Set(['highlight']), numbers: {}, sayAs: () => (level, reason) => checks.push({ level, reason }) }, shadingOf(img, an, thresholds), []);
    return checks;
  };
  const plain = judge(sphere((n) => atLight(n, [0.8, 0.5, 0.3])));
  assert.ok(plain.some((c) => c.level === 'mistake' && /sits at the light/.test(c.reason)), plain.map((c) => c.reason).join(' | '));
  const tinted = judge(sphere((n) => atLight(n, turn(n).map((v) => 0.5 * v + 0.5))));
  assert.ok(!tinted.some((c) => c.level === 'mistake'), tinted.map((c) => c.reason).join(' | '));
  assert.ok(tinted.some((c) => /^note: the highlight's place is not judged: the colours are tinted by the normal/.test(c.reason)), tinted.map((c) => c.reason).join(' | '));
});

/** A page under the page interface: snap() draws `draw(values)` (values: control index → value as set), setValue records each call. */
function fakePage(controls, draw) {
  const values = new Map(controls.map((c) => [c.index, c.value]));
  const calls = [];
  const pageState = async () => ({ api: 'webgl', frames: 0, draws: 1, vertices: 3, pending: 0, faces: {} });
  return {
    calls, values,
    page: {
      state: pageState,
      snap: async () => draw(values),
      controls: async () => controls,
      setValue: async (c, v, events) => { values.set(c.index, String(v)); calls.push([c.id, String(v), events.join(',')]); },
      tick: pageState,
      click: async () => ({ ok: true }),
    },
  };
}

test('trySliders moves the three sliders of one parameter together, and the artifact says which', async () => {
  const { openSession } = await import('../../grader/core/gather/session.js');
  const { trySliders } = await import('../../grader/core/gather/sliders.js');
  const controls = ['ks_r', 'ks_g', 'ks_b', 'shine'].map((id, k) => ({ ...slider(k, id), max: id === 'shine' ? '100' : '1', value: id === 'shine' ? '30' : '0.6' }));
  const { page, calls } = fakePage(controls, (v) => sphere((n) => { const ks = [0, 1, 2].map((k) => Number(v.get(k))); return ks.map((x) => 0.3 + 0.5 * x * Math.pow(n[2], Number(v.get(3)))); }));
  const S = openSession(page, { part: 'WP04P4', rubric });
  S.facts.judged = S.keep('judged', await page.snap());
  await trySliders(S, controls);
  assert.equal(S.facts.sliders.length, 2);
  assert.deepEqual(S.facts.sliders[0].controls, [0, 1, 2]);
  assert.equal(S.facts.sliders[0].role, 'ks');
  // the three set to 0 before the picture was taken, on input, then back
  assert.deepEqual(calls.slice(0, 3), [['ks_r', '0', 'input'], ['ks_g', '0', 'input'], ['ks_b', '0', 'input']]);
  assert.deepEqual(calls.slice(3, 6).map((c) => c[1]), ['0.6', '0.6', '0.6']);
});

test('a picture washed out to white: the page\'s own kd, Le, La are halved in turn until it is not, and stay there', async () => {
  const { openSession } = await import('../../grader/core/gather/session.js');
  const { unclip } = await import('../../grader/core/gather/visible.js');
  const controls = [['kd', '2', '1.6'], ['Le', '3', '1.5'], ['La', '1', '0.5']].map(([id, max, value], k) => ({ ...slider(k, id), max, value }));
  const draw = (v) => sphere((n) => {
    const kd = Number(v.get(0)), Le = Number(v.get(1)), La = Number(v.get(2)), d = Math.max(dot(n, wi), 0);
    return [1, 0.96, 0.9].map((c) => c * kd * (La + Le * d));
  });
  const { page, values } = fakePage(controls, draw);
  const S = openSession(page, { part: 'WP04P5', rubric });
  const img = await page.snap();
  const shown = await unclip(S, controls, img, analyse(img, thresholds));
  assert.ok(shown, 'a picture to read the shading from');
  assert.deepEqual(S.facts.unclipped.steps.map((s) => [s.role, s.value]), [['kd', 0.8], ['Le', 0.75]]);
  assert.ok(S.facts.unclipped.before >= thresholds.clippedShare && S.facts.unclipped.after <= thresholds.unclippedShare);
  assert.equal(values.get(0), '0.8');
  assert.equal(S.now(controls[1]), 0.75);
  // a picture that is not washed out is left alone
  const S2 = openSession(fakePage(controls, draw).page, { part: 'WP04P5', rubric });
  assert.equal(await unclip(S2, controls, shown, analyse(shown, thresholds)), null);
});
