// A lit step whose colours decode to unit normals is WP04P1's colouring, not lighting, unless the
// page's own surface shows the lighting beside that colour (grader/core/audits/units/
// normals-not-light.js): on pictures made here from the exact sphere, the normal colour as the
// material times the slides' diffuse and ambient terms, with the light at the eye.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { mat4 } from 'gl-matrix';
import { surfaceUnder } from './surface-scenes.js';
import { auditNormalsNotLight } from '../../grader/core/audits/units/normals-not-light.js';
import { exactLighting } from '../../grader/core/computed/lighting.js';
import { analyse } from '../../grader/core/measure.js';

const T = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8')).thresholds;
const eye = [0, 0, 3.5];
const pv = mat4.multiply(mat4.create(), mat4.perspective(mat4.create(), Math.PI / 4, 1, 0.5, 10), mat4.lookAt(mat4.create(), eye, [0, 0, 0], [0, 1, 0]));
const wi = (() => { const l = [0, 0.3, 1], n = Math.hypot(...l); return l.map((x) => x / n); })();
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** What the audit says of the picture drawn with `shade` (on black), given the surface's fit or not; and that fit. */
function judge(shade, withSurface) {
  const u = surfaceUnder(pv, eye, { shade });
  for (let i = 3; i < u.picture.data.length; i += 4) if (!u.images.n.data[i]) u.picture.data.fill(0, i - 3, i);
  const judged = { img: u.picture, an: analyse(u.picture, T) };
  const exact = withSurface ? exactLighting({}, u.images, judged, T, u.facts) : null;
  const said = [];
  const context = { thresholds: T, must: new Set(['diffuse', 'highlight']), numbers: {}, sayAs: (id) => (level, reason) => said.push(`${id} ${level}: ${reason}`) };
  return { notLight: auditNormalsNotLight(context, judged, exact), said: said.join('\n'), exact };
}

test('the normal colour as the material, lit from the eye: lighting on the surface, though its colours decode to unit normals', () => {
  // c = (0.5·n + 0.5)·(ka·La + kd·Le·max(n·w_i, 0)): the normal colour multiplied by the lighting
  const shade = (p, k) => (0.5 * p[k] + 0.5) * (0.4 + 0.8 * Math.max(dot(p, wi), 0));
  const onPicture = judge(shade, false);
  assert.equal(onPicture.notLight, true);
  assert.match(onPicture.said, /^normals-not-light mistake: shows the normal colouring of WP04P1, not the lighting/);
  const onSurface = judge(shade, true);
  assert.equal(onSurface.exact.lit, true);
  assert.equal(onSurface.exact.best.tint, 'times');
  assert.equal(onSurface.notLight, false);
  assert.equal(onSurface.said, '');
});

test('WP04P1\'s colouring alone in a lit step stays a mistake with the surface read', () => {
  const { notLight, said, exact } = judge((p, k) => 0.5 * p[k] + 0.5, true);
  assert.equal(exact.lit, false);
  assert.equal(notLight, true);
  assert.match(said, /^normals-not-light mistake: shows the normal colouring of WP04P1/);
});
