// The sphere mesh (common/sphere.js): vertex counts, every vertex on the unit sphere, winding
// counter-clockwise seen from outside, a closed mesh, clear errors, one reused array,
// MAX_DEVIATION as measured, and chooseLevel's least level for a silhouette and a shading error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { tetrahedronSphere, sphereMesh, builtLevels, forgetMeshes, vertexCount, vertexBytes, chooseLevel, MAX_DEVIATION, MAX_LEVEL, SHADING_RMSE, SHADING_TABLE, SHININESS, shadingRmse } from '../../common/sphere.js';
import { meshDeviation } from '../../tools/reference/measure.js';

test('vertex count is 4·4^n·3 at every level', () => {
  for (let n = 0; n <= MAX_LEVEL; n++) {
    assert.equal(vertexCount(n), 4 * 4 ** n * 3);
    assert.equal(vertexBytes(n), vertexCount(n) * 12);
    const p = new Float32Array(3 * vertexCount(n));
    assert.equal(tetrahedronSphere(n, p), vertexCount(n));
  }
});

test('every vertex is on the unit sphere; every triangle is non-degenerate and counter-clockwise seen from outside', () => {
  for (let n = 0; n <= MAX_LEVEL; n++) {
    const p = sphereMesh(n);
    assert.equal(p.length, 3 * vertexCount(n));
    let worstRadius = 0, minArea = Infinity, clockwise = 0;
    for (let i = 0; i < p.length; i += 9) {
      for (let v = 0; v < 9; v += 3) {
        worstRadius = Math.max(worstRadius, Math.abs(Math.hypot(p[i + v], p[i + v + 1], p[i + v + 2]) - 1));
      }
      const ux = p[i + 3] - p[i], uy = p[i + 4] - p[i + 1], uz = p[i + 5] - p[i + 2];
      const vx = p[i + 6] - p[i], vy = p[i + 7] - p[i + 1], vz = p[i + 8] - p[i + 2];
      const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      minArea = Math.min(minArea, Math.hypot(nx, ny, nz) / 2);
      // (b-a)×(c-a) points outward (along the centroid) for a counter-clockwise triangle
      const cx = p[i] + p[i + 3] + p[i + 6], cy = p[i + 1] + p[i + 4] + p[i + 7], cz = p[i + 2] + p[i + 5] + p[i + 8];
      if (nx * cx + ny * cy + nz * cz <= 0) clockwise++;
    }
    assert.ok(worstRadius < 1e-6, `level ${n}: a vertex is ${worstRadius} off the unit sphere`);
    assert.equal(clockwise, 0, `level ${n}: ${clockwise} triangles wind clockwise seen from outside`);
    // a level-n triangle has roughly 1/4^n of the tetrahedron face's area (0.41); far from zero
    assert.ok(minArea > 0.05 / 4 ** n, `level ${n}: a triangle has area ${minArea}`);
  }
});

test('the mesh is closed: every edge is shared by exactly two triangles, in opposite directions', () => {
  for (let n = 0; n <= 4; n++) {
    const p = sphereMesh(n);
    const key = (i) => `${p[i].toFixed(5)},${p[i + 1].toFixed(5)},${p[i + 2].toFixed(5)}`;
    const edges = new Map();
    for (let t = 0; t < p.length; t += 9) {
      for (let e = 0; e < 3; e++) {
        const a = key(t + 3 * e), b = key(t + 3 * ((e + 1) % 3));
        edges.set(`${a}|${b}`, (edges.get(`${a}|${b}`) || 0) + 1);
      }
    }
    for (const [edge, count] of edges) {
      const [a, b] = edge.split('|');
      assert.equal(count, 1, `level ${n}: directed edge ${edge} used ${count} times`);
      assert.equal(edges.get(`${b}|${a}`), 1, `level ${n}: edge ${edge} has no twin`);
    }
  }
});

test('bad levels and short arrays throw a clear RangeError', () => {
  assert.throws(() => tetrahedronSphere(-1, new Float32Array(100)), /integer from 0 to 8/);
  assert.throws(() => tetrahedronSphere(1.5, new Float32Array(1000)), RangeError);
  assert.throws(() => tetrahedronSphere(MAX_LEVEL + 1, new Float32Array(1)), RangeError);
  assert.throws(() => tetrahedronSphere(2, new Float32Array(10)), /needs 576 floats/);
});

test('sphereMesh builds each level once and gives back the same array', () => {
  forgetMeshes();
  const a = sphereMesh(3);
  assert.deepEqual(builtLevels(), [false, false, false, true, false, false, false, false, false], 'only the level asked for (no idle time in Node)');
  assert.equal(sphereMesh(2).length, 3 * vertexCount(2));
  assert.equal(sphereMesh(3), a, 'the second visit is the same array');
  assert.throws(() => sphereMesh(9), /integer from 0 to 8/);
  assert.throws(() => sphereMesh(-1), RangeError);
});

test('sphereMesh builds the neighbouring levels ahead, when idle after the click\'s upload and frame', (t) => {
  t.mock.timers.enable({ apis: ['setTimeout'] });
  const idle = [];
  globalThis.requestIdleCallback = (callback) => idle.push(callback);
  const later = () => t.mock.timers.tick(25); // two calls: past the 50 ms the click's frame gets
  try {
    forgetMeshes();
    sphereMesh(4);
    later();
    assert.equal(idle.length, 0, 'no idle callback is asked for while the click\'s upload and frame may still be under way');
    later();
    assert.equal(idle.length, 2, 'levels 5 and 3 are queued');
    sphereMesh(4);
    later();
    later();
    assert.equal(idle.length, 2, 'queued once, not again on the next call');
    for (const callback of idle.splice(0)) callback();
    assert.deepEqual(builtLevels(), [false, false, false, true, true, true, false, false, false]);
    const five = sphereMesh(5);
    const fresh = new Float32Array(five.length);
    tetrahedronSphere(5, fresh);
    assert.deepEqual(five, fresh, 'the level built ahead is the sphere at that level');
    sphereMesh(8);
    later();
    later();
    assert.equal(idle.length, 2, 'level 6 from 5, and level 7 from 8; nothing above the top');
  } finally {
    delete globalThis.requestIdleCallback;
    forgetMeshes();
  }
});

test('MAX_DEVIATION is what the mesh measures: 1 − the least distance to a triangle plane', () => {
  for (let n = 0; n <= MAX_LEVEL; n++) {
    const measured = meshDeviation(sphereMesh(n));
    assert.ok(Math.abs(measured - MAX_DEVIATION[n]) / MAX_DEVIATION[n] < 2e-3, `level ${n}: ${measured} vs ${MAX_DEVIATION[n]}`);
  }
});

test('shadingRmse reads the table at the material\'s shininess, the larger of two rows between them', () => {
  const k40 = SHININESS.indexOf(40), k80 = SHININESS.indexOf(80);
  assert.equal(shadingRmse('gouraud', 4, 40), SHADING_TABLE.gouraud[k40][4]);
  assert.equal(shadingRmse('gouraud', 4), SHADING_TABLE.gouraud[k40][4], 's = 40 by default');
  assert.equal(shadingRmse('phong', 3, 60), Math.max(SHADING_TABLE.phong[k40][3], SHADING_TABLE.phong[k80][3]));
  assert.equal(shadingRmse('phong', 5, 1e4), SHADING_TABLE.phong.at(-1)[5], 'above the last row: the last row');
  assert.equal(shadingRmse('diffuse', 2, 500), SHADING_TABLE.diffuse[2], 'no shininess in diffuse light');
  assert.deepEqual(SHADING_RMSE.phong, SHADING_TABLE.phong[k40]);
  assert.throws(() => shadingRmse('flat', 2), /one of diffuse, gouraud, phong/);
  // the material sets the level: at 128 px Gouraud shading needs level 6 for s = 40, 5 for s = 10
  assert.equal(chooseLevel(128, 45, 3, { shading: 'gouraud', shininess: 40 }).level, 6);
  assert.equal(chooseLevel(128, 45, 3, { shading: 'gouraud', shininess: 10 }).level, 5);
});

test('chooseLevel: the least level with a silhouette error under half a pixel', () => {
  // eye 3 from the centre, fovy 45°: 512 px needs level 6, 128 px level 5, 32 px level 4
  assert.equal(chooseLevel(512, 45, 3).level, 6);
  assert.equal(chooseLevel(128, 45, 3).level, 5);
  assert.equal(chooseLevel(32, 45, 3).level, 4);
  for (const h of [16, 64, 128, 256, 512, 1024, 2048]) {
    const { level, errorPx, radiusPx } = chooseLevel(h, 45, 3);
    assert.ok(errorPx < 0.5 || level === MAX_LEVEL);
    if (level > 0) assert.ok(chooseLevel(h, 45, 3, { tolerancePx: 0.5 }).errorPx * MAX_DEVIATION[level - 1] / MAX_DEVIATION[level] >= 0.5);
    // the silhouette radius: tan(asin(1/3)) / tan(22.5°) of half the height
    assert.ok(Math.abs(radiusPx - (h / 2) * Math.tan(Math.asin(1 / 3)) / Math.tan(Math.PI / 8)) < 1e-9);
  }
  assert.equal(chooseLevel(1e6, 45, 3).level, MAX_LEVEL, 'a huge canvas gets the most the page offers');
});

test('chooseLevel with a shading method: also the least level whose shading error is within tolerance', () => {
  for (const table of Object.values(SHADING_RMSE)) {
    assert.equal(table.length, MAX_LEVEL + 1);
    for (let k = 1; k < table.length; k++) assert.ok(table[k] <= table[k - 1], 'the error never grows with the level');
  }
  // Gouraud highlights need level 6 at any size; diffuse Gouraud and Phong shading level 5
  assert.deepEqual([32, 128, 256, 512].map((h) => chooseLevel(h, 45, 3, { shading: 'gouraud' }).level), [6, 6, 6, 6]);
  assert.deepEqual([32, 128, 256, 512].map((h) => chooseLevel(h, 45, 3, { shading: 'phong' }).level), [5, 5, 5, 6]);
  assert.deepEqual([32, 128, 256, 512].map((h) => chooseLevel(h, 45, 3, { shading: 'diffuse' }).level), [5, 5, 5, 6]);
  assert.equal(chooseLevel(128, 45, 3, { shading: 'gouraud' }).limit, 'shading');
  assert.equal(chooseLevel(128, 45, 3, { shading: 'phong' }).limit, 'silhouette');
  assert.equal(chooseLevel(128, 45, 3, { shading: 'gouraud' }).rmse, SHADING_RMSE.gouraud[6]);
  assert.equal(chooseLevel(128, 45, 3).rmse, null);
  // a looser tolerance lets Gouraud down to the silhouette's level; none at all is never met
  assert.equal(chooseLevel(128, 45, 3, { shading: 'gouraud', toleranceRmse: 2 }).level, 5);
  assert.deepEqual([chooseLevel(128, 45, 3, { shading: 'phong', toleranceRmse: 0 }).level, chooseLevel(128, 45, 3, { shading: 'phong', toleranceRmse: 0 }).limit], [MAX_LEVEL, 'max']);
  assert.throws(() => chooseLevel(128, 45, 3, { shading: 'flat' }), /shading must be one of diffuse, gouraud, phong/);
});
