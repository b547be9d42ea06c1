// WP04P1/P2 read from the normals the colours show: "in perspective view" by how far
// they reach at the rim, the slide's clockwise experiment as a note, and WP04P1's colours in a lit
// step not taken for lighting. On pictures rendered here, exactly, with no browser.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { analyse, samples } from '../../grader/core/measure.js';
import { normalAngle, rimAngle } from '../../grader/core/measure/perspective.js';
import { auditNormals } from '../../grader/core/audits/units/normal-colours.js';
import { auditPerspective } from '../../grader/core/audits/units/perspective.js';
import { auditNormalsNotLight } from '../../grader/core/audits/units/normals-not-light.js';
import { checkList } from '../../grader/core/verdict.js';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const thresholds = rubric.thresholds;
const DEG = 180 / Math.PI;

// the world turned against the view (the colours are world normals, whatever the camera)
const c = Math.cos(0.7), s = Math.sin(0.7);
const turn = (n) => [c * n[0] + s * n[2], n[1], -s * n[0] + c * n[2]];

/**
 * A w×w picture of the unit sphere, coloured by `shade(n)` (n the world normal) on a dark grey
 * background: seen by an eye `d` radii from the centre with a field of view `fovy` degrees, or
 * orthographically (d = Infinity, the sphere `share` of the picture wide); `far`: the inside of
 * the far side (the front faces culled).
 */
function sphere({ w = 160, d = 3, fovy = 45, share = 0.8, far = false, shade = (n) => n.map((v) => 0.5 * v + 0.5) } = {}) {
  const data = new Uint8Array(w * w * 4);
  const t = Math.tan(fovy / 2 / DEG);
  for (let y = 0; y < w; y++) {
    for (let x = 0; x < w; x++) {
      const sx = (x + 0.5) / w * 2 - 1, sy = 1 - (y + 0.5) / w * 2;
      let n = null;
      if (d === Infinity) {
        const px = sx / share, py = sy / share, r2 = px * px + py * py;
        if (r2 < 1) n = [px, py, (far ? -1 : 1) * Math.sqrt(1 - r2)];
      } else {
        const dir = [sx * t, sy * t, -1], len = Math.hypot(...dir);
        const u = dir.map((v) => v / len);
        const b = d * u[2], disc = b * b - d * d + 1; // |(0, 0, d) + k u|² = 1
        if (disc > 0) {
          const k = -b + (far ? 1 : -1) * Math.sqrt(disc);
          n = [k * u[0], k * u[1], d + k * u[2]];
        }
      }
      const col = n ? shade(turn(n)) : [0.2, 0.2, 0.25];
      data.set([...col.map((v) => Math.round(255 * Math.min(1, Math.max(0, v)))), 255], 4 * (y * w + x));
    }
  }
  return { width: w, height: w, data };
}

const judgedOf = (img) => ({ img, an: analyse(img, thresholds) });
function context(mustList, facts = {}) {
  const { checks, sayAs } = checkList(rubric);
  return { C: { facts, images: {}, thresholds, must: new Set(mustList), sayAs, numbers: {} }, checks };
}

test('normalAngle: orthographic reaches 90° at the rim, a perspective view acos(1/d), the inside of the far side 180° − acos(1/d)', () => {
  assert.ok(Math.abs(normalAngle(1, 0) * DEG - 90) < 1e-9);
  for (const d of [2, 3, 10]) {
    const a = Math.asin(1 / d);
    assert.ok(Math.abs(normalAngle(1, a) * DEG - Math.acos(1 / d) * DEG) < 1e-6, `d = ${d}`);
    assert.ok(Math.abs(normalAngle(1, a, true) * DEG - (180 - Math.acos(1 / d) * DEG)) < 1e-6, `far, d = ${d}`);
    assert.ok(Math.abs(normalAngle(0, a)) < 1e-12);
  }
});

test('rimAngle reads the projection from the normals: orthographic 90°, an eye 3 or 10 radii away acos(1/d), on either side', () => {
  const rim = (o) => rimAngle(samples(sphere(o), analyse(sphere(o), thresholds), thresholds, { maxRho: 0.9 }), !!o.far, thresholds);
  const ortho = rim({ d: Infinity });
  assert.ok(ortho.rimDegrees >= 89.5 && ortho.rms < 1, JSON.stringify(ortho));
  for (const d of [3, 10]) {
    const want = Math.acos(1 / d) * DEG;
    const near = rim({ d, fovy: d === 3 ? 45 : 15 });
    assert.ok(Math.abs(near.rimDegrees - want) <= 1 && near.rms < 1, `d = ${d}: ${JSON.stringify(near)}`);
    const far = rim({ d, fovy: d === 3 ? 45 : 15, far: true });
    assert.ok(Math.abs(far.rimDegrees - (180 - want)) <= 1 && far.rms < 1, `far, d = ${d}: ${JSON.stringify(far)}`);
  }
  assert.ok(Math.abs(rim({ d: Infinity, far: true }).rimDegrees - 90) <= 0.5);
});

test('WP04P1 in perspective view: an orthographic picture is a review in the slide\'s words; an eye 3 or 10 radii away passes', () => {
  const judge = (o) => {
    const { C, checks } = context(['normal-colours', 'perspective']);
    auditPerspective(C, auditNormals(C, judgedOf(sphere(o))));
    return checks.filter((k) => /perspective/.test(k.reason));
  };
  const ortho = judge({ d: Infinity });
  assert.equal(ortho.length, 1);
  assert.equal(ortho[0].level, 'review');
  assert.match(ortho[0].reason, /not in perspective view \(the slide: "Draw a solid sphere in perspective view"\)/);
  for (const o of [{ d: 3 }, { d: 10, fovy: 15 }, { d: 3, far: true }]) {
    const got = judge(o);
    assert.equal(got.length, 1, JSON.stringify(o));
    assert.equal(got[0].level, 'pass', got[0].reason);
  }
  // the rule belongs to the parts whose rubric asks for it
  const { C, checks } = context(['normal-colours']);
  auditPerspective(C, auditNormals(C, judgedOf(sphere({ d: Infinity }))));
  assert.ok(!checks.some((k) => /perspective/.test(k.reason)));
});

test('WP04P2: the inside of the far side with clockwise front faces and back faces culled is the slide\'s experiment (a note); without them a review', () => {
  const far = judgedOf(sphere({ d: 3, far: true }));
  const judge = (faces, api = 'webgl') => {
    const { C, checks } = context(['normal-colours', 'front-faces'], { api, faces });
    auditNormals(C, far);
    return checks;
  };
  const cw = judge({ depthTest: true, culling: true, cullMode: 'back', frontFace: 'cw' });
  assert.ok(cw.some((k) => k.level === 'pass' && /^note: the back side of the sphere shows, as the slide's clockwise experiment.*gl\.frontFace\(gl\.CW\)/.test(k.reason)), cw.map((k) => k.reason).join(' | '));
  assert.ok(!cw.some((k) => k.level !== 'pass'));
  const gpu = judge({ depthTest: true, culling: true, cullMode: 'back', frontFace: 'cw' }, 'webgpu');
  assert.ok(gpu.some((k) => /frontFace: 'cw'/.test(k.reason)));
  for (const faces of [{ depthTest: true, culling: true, cullMode: 'back' }, { depthTest: true, culling: true, cullMode: 'front', frontFace: 'cw' }, { depthTest: true, culling: false, frontFace: 'cw' }]) {
    assert.ok(judge(faces).some((k) => k.level === 'review' && /inside of the far side/.test(k.reason)), JSON.stringify(faces));
  }
  // the grader's frame with culling off: the same picture means the nearest faces showed, unless the
  // page drew nothing meanwhile (it draws only when a control asks): then it tells nothing
  const faces = { depthTest: true, culling: true, frontFace: 'cw' };
  const probe = (draws) => {
    const { C, checks } = context(['normal-colours', 'front-faces'], { api: 'webgl', faces, noCull: { faces, image: 'no-cull', draws } });
    C.images['no-cull'] = far.img;
    auditNormals(C, far);
    return checks.map((k) => k.reason).join(' | ');
  };
  assert.match(probe(3), /the visible faces are the nearest ones/);
  assert.match(probe(0), /note: the back side of the sphere shows/);
  assert.doesNotMatch(probe(0), /nearest/);
});

test('a lit step that shows WP04P1\'s colours is not lit; a lit sphere, white or tinted by the normal colour, is not taken for them', () => {
  const judge = (shade) => {
    const { C, checks } = context(['sphere', 'diffuse', 'orbit-toggle']);
    return { said: auditNormalsNotLight(C, judgedOf(sphere({ d: 3, shade }))), checks };
  };
  const p1 = judge(undefined);
  assert.equal(p1.said, true);
  assert.equal(p1.checks[0].level, 'review');
  assert.match(p1.checks[0].reason, /shows the normal colouring of WP04P1, not the lighting/);
  const w = turn([0.3, 0.5, 0.8]).map((v, k, a) => v / Math.hypot(...a));
  const diffuse = (n) => 0.1 + 0.85 * Math.max(0, n[0] * w[0] + n[1] * w[1] + n[2] * w[2]);
  for (const shade of [(n) => [0.9, 0.9, 0.9].map((k) => k * diffuse(n)), (n) => n.map((v) => (0.5 * v + 0.5) * diffuse(n))]) {
    const got = judge(shade);
    assert.equal(got.said, false);
    assert.deepEqual(got.checks, []);
  }
  const { C, checks } = context(['normal-colours']);
  assert.equal(auditNormalsNotLight(C, judgedOf(sphere({ d: 3 }))), false);
  assert.deepEqual(checks, []);
});
