// The slide's model fitted on the page's own surface (grader/core/measure/surface-fit.js): on
// pictures made here from the exact sphere with a known light, material and form, the fit finds
// the light and names the form, the normal colour added, and w_o as the slide has it or not.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { surfaceOf, degreesBetween } from '../../grader/core/computed/surface.js';
import { surfaceFit } from '../../grader/core/measure/surface-fit.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const eye = [1.2, 0.6, 3.2];
const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));
const wi = (() => { const l = [0.3, 0.5, 1], n = Math.hypot(...l); return l.map((x) => x / n); })();
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };

/** L_o of the slides at p (n = p), w_o from `woOf(p)`, Phong with s = 40 and ks; the normal colour added with weight `tint`. */
const model = ({ woOf = (p) => unit(eye.map((e, k) => e - p[k])), tint = 0, kd = [0.7, 0.5, 0.3], ks = 0.4 } = {}) => (p, k) => {
  const c = dot(p, wi), wo = woOf(p);
  const wr = p.map((n, j) => 2 * c * n - wi[j]);
  const spec = c > 0 ? Math.max(dot(wr, wo), 0) ** 40 : 0;
  return 0.1 + kd[k] * Math.max(c, 0) * 0.8 + ks * spec + tint * (0.5 * p[k] + 0.5);
};

function fitOf(shade) {
  const u = surfaceUnder(pv, eye, { shade });
  return surfaceFit(surfaceOf(u.facts, u.images, T), u.picture, T);
}

test('the slide\'s Phong model: the light found, the slide\'s w_o named best', () => {
  const f = fitOf(model());
  assert.ok(!f.why, f.why);
  assert.ok(degreesBetween(f.best.wi, wi) < 3, `light ${f.best.wi}`);
  assert.equal(f.best.view, 'the slide');
  assert.equal(f.best.tint, null);
  assert.ok(f.best.rms < 0.01, `rms ${f.best.rms}`);
});

test('the normal colour added to the lighting is a term of its own; w_o fixed in the eye space is told from the slide\'s', () => {
  const tinted = fitOf(model({ tint: 0.5, kd: [0.3, 0.3, 0.3] }));
  assert.equal(tinted.best.tint, 'added', tinted.best.name);
  // the lighting is there beside the normal colour; WP04P1's colouring alone is not lit
  assert.equal(tinted.lit, true);
  const p1 = fitOf((p, k) => 0.5 * p[k] + 0.5);
  assert.equal(p1.lit, false);
  assert.ok(p1.normalColourAlone.rms < 0.005);
  assert.ok(degreesBetween(tinted.best.wi, wi) < 3);
  const back = unit(eye);
  const fixed = fitOf(model({ woOf: () => back }));
  // (a term more fits a little better: among the fits with nothing added)
  const plain = fixed.variants.filter((v) => !/normal colour/.test(v.name));
  assert.equal(plain[0].name, 'phong, w_o fixed at the eye space\'s (0, 0, 1)');
  const slide = fixed.variants.find((v) => v.name === 'phong, w_o the slide');
  assert.ok(slide.rms > 1.5 * plain[0].rms, `${slide.rms} against ${plain[0].rms}`);
  // named only where the slide's formula leaves a visible residual: here it is within surfaceResidual
  assert.ok(slide.rms < T.surfaceResidual);
  assert.equal(fixed.best.name, 'phong, w_o the slide');
  assert.match(surfaceFit(null, null, T).why, /no surface/);
});

test('below the margin, the reason says the pictures cannot tell a w_o misread from the slide\'s', async () => {
  const { auditSurfaceFit } = await import('../../grader/core/audits/units/surface-fit.js');
  const said = (f, must) => {
    const out = [];
    auditSurfaceFit({ sayAs: () => (level, reason) => out.push(`${level}: ${reason}`), must: new Set(must), thresholds: T }, f);
    return out.join('\n');
  };
  // w_o fixed at the eye space's (0, 0, 1): a little better than the slide's, not by the margin
  const fixed = fitOf(model({ woOf: () => unit(eye) }));
  assert.equal(fixed.best.view, 'the slide');
  assert.match(said(fixed, ['highlight']), /^pass: note: on the page's own surface, a w_o misread explains the picture a little better than the slide's w_o \(w_o is one direction for the whole sphere .*the pictures cannot tell them apart$/);
  // a step with no highlight asked for (P3) says nothing of w_o; nor does the slide's own picture
  assert.equal(said(fixed, ['diffuse']), '');
  assert.equal(said(fitOf(model()), ['highlight']), '');
});

test('the normal colour as the material, multiplying the lighting, is named as such', () => {
  const times = fitOf((p, k) => (0.5 * p[k] + 0.5) * model({ kd: [1, 1, 1] })(p, k));
  assert.equal(times.best.tint, 'times', times.best.name);
  assert.ok(degreesBetween(times.best.wi, wi) < 3);
});

test('where the page\'s surface could not be read, the part says its lighting was judged on the outline, and why', async () => {
  const { auditPart } = await import('../../grader/core/audit.js');
  const { readArtifact } = await import('../../grader/node/run/artifacts.js');
  const { RECORDED } = await import('../fixtures/record.js');
  const path = await import('node:path');
  const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
  // quinn's P3 makes its positions in the vertex shader: its geometry is not drawn again
  const said = auditPart(readArtifact(path.join(RECORDED, 'quinn', 'WP04P3')), rubric).checks.filter((c) => c.id === 'surface-fit');
  assert.deepEqual(said.map((c) => c.level), ['pass']);
  assert.match(said[0].reason, /^note: the lighting was judged on the outline \(a sphere assumed from the silhouette\), not on the page's own surface: the page's geometry could not be drawn again/);
  // a part whose surface was read says nothing of the kind
  const read = auditPart(readArtifact(path.join(RECORDED, 'anna', 'WP04P3')), rubric).checks.filter((c) => /judged on the outline/.test(c.reason));
  assert.deepEqual(read, []);
});

test('w_o with the view matrix applied twice is named, and a w_o misread past the margin is a review', async () => {
  const V = mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]);
  // the page's w_o: −normalize(V·(V·p)) in the eye's space, i.e. normalize(e − V·p) in the model's
  const twice = (p) => {
    const q = [0, 1, 2].map((r) => V[r] * p[0] + V[4 + r] * p[1] + V[8 + r] * p[2] + V[12 + r]);
    return unit(eye.map((e, k) => e - q[k]));
  };
  // (a highlight as bright as a student's default: the slide's formula then leaves a visible residual)
  const f = fitOf(model({ woOf: twice, kd: [0.5, 0.4, 0.3], ks: 0.9 }));
  assert.equal(f.best.view, 'with the view matrix applied twice', [f.slide.rms, ...f.variants.slice(0, 4).map((v) => `${v.name} ${v.rms}`)].join('\n'));
  const { auditSurfaceFit } = await import('../../grader/core/audits/units/surface-fit.js');
  const said = [];
  auditSurfaceFit({ sayAs: () => (level, reason) => said.push({ level, reason }) }, f);
  assert.deepEqual(said.map((x) => x.level), ['mistake']);
  assert.match(said[0].reason, /w_o is built with the view matrix applied twice/);
  // two misreadings at once, each of which alone leaves the picture unexplained: w_o built with V
  // twice and the normal colour added (the slide's formula with the colour, or with the misread w_o
  // alone, do not beat the slide's formula by the margin; the two together do)
  const both = fitOf(model({ woOf: twice, tint: 0.2, kd: [0.5, 0.5, 0.5], ks: 0.9 }));
  assert.equal(both.best.view, 'with the view matrix applied twice', [both.slide.rms, ...both.variants.slice(0, 4).map((v) => `${v.name} ${v.rms}`)].join('\n'));
  assert.equal(both.best.tint, 'added');
  // the normal colour kept in the material is the page's choice: a note, not a mistake
  const tinted = [];
  auditSurfaceFit({ sayAs: () => (level, reason) => tinted.push({ level, reason }) }, fitOf(model({ tint: 0.5, kd: [0.3, 0.3, 0.3] })));
  assert.deepEqual(tinted.map((x) => x.level), ['pass']);
  assert.match(tinted[0].reason, /^note: /);
});
