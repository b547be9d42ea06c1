// The steps' parameters (common/params.js): reading the URL, clamping, saying what was fixed,
// defaults that follow other values, and writing the view back into a query string.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { PARAMETERS, autoLevel, queryString, readParams, wrapAngle } from '../../common/params.js';
import { chooseLevel } from '../../common/sphere.js';

const LIT = ['api', 'size', 'height', 'near', 'far', 'level', 'orbit', 'angle', 'light', 'lx', 'ly', 'lz', 'kd', 'Le', 'ks', 's', 'La', 'model'];

test('no query: every parameter gets its declared default, and nothing is said', () => {
  const { values, notices } = readParams(LIT, '', { shading: 'phong' });
  assert.deepEqual(notices, []);
  assert.deepEqual(values, {
    api: 'webgl2', size: 512, height: 512, near: 0.1, far: 10, level: chooseLevel(512, 45, 3, { shading: 'phong' }).level,
    orbit: true, angle: 0, light: 'directional', lx: 0, ly: 0, lz: -1, kd: 0.8, Le: 1, ks: 0.5, s: 40, La: 0.2, model: 'phong',
  });
});

test('good values are taken as given', () => {
  const { values, notices } = readParams(LIT, '?level=3&orbit=0&angle=0.6&kd=0.25&s=0&Le=1e6&model=blinn-phong&api=webgl');
  assert.deepEqual(notices, []);
  assert.equal(values.level, 3);
  assert.equal(values.orbit, false);
  assert.equal(values.angle, 0.6);
  assert.equal(values.kd, 0.25);
  assert.equal(values.s, 0);
  assert.equal(values.Le, 1e6);
  assert.equal(values.model, 'blinn-phong');
  assert.equal(values.api, 'webgl');
});

test('bad values are clamped or replaced by the default, each with a sentence that says so', () => {
  const { values, notices } = readParams(LIT, '?level=999&s=-3&kd=abc&api=foo&orbit=maybe&size=7.5&model=');
  assert.equal(values.level, 8);
  assert.equal(values.s, 0);
  assert.equal(values.kd, 0.8);
  assert.equal(values.api, 'webgl2');
  assert.equal(values.orbit, true);
  assert.equal(values.size, 16);
  assert.equal(values.model, 'phong');
  assert.deepEqual(notices.sort(), [
    'api=foo is not one of webgl2, webgl, webgpu: using api=webgl2.',
    'kd=abc is not a number: using kd=0.8.',
    'level=999 is above the largest value 8: using 8.',
    'model= is not one of phong, blinn-phong: using model=phong.',
    'orbit=maybe is not on/off (1 or 0): using orbit=true.',
    's=-3 is below the least value 0: using 0.',
    'size=7.5 is below the least value 16: using 16.',
  ]);
  assert.deepEqual(readParams(['api', 'size', 'level'], '?level=2.6').notices, ['level=2.6 is not a whole number: using 3.']);
});

test('a parameter the step does not have is ignored and named', () => {
  const { values, notices } = readParams(['api', 'size', 'level'], '?kd=0.5&level=2');
  assert.deepEqual(notices, ['Unknown parameter "kd" ignored.']);
  assert.equal(values.level, 2);
  assert.equal('kd' in values, false);
});

test('defaults that follow other values: height follows size, the light follows its kind, the level the canvas', () => {
  const point = readParams(LIT, '?light=point&size=128').values;
  assert.deepEqual([point.lx, point.ly, point.lz], [0, 0, 2]);
  assert.equal(point.height, 128);
  assert.equal(point.level, chooseLevel(128, 45, 3).level); // no shading given: the silhouette alone
  const given = readParams(LIT, '?light=point&lz=5').values;
  assert.deepEqual([given.lx, given.ly, given.lz], [0, 0, 5]);
  // the level is chosen for the height, not the width
  assert.equal(readParams(LIT, '?size=512&height=64', { shading: 'gouraud' }).values.level,
    chooseLevel(64, 45, 3, { shading: 'gouraud' }).level);
  assert.equal(autoLevel({ size: 512 }), chooseLevel(512, 45, 3).level);
});

test('the view\'s own rules: the angle wraps into [0, 2π), the far plane stays beyond the near one', () => {
  assert.ok(Math.abs(readParams(LIT, `?angle=${-Math.PI / 2}`).values.angle - 1.5 * Math.PI) < 1e-12);
  assert.ok(Math.abs(wrapAngle(7) - (7 - 2 * Math.PI)) < 1e-12);
  const v = readParams(LIT, '?near=5&far=1').values;
  assert.equal(v.near, 5);
  assert.ok(v.far > v.near);
});

test('a query string written from values reads back to the same values', () => {
  const { values } = readParams(LIT, '?orbit=0&angle=1.25&light=point&lx=1.5&s=120&model=blinn-phong&size=200');
  const again = readParams(LIT, `?${queryString(values)}`);
  assert.deepEqual(again.notices, []);
  assert.deepEqual(again.values, values);
  assert.match(queryString({ orbit: false, cull: true }), /^orbit=0&cull=1$/);
});

test('every slider range lies within what the URL accepts, and every control has a label', () => {
  for (const [name, rule] of Object.entries(PARAMETERS)) {
    if (rule.slider) {
      const [min, max, step] = rule.slider;
      assert.ok(min >= rule.min && max <= rule.max && min < max && step > 0, `${name}: slider ${rule.slider} within [${rule.min}, ${rule.max}]`);
      assert.ok(rule.label, `${name} has a label`);
    }
    if (rule.type === 'enum') assert.ok(Object.keys(rule.options).includes(rule.default), `${name}'s default is an option`);
    if (rule.type === 'bool') assert.ok(rule.label, `${name} has a label`);
  }
});
