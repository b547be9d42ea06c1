// The grader's modules without a browser: finding parts, stand-in files, sorting a control by its
// effect on pictures, verdicts and reasons from findings, and a teacher's labels against verdicts.
import { fileURLToPath } from 'node:url';
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { partNumber } from '../../grader/files/parts.js';
import { partsOf } from '../../grader/core/part-names.js';
import { findStandIn, typeOf } from '../../grader/core/standin.js';
import { serveSubmission } from '../../grader/node/run/serve-submission.js';
import { analyse, diffuseFit, samples, highlightSeen, highlightOffset, openMask } from '../../grader/core/measure.js';
import { effectOf, nameRole, trialOrder } from '../../grader/core/controls.js';
import { normalAngle } from '../../grader/core/measure/perspective.js';
import { checkList, verdictOf, reasonsOf, findingsOf } from '../../grader/core/verdict.js';
import { parseLabels, agreement, agreementText } from '../../grader/node/report/labels.js';
import { memo } from '../../grader/core/computed/memo.js';
import { readFileSync } from 'node:fs';

const rubric = JSON.parse(readFileSync(new URL('../../grader/core/rubric.json', import.meta.url), 'utf8'));
const T = rubric.thresholds;

/** A w×w picture: a regular polygon of `sides` corners (a sphere's outline at some level) shaded by `shade(nx, ny, nz)`, on grey. */
function polygon(sides, { w = 96, r = 36, shade = () => [0.8, 0.4, 0.2], turn = 0 } = {}) {
  const data = new Uint8Array(w * w * 4);
  const c = w / 2;
  const apothem = r * Math.cos(Math.PI / sides);
  for (let y = 0; y < w; y++) {
    for (let x = 0; x < w; x++) {
      const dx = x + 0.5 - c, dy = y + 0.5 - c;
      const a = Math.atan2(dy, dx) - turn;
      const sector = (2 * Math.PI) / sides;
      const local = ((a % sector) + sector) % sector - sector / 2;
      const inside = Math.hypot(dx, dy) * Math.cos(local) <= apothem;
      const o = 4 * (y * w + x);
      let col = [0.3, 0.3, 0.3];
      if (inside) {
        const nx = dx / r, ny = -dy / r, nz = Math.sqrt(Math.max(0, 1 - nx * nx - ny * ny));
        col = shade(nx, ny, nz);
      }
      data.set([...col.map((v) => Math.round(255 * Math.min(1, Math.max(0, v)))), 255], o);
    }
  }
  return { width: w, height: w, data };
}
const shotOf = (img) => ({ img, an: analyse(img, T) });

test('parts are found by the worksheet and part numbers students write', () => {
  for (const [name, n] of [['W4-1', 1], ['wks4_3', 3], ['ws4_part2', 2], ['02561_W04P5', 5], ['uge4-4', 4], ['sheet4_2', 2]]) assert.equal(partNumber(name), n, name);
  for (const name of ['W4-6', 'wks4', 'Worksheet_4', 'Lab 4', 'model1', 'p12']) assert.equal(partNumber(name), null, name);
  for (const [name, n] of [['01', 1], ['5', 5], ['opgave3', 3], ['Opg_2', 2]]) assert.equal(partNumber(name), n, name);
  for (const name of ['06', '10', '2024', 'v1.2', 'complex1', 'exercise5']) assert.equal(partNumber(name), null, name);
});

test('parts in numbered folders under a week folder, beside common/, are found (week-4/01 … 05)', () => {
  const pages = ['week-4/01/index.html', 'week-4/02/index.html', 'week-4/03/index.html', 'week-4/04/index.html', 'week-4/05/index.html', 'week-4/common/test.html'];
  const found = partsOf(pages.map((p) => p.split('/')), (s) => s.join('/'));
  assert.deepEqual(found, { WP04P1: 'week-4/01/index.html', WP04P2: 'week-4/02/index.html', WP04P3: 'week-4/03/index.html', WP04P4: 'week-4/04/index.html', WP04P5: 'week-4/05/index.html' });
  // a part's own name still wins over a bare number elsewhere
  const both = partsOf([['1', 'index.html'], ['part1', 'index.html']], (s) => s.join('/'));
  assert.equal(both.WP04P1, 'part1/index.html');
});

test('a file asked for in other letter case or one folder too far up is found inside the submission, once', () => {
  const files = ['Common/MV.js', 'week4/part1/index.html', 'week4/part1/main.js', 'a/util.js', 'b/util.js'];
  assert.equal(findStandIn('/common/mv.js', files), 'Common/MV.js');
  assert.equal(findStandIn('/../Common/MV.js'.replace('/..', ''), files), 'Common/MV.js');
  assert.equal(findStandIn('/x/y/Common/MV.js', files), 'Common/MV.js');
  assert.equal(findStandIn('/util.js', files), null, 'two files of that name, none closer: no guess');
  assert.equal(findStandIn('/a/util.js', files), 'a/util.js');
  assert.equal(findStandIn('/nothing.js', files), null);
  assert.equal(typeOf('x/shader.WGSL'), 'text/plain');
  assert.equal(typeOf('x/page.html'), 'text/html');
});

test('a kept context serves the part open now: its folder at its origin, an empty page between parts, the parts before refused silently', async () => {
  const handins = fileURLToPath(new URL('../fixtures/handins/', import.meta.url));
  const site = { root: `${handins}anna`, origin: 'http://p1.submission.localhost', log: { errors: [], blocked: [], notes: [] }, former: new Set() };
  let handler = null;
  await serveSubmission({ route: async (pattern, h) => { handler = h; } }, site);
  const ask = async (href) => {
    let answer = null;
    const request = { url: () => href, isNavigationRequest: () => false };
    await handler({ request: () => request, fulfill: (r) => { answer = { status: r.status, body: String(r.body) }; }, abort: (why) => { answer = { abort: why }; } });
    return answer;
  };
  const anna = 'Worksheet4/Part1/index.html', bjorn = 'week4/p1/index.html';
  assert.deepEqual(await ask(`http://p1.submission.localhost/${anna}`), { status: 200, body: readFileSync(`${handins}anna/${anna}`, 'utf8') });
  // between two parts: an empty page at a new origin; the origin before is refused without a word
  site.former.add(site.origin);
  Object.assign(site, { root: null, origin: 'http://p2.submission.localhost', log: { errors: [], blocked: [], notes: [] } });
  assert.deepEqual(await ask('http://p2.submission.localhost/'), { status: 200, body: '<!doctype html>' });
  assert.deepEqual(await ask(`http://p1.submission.localhost/${anna}`), { abort: 'blockedbyclient' });
  assert.deepEqual(site.log.blocked, []);
  // the next part: its own folder only; another host is refused and said
  site.former.add(site.origin);
  Object.assign(site, { root: `${handins}bjorn`, origin: 'http://p3.submission.localhost' });
  assert.deepEqual(await ask(`http://p3.submission.localhost/${bjorn}`), { status: 200, body: readFileSync(`${handins}bjorn/${bjorn}`, 'utf8') });
  assert.equal((await ask(`http://p3.submission.localhost/${anna}`)).status, 404);
  assert.deepEqual(site.log.errors, [`missing file: /${anna}`]);
  assert.deepEqual(await ask('http://example.com/x.js'), { abort: 'blockedbyclient' });
  assert.deepEqual(site.log.blocked, ['request: http://example.com/x.js']);
});

test('a control is sorted by what it does to the picture: rounder, coarser, shading, moving', () => {
  const coarse = shotOf(polygon(8)), fine = shotOf(polygon(48));
  const darker = shotOf(polygon(48, { shade: () => [0.4, 0.2, 0.1] }));
  assert.equal(effectOf({ before: coarse, after: fine, later: fine, wasMoving: false }, T), 'finer');
  assert.equal(effectOf({ before: fine, after: coarse, later: coarse, wasMoving: false }, T), 'coarser');
  assert.equal(effectOf({ before: fine, after: darker, later: darker, wasMoving: false }, T), 'shading');
  assert.equal(effectOf({ before: fine, after: fine, later: fine, wasMoving: false }, T), 'none');
  const turned = shotOf(polygon(8, { turn: 0.2 }));
  assert.equal(effectOf({ before: coarse, after: coarse, later: turned, wasMoving: false }, T), 'starts');
  assert.equal(effectOf({ before: coarse, after: turned, later: turned, wasMoving: true }, T), 'stops');
  const blank = shotOf(polygon(8, { r: 0 }));
  assert.equal(effectOf({ before: fine, after: blank, later: blank, wasMoving: false }, T), 'blank');
});

test('names only order the trials: the control named for a role first, unnamed ones next, others last', () => {
  const P = rubric.controls;
  const cs = [{ index: 0, type: 'button', id: 'subdiv-dec', text: '-' }, { index: 1, type: 'button', id: 'makeSquare', text: 'reduce' },
    { index: 2, type: 'button', id: 'go', text: 'Toggle Orbit' }, { index: 3, type: 'button', id: 'b', text: 'Increment' }];
  assert.deepEqual(trialOrder(cs, 'subdivide', P).map((c) => c.index), [0, 3, 1, 2]);
  assert.equal(nameRole(cs[2], P), 'orbit');
  assert.equal(nameRole({ index: 9, type: 'range', id: 'shininessSlider', text: 'Shininess' }, P), 's');
});

test('openMask is a morphological opening by a (2r + 1)² square, outside the picture counting as empty', () => {
  // the definition, pixel by pixel: erode (every pixel of the square set), then dilate (any set)
  const byDefinition = (m, w, h, r) => {
    const at = (src, x, y) => (x >= 0 && y >= 0 && x < w && y < h ? src[y * w + x] : 0);
    const over = (src, all) => {
      const out = new Uint8Array(w * h);
      for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
        let v = all ? 1 : 0;
        for (let dy = -r; dy <= r; dy++) for (let dx = -r; dx <= r; dx++) v = all ? v & at(src, x + dx, y + dy) : v | at(src, x + dx, y + dy);
        out[y * w + x] = v;
      }
      return out;
    };
    return over(over(m, true), false);
  };
  let seed = 7;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (const [w, h, r, density] of [[37, 23, 2, 0.8], [16, 40, 1, 0.6], [30, 30, 3, 0.9], [5, 4, 2, 1]]) {
    const m = Uint8Array.from({ length: w * h }, () => (rnd() < density ? 1 : 0));
    assert.deepEqual([...openMask(m.slice(), w, h, r)], [...byDefinition(m, w, h, r)], `${w}×${h}, r ${r}`);
  }
  // the ones in a part of the picture only (openMask works in the box around them): inside, at an
  // edge, in a corner, none at all
  for (const [w, h, r, bx0, bx1, by0, by1] of [[40, 30, 2, 10, 25, 5, 15], [40, 30, 3, 30, 39, 12, 29], [25, 25, 1, 0, 6, 0, 8], [20, 20, 2, 5, 4, 5, 4]]) {
    const m = new Uint8Array(w * h);
    for (let y = by0; y <= by1; y++) for (let x = bx0; x <= bx1; x++) m[y * w + x] = rnd() < 0.85 ? 1 : 0;
    assert.deepEqual([...openMask(m.slice(), w, h, r)], [...byDefinition(m, w, h, r)], `${w}×${h}, r ${r}, ones in x ${bx0}..${bx1}, y ${by0}..${by1}`);
  }
});

test('diffuseFit finds the light of a diffuse sphere, and its ambient and diffuse terms', () => {
  const l = [-0.7, 0.4, 0.45].map((v, k, a) => v / Math.hypot(...a));
  const shade = (nx, ny, nz) => { const v = 0.45 + 0.5 * Math.max(0, nx * l[0] + ny * l[1] + nz * l[2]); return [v, v, v]; };
  const img = polygon(128, { w: 160, r: 64, shade }); // (the darkest side stays clear of the grey background)
  const fit = diffuseFit(samples(img, analyse(img, T), T), T);
  const angle = (180 / Math.PI) * Math.acos(Math.min(1, fit.light.reduce((a, v, k) => a + v * l[k], 0)));
  assert.ok(angle < 3, `light ${fit.light} is ${angle}° off`);
  assert.ok(fit.r2 > 0.98, `R² ${fit.r2}`);
  assert.ok(Math.abs(fit.ambient - 0.45) < 0.03 && Math.abs(fit.diffuse - 0.5) < 0.05, `ambient ${fit.ambient}, diffuse ${fit.diffuse}`);
  assert.ok(fit.r2 > fit.r2TwoSided, 'one-sided fits a one-sided light better than |n·l|');
});

test('a small tinted highlight that stands out of a clean diffuse fit is a highlight; a plain diffuse sphere has none', () => {
  const l = [0.4, 0.4, 0.82];
  const diffuse = (nx, ny, nz) => 0.1 + 0.5 * Math.max(0, nx * l[0] + ny * l[1] + nz * l[2]);
  const h = [l[0], l[1], l[2] + 1].map((v, k, a) => v / Math.hypot(...a));
  const withSpot = (nx, ny, nz) => {
    const d = diffuse(nx, ny, nz), s = 0.45 * Math.max(0, nx * h[0] + ny * h[1] + nz * h[2]) ** 200;
    return [d + s * 0.1, d + s * 0.5, d + s * 0.3]; // tinted: its brightness rises less than white would
  };
  const plain = polygon(64, { shade: (...n) => [diffuse(...n), diffuse(...n), diffuse(...n)] });
  const spot = polygon(64, { shade: withSpot });
  const fp = diffuseFit(samples(plain, analyse(plain, T), T), T), fs = diffuseFit(samples(spot, analyse(spot, T), T), T);
  assert.equal(highlightSeen(fp, T), false, `plain: rise ${fp.highlightRise}, peak ${fp.highlightPeak}`);
  assert.equal(highlightSeen(fs, T), true, `spot: rise ${fs.highlightRise}, peak ${fs.highlightPeak}, rms ${fs.rms}`);
  assert.ok(fs.highlightPeak < T.highlightPeak, 'the spot is one the peak share alone would miss');
});

test('a highlight at w_h is never read as one at the light (highlightAtLightDegrees), the light 50–63° from the viewer', () => {
  // (the converse is weaker: the diffuse fit takes in much of a highlight at the light, and the rise
  // left above it sits toward the viewer, so a highlight at the light is often not told; on the real
  // hand-ins it was, 7° from the light and 24° from w_h)
  for (const deg of [50, 55, 63]) {
    for (const s of [10, 20]) {
      const l = [Math.sin(deg * Math.PI / 180), 0, Math.cos(deg * Math.PI / 180)];
      const h = [l[0], l[1], l[2] + 1].map((v, k, a) => v / Math.hypot(...a));
      const img = polygon(128, { w: 160, r: 64, shade: (nx, ny, nz) => {
        const d = 0.1 + 0.6 * Math.max(0, nx * l[0] + ny * l[1] + nz * l[2]), sp = 0.4 * Math.max(0, nx * h[0] + ny * h[1] + nz * h[2]) ** s;
        return [d + sp, d + sp, d + sp];
      } });
      const fit = diffuseFit(samples(img, analyse(img, T), T), T);
      const fromHalf = highlightOffset(fit.highlightNormal, fit.light), fromLight = highlightOffset(fit.highlightNormal, fit.light, 0);
      assert.ok(fromHalf - fromLight < T.highlightAtLightDegrees, `light ${deg}°, s = ${s}: ${fromHalf}° from w_h, ${fromLight}° from the light`);
    }
  }
});

test('verdicts from findings: a fail wins, then a review; a mistake costs what the rubric says; reasons worst first, each with its audit id', () => {
  const { checks, sayAs } = checkList({ mistakeVerdict: 'review' });
  sayAs('sphere')('pass', 'round');
  assert.equal(verdictOf(checks), 'pass');
  sayAs('highlight')('mistake', 'no highlight');
  assert.deepEqual(checks.at(-1), { id: 'highlight', level: 'review', reason: 'no highlight' });
  assert.equal(verdictOf(checks), 'review');
  assert.equal(verdictOf(checks, 'drew nothing'), 'fail');
  const strict = checkList({ mistakeVerdict: 'fail' });
  strict.sayAs('highlight')('mistake', 'no highlight');
  assert.equal(verdictOf(strict.checks), 'fail');
  const reasons = reasonsOf({ checks, pageErrors: ['page error: x'] });
  assert.deepEqual(reasons, ['REVIEW: no highlight', 'round', 'the page reported errors: page error: x']);
  assert.deepEqual(findingsOf({ fail: 'drew nothing', failId: 'first-frame', checks }).map((f) => [f.id, f.level]),
    [['first-frame', 'fail'], ['highlight', 'review'], ['sphere', 'pass']]);
});

test("a teacher's labels against the verdicts: agreement, the label × verdict table, the disagreements", () => {
  const labels = parseLabels('submission\tpart\tlabel\tapi\tcontrols\treasons\nann\tWP04P1\tcorrect\tWebGL\t\tfine\nann\tWP04P2\tpartial\tWebGL\t\tcolours (unsure)\n' +
    'bob\tWP04P1\tbroken\tWebGL\t\tblank\nbob\tWP04P3\tcorrect\tWebGL\t\tok\n');
  assert.equal(labels[1].unsure, true);
  const subs = [{ name: 'ann', parts: [{ part: 'WP04P1', verdict: 'pass', reasons: [] }, { part: 'WP04P2', verdict: 'pass', reasons: ['ok'] }] },
    { name: 'bob', parts: [{ part: 'WP04P1', verdict: 'fail', reasons: ['drew nothing'] }] }];
  const a = agreement(labels, subs);
  assert.equal(a.agree, 2);
  assert.equal(a.total, 4);
  assert.deepEqual([a.correctPassed, a.correct, a.partialPassed, a.partial, a.brokenPassed, a.broken], [1, 2, 1, 1, 0, 1]);
  assert.equal(a.confusion.partial.pass, 1);
  assert.equal(a.confusion.correct['not graded'], 1);
  assert.deepEqual(a.missing, ['bob WP04P3']);
  const text = agreementText(a).join('\n');
  assert.match(text, /2 of 4 labelled parts/);
  assert.match(text, /ann WP04P2: labelled partial \(unsure\), graded pass/);
  assert.throws(() => parseLabels('a\tb\n1\t2\n'), /submission, part and label/);
  assert.throws(() => parseLabels('submission\tpart\tlabel\nx\tWP04P1\tgood\n'), /line 2: label "good"/);
});

test('at a high level a level change moves only outline pixels: still finer or coarser, not shading', () => {
  const l5 = shotOf(polygon(32)), l6 = shotOf(polygon(64)); // 8 outline pixels apart
  assert.ok(Math.abs(l5.an.area - l6.an.area) / l6.an.area < 0.003, 'too small a change for the area alone');
  assert.equal(effectOf({ before: l5, after: l6, later: l6, wasMoving: false }, T), 'finer');
  assert.equal(effectOf({ before: l6, after: l5, later: l5, wasMoving: false }, T), 'coarser');
});

/**
 * A page under the page interface, without a browser: a WP04P1-like sphere whose outline has
 * 4·2^level corners and whose colours are 0.5·n + 0.5, with the controls given. `act(c)` or
 * `key(k)` change `state.level`.
 */
function fakePart({ controls, act = () => {}, key = () => {}, level = 1 }) {
  const state = { level };
  // the normals an eye 3 radii away sees (WP04P1 asks for a perspective view), as 0.5·n + 0.5
  const normals = (nx, ny) => {
    const rho = Math.hypot(nx, ny), t = normalAngle(rho, Math.asin(1 / 3)), k = rho ? Math.sin(t) / rho : 0;
    return [0.5 * nx * k + 0.5, 0.5 * ny * k + 0.5, 0.5 * Math.cos(t) + 0.5];
  };
  const pageState = async () => ({ api: 'webgl', frames: 0, adapter: 'ok', draws: 1, vertices: 3, pending: 0, shaderErrors: [], gpuErrors: [], faces: { depthTest: true, culling: true } });
  return {
    state,
    page: {
      state: pageState,
      snap: async () => ({ ...polygon(4 * 2 ** Math.min(state.level, 6), { w: 128, r: 50, shade: normals }), api: 'webgl' }),
      controls: async () => controls,
      click: async (c) => { act(c, state); return { ok: true }; },
      setValue: async () => {},
      press: async (k) => key(k, state),
      tick: pageState,
      setNoCull: async () => {},
      sources: async () => ({ glsl: [], wgsl: [] }),
      errors: () => [],
    },
  };
}

test('drive: Subdivide and Coarsen found by what they do, whatever they are called', async () => {
  const { gradePart } = await import('../../grader/core/grade-part.js');
  const controls = [{ index: 0, type: 'button', id: 'makeSquare', text: 'reduce', events: ['click'] }, { index: 1, type: 'button', id: 'makeSphere', text: 'grow', events: ['click'] }];
  const { page } = fakePart({ controls, act: (c, s) => { s.level = Math.max(0, Math.min(6, s.level + (c.index === 1 ? 1 : -1))); } });
  const out = await gradePart(page, { part: 'WP04P1', rubric });
  assert.equal(verdictOf(out.checks, out.fail), 'pass', out.checks.map((c) => c.reason).join(' | '));
  assert.match(out.controls.subdivide, /makeSphere.*rounder/);
  assert.match(out.controls.coarsen, /makeSquare.*coarser/);
});

test('drive: the level on the arrow keys when no control changes it; no level control at all is a review that says what was tried', async () => {
  const { gradePart } = await import('../../grader/core/grade-part.js');
  const { page } = fakePart({ controls: [], key: (k, s) => { if (k === 'ArrowUp') s.level++; if (k === 'ArrowDown') s.level = Math.max(0, s.level - 1); } });
  const out = await gradePart(page, { part: 'WP04P1', rubric });
  assert.equal(verdictOf(out.checks, out.fail), 'pass', out.checks.map((c) => c.reason).join(' | '));
  assert.match(out.controls.subdivide, /ArrowUp/);
  const none = await gradePart(fakePart({ controls: [] }).page, { part: 'WP04P1', rubric });
  assert.equal(verdictOf(none.checks, none.fail), 'review');
  assert.ok(none.checks.some((c) => /nothing found that makes the sphere finer: .*keys pressed/.test(c.reason)));
});

test('memo: a reading remembered by each object it reads (picture, analysis, thresholds), computed afresh for another or for a non-object', () => {
  let calls = 0;
  const read = memo((img, an, T) => ({ n: ++calls, img, an, T }));
  const img = {}, an = {}, other = {}, T2 = {};
  const first = read(img, an, T2);
  assert.equal(read(img, an, T2), first);
  assert.equal(calls, 1);
  assert.notEqual(read(img, other, T2), first); // (the same picture read with another analysis)
  assert.notEqual(read(img, an, {}), first);
  assert.equal(calls, 3);
  read(img, null, T2);
  read(img, null, T2);
  assert.equal(calls, 5);
  const two = memo((a, b) => [a, b]);
  assert.equal(two(img, T2), two(img, T2));
});
