// The diffuse term read on the page's own surface (grader/core/audits/units/diffuse.js): pictures
// and surfaces made here of the exact sphere, lit by the slide's model, by a near point light the
// surface's model (a directional light) does not explain, and by a highlight over a diffuse term
// too faint to see.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { exactLighting } from '../../grader/core/computed/lighting.js';
import { shadingOf, sphereView } from '../../grader/core/computed/evidence.js';
import { auditDiffuse } from '../../grader/core/audits/units/diffuse.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
const eye = [0, 0, 3.5], wi = unit([0.8, 0.3, 0.4]);
const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));

/** What the diffuse audit says of the sphere shaded by `shade(p)`, with its surface read (or not). */
function said(shade, withSurface = true) {
  const u = surfaceUnder(pv, eye, { shade });
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  const facts = { surface: u.facts }, { an } = sphereView(u.picture, T), out = [];
  const exact = withSurface ? exactLighting(facts, u.images, { img: u.picture, an }, T) : null;
  auditDiffuse({ facts, images: u.images, thresholds: T, must: new Set(['diffuse', 'highlight']), numbers: {},
    sayAs: (id) => (level, reason) => out.push(`${id} ${level}: ${reason}`) }, shadingOf(u.picture, an, T), [], exact);
  return out.join('\n');
}

/** The slides' Phong specular term at p (n = p), w_o towards the eye. */
const specular = (p, s) => {
  const c = dot(p, wi), wo = unit(eye.map((e, k) => e - p[k])), wr = p.map((n, j) => 2 * c * n - wi[j]);
  return c > 0 ? Math.max(dot(wr, wo), 0) ** s : 0;
};

test('the slide\'s diffuse term is read on the page\'s own surface, with its k_d L_e', () => {
  assert.match(said((p) => 0.15 + 0.7 * Math.max(dot(p, wi), 0)),
    /^diffuse pass: brightness follows max\(n·w_i, 0\)·kd·Le \+ ambient, read on the page's own surface .*residual of 0\.00\d, k_d L_e 0\.70$/);
  // without it, the picture's fit on a sphere assumed from the outline
  assert.match(said((p) => 0.15 + 0.7 * Math.max(dot(p, wi), 0), false), /^diffuse pass: brightness follows .*\(R² [\d.]+, fitted light/);
});

test('a near point light: the surface\'s directional model leaves a residual, and the pictures judge it, saying why', () => {
  const light = [1.6, 0.6, 0.8];
  const shade = (p) => { const l = light.map((v, k) => v - p[k]), r = Math.hypot(...l); return 0.1 + (1.2 * Math.max(dot(p, l) / r, 0)) / (r * r); };
  assert.match(said(shade), /^diffuse (pass|mistake): .*\(on the pictures: the page's own surface cannot say: the slide's model leaves a residual of [\d.]+ on the page's own surface\)$/);
});

test('a highlight over a diffuse term too faint to see: no diffuse term, read on the surface', () => {
  const shade = (p) => 0.2 + 0.02 * Math.max(dot(p, wi), 0) + 0.7 * specular(p, 5);
  assert.match(said(shade), /^diffuse mistake: no diffuse term to see: on the page's own surface .*k_d L_e 0\.0\d, under 0\.08$/);
});
