// The highlight's place read on the page's own surface in the view along the orbit
// (grader/core/audits/units/highlight-place.js): on pictures made here from the exact sphere, the
// slide's Phong model with WP04P1's normal colour added, whose highlight the picture's own fit (a
// sphere assumed from the outline) places 41° off, and w_o built with the view matrix applied twice,
// whose highlight the picture's fit passes and the surface names.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { auditPlaceFarther } from '../../grader/core/audits/units/highlight-place.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };

/** A camera at `eye` looking at the sphere, and the light `degrees` from it (the view the gatherer looks for: 50° or more). */
function sceneAt(eye, degrees = 55) {
  const V = mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]);
  const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), V);
  // (the light given in the eye's space, taken to the model's: Vᵀ · l)
  const l = unit([Math.sin((degrees * Math.PI) / 180), 0.3, Math.cos((degrees * Math.PI) / 180)]);
  const wi = [0, 1, 2].map((k) => V[4 * k] * l[0] + V[4 * k + 1] * l[1] + V[4 * k + 2] * l[2]);
  return { eye, V, pv, wi };
}

/** The slides' L_o at p (n = p), Phong with s = 40 and ks, w_o from `woOf(p)`, and the normal colour 0.5·n + 0.5 added with weight `tint`. */
const model = ({ eye, wi }, { woOf = (p) => unit(eye.map((e, k) => e - p[k])), tint = 0, ks = 0.5 } = {}) => (p, k) => {
  const c = dot(p, wi), wo = woOf(p);
  const wr = p.map((n, j) => 2 * c * n - wi[j]);
  const spec = c > 0 ? Math.max(dot(wr, wo), 0) ** 40 : 0;
  return 0.1 + 0.7 * Math.max(c, 0) * 0.8 + ks * spec + tint * (0.5 * p[k] + 0.5);
};

/** What highlight-place says of the view along the orbit drawn with `shade` (on black), with its surface or without. */
function placeSaid({ eye, pv }, shade, withSurface) {
  const u = surfaceUnder(pv, eye, { shade });
  // (a black background: the sphere clips to white in places, and must not melt into a white one)
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  const said = [];
  const context = {
    facts: { placeFarther: { image: 'place', ...(withSurface ? { surface: u.facts } : {}) } },
    images: { place: u.picture, ...u.images },
    thresholds: T,
    numbers: {},
    imagesShown: {},
    sayAs: (id) => (level, reason) => said.push(`${id} ${level}: ${reason}`),
  };
  auditPlaceFarther(context, null);
  return said.join('\n');
}

test('the slide\'s Phong with the normal colour added: the surface places the highlight where the picture\'s fit cannot', () => {
  const scene = sceneAt([0, 0, 3.5], 70), shade = model(scene, { tint: 1, ks: 0.3 });
  // the picture's own fit, on a sphere assumed from the outline, is misled by the added colour
  assert.match(placeSaid(scene, shade, false), /^highlight-place mistake: the highlight is \d+° from where the model puts it/);
  const said = placeSaid(scene, shade, true);
  assert.match(said, /^highlight-place pass: the highlight sits where the slide's (Phong|Blinn-Phong) model with w_o = normalize\(e − p\) puts it, read on the page's own surface/);
  assert.match(said, /with the normal colour in the material/);
});

test('w_o built with the view matrix applied twice: the picture\'s fit passes it, the surface names it (a mistake)', () => {
  const scene = sceneAt([2.2, 1, 2.4]), { V, eye } = scene;
  // the page's w_o: −normalize(V·(V·p)) in the eye's space, i.e. normalize(e − V·p) in the model's
  const twice = (p) => unit(eye.map((e, k) => e - (V[k] * p[0] + V[4 + k] * p[1] + V[8 + k] * p[2] + V[12 + k])));
  const shade = model(scene, { woOf: twice, ks: 0.9 });
  assert.match(placeSaid(scene, shade, false), /^highlight-place pass: /);
  assert.match(placeSaid(scene, shade, true), /^highlight-place mistake: the highlight is not where the slide puts it: on the page's own surface in a view along the orbit, the picture is explained with a residual of [\d.]+ \(the slide's formula: [\d.]+\) where w_o is built with the view matrix applied twice/);
});

test('in the judged view, the judged view\'s surface decides where the view stood still, the picture where the orbit never stopped', async () => {
  const { fullFit } = await import('../../grader/core/computed/views.js');
  const scene = sceneAt([0, 0, 3.5], 70), u = surfaceUnder(scene.pv, scene.eye, { shade: model(scene, { tint: 1, ks: 0.3 }) });
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  const near = { fit: fullFit(u.picture, T), where: 'the judged view', img: u.picture, atJudged: true };
  const said = (stopped) => {
    const out = [];
    auditPlaceFarther({ facts: { placeFarther: { image: null }, surface: u.facts, stopped }, images: u.images, thresholds: T,
      numbers: {}, imagesShown: {}, sayAs: (id) => (level, reason) => out.push(`${id} ${level}: ${reason}`) }, near);
    return out.join('\n');
  };
  assert.match(said(true), /^highlight-place pass: .* read on the page's own surface in the judged view/);
  assert.match(said(false), /^highlight-place mistake: the highlight is \d+° from where the model puts it/);
});
