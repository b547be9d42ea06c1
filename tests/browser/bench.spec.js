// npm run bench -- --quick, checked for shape and sanity (never for speed), and the level chooser
// checked against the exact reference.
import { spawnSync } from 'node:child_process';
import { readFileSync, mkdtempSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect, open, canvasPixels, andDraw, errorAgainstReference } from './fixtures.js';
import { renderReference } from '../../common/exact-render.js';
import { silhouetteErrorPx } from '../../tools/reference/measure.js';
import { chooseLevel } from '../../common/sphere.js';
import { EDGE_CASES } from '../../tools/edge-cases.js';

test('bench --quick: every method and level in WebGL 2 and WebGPU, errors that fall with the level, an exact impostor', async ({ api }) => {
  test.skip(api !== 'webgl2', 'the bench picks its own context; once is enough');
  // a bound on a hang, not on speed: under a loaded machine the quick bench took up to 114 s here
  test.setTimeout(330_000);
  const out = mkdtempSync(path.join(os.tmpdir(), 'bench-'));
  const run = spawnSync(process.execPath, ['tools/bench.js', '--quick', '--out', out], { encoding: 'utf8', timeout: 300_000 });
  expect(run.status, run.stderr).toBe(0);
  expect(run.stderr).toMatch(/\[bench\]/); // a progress line
  const r = JSON.parse(readFileSync(path.join(out, 'bench.json'), 'utf8'));
  expect(r.meta.renderer).toBeTruthy();
  expect(r.meta.machine).toBeTruthy();
  expect(r.meta.browser).toMatch(/Chromium/);
  expect(r.meta.rendererWebGPU).toBeTruthy();
  expect(new Set(r.frames.map((f) => f.api))).toEqual(new Set(['webgl2', 'webgpu']));
  for (const benchApi of ['webgl2', 'webgpu']) {
    for (const method of ['flat', 'gouraud', 'phong']) {
      const rows = r.frames.filter((f) => f.api === benchApi && f.method === method).sort((a, b) => a.level - b.level);
      expect(rows.map((f) => f.level), `${benchApi} ${method}`).toEqual([0, 1, 2, 3, 4, 5]);
      for (const f of rows) {
        expect(f.msMedian).toBeGreaterThan(0);
        expect(f.vertices).toBe(12 * 4 ** f.level);
      }
      if (method !== 'flat') {
        for (let k = 1; k < rows.length; k++) expect(rows[k].rmse, `${benchApi} ${method} level ${k}`).toBeLessThan(rows[k - 1].rmse);
      }
      expect(rows[5].silhouetteErrorPx).toBeLessThan(0.5);
    }
    const impostor = r.frames.find((f) => f.api === benchApi && f.method === 'impostor');
    expect(impostor.rmse * 255, benchApi).toBeLessThan(0.5);
    expect(impostor.silhouetteMismatch).toBeLessThanOrEqual(2);
  }
  // the WGSL twins draw what the GLSL draws: the same error, within ½ of an 8-bit step, at every level
  for (const f of r.frames.filter((x) => x.api === 'webgpu')) {
    const twin = r.frames.find((x) => x.api === 'webgl2' && x.method === f.method && x.level === f.level && x.size === f.size);
    expect(Math.abs(f.rmse - twin.rmse) * 255, `${f.method} level ${f.level}`).toBeLessThan(0.5);
  }
  expect(r.levelChange.map((l) => l.level)).toEqual([0, 1, 2, 3, 4, 5, 6]);
  for (const l of r.levelChange) {
    expect(l.oursMs * l.coldMs * l.classicMs * l.boundMs).toBeGreaterThan(0);
    expect(l.gpuOursMs * l.gpuColdMs * l.gpuClassicMs * l.gpuBoundMs, `WebGPU level ${l.level}`).toBeGreaterThan(0);
  }
  expect(r.indexed.every((x) => x.pixelsEqual)).toBe(true);
  expect(r.indexed.map((x) => x.vertices)).toEqual([0, 1, 2, 3, 4, 5, 6].map((n) => 2 * 4 ** n + 2));
  const phong = r.stability.find((s) => s.method === 'phong' && s.level === 5);
  const gouraud = r.stability.find((s) => s.method === 'gouraud' && s.level === 3);
  expect(phong.peakErrorRms).toBeLessThan(gouraud.peakErrorRms);
  // the edge-case table: a quick run measures the first two cases (edge-cases.spec.js holds them
  // all, in every API) for both methods, and no NaN-black pixel anywhere
  expect(r.edgeCases.map((e) => `${e.case} ${e.method}`)).toEqual(EDGE_CASES.slice(0, 2).flatMap((c) => [`${c.name} gouraud`, `${c.name} phong`]));
  expect(r.edgeCases.every((e) => e.nanLike === 0)).toBe(true);
  expect(readFileSync(path.join(out, 'bench.csv'), 'utf8')).toMatch(/^# .*\napi,method,level,size,[^]*\nwebgpu,phong,5,/);
});

for (const size of [128, 256]) {
  test(`the chosen level at ${size} px keeps the silhouette within ½ px; one level less does not`, async ({ page }) => {
    const s = await open(page, '/WP04P5/', { orbit: 0, angle: 0, size });
    await expect(page.locator('#info')).toContainText(`the least level that looks round at ${size} px`);
    const ref = renderReference(s, size, size);
    expect(silhouetteErrorPx(await canvasPixels(page), ref, s)).toBeLessThan(0.5);
    const coarser = await andDraw(page, () => page.getByRole('button', { name: 'Coarsen' }).click());
    expect(coarser.level).toBe(s.level - 1);
    expect(silhouetteErrorPx(await canvasPixels(page), ref, coarser)).toBeGreaterThan(0.5);
  });
}

for (const [step, shading] of [['WP04P3', 'diffuse'], ['WP04P4', 'gouraud'], ['WP04P5', 'phong']]) {
  test(`${step}'s chosen level at 128 px shades within 1/255 (silhouette aside); where shading set it, one level less does not`, async ({ page }) => {
    const shadingError = async () => (await errorAgainstReference(page, { interior: 'both' })).rmse * 255;
    const s = await open(page, `/${step}/`, { orbit: 0, angle: 0, size: 128 });
    const rule = chooseLevel(128, 45, 3, { shading });
    expect(s.level).toBe(rule.level);
    await expect(page.locator('#info')).toContainText('shades within 1/255');
    expect(await shadingError()).toBeLessThanOrEqual(1);
    if (rule.limit === 'shading') {
      await andDraw(page, () => page.getByRole('button', { name: 'Coarsen' }).click());
      expect(await shadingError()).toBeGreaterThan(1);
    }
  });
}

test('the lab page draws its charts and tables from the committed results', async ({ page }) => {
  await page.goto('/lab/');
  await page.waitForFunction(() => window.labReady);
  await expect(page.locator('#speed-accuracy canvas')).toBeVisible();
  await expect(page.locator('#claim p')).toHaveCount(4);
  await expect(page.locator('#claim')).toContainText('Gouraud (WP04P4)');
  for (const id of ['api-table', 'level-table', 'stability', 'indexed', 'edge-cases', 'needs']) expect(await page.locator(`#${id} tr`).count(), id).toBeGreaterThan(2);
  // the level each material needs, from the calibrated table: s = 40 at 128 px is WP04P4's default level
  await expect(page.locator('#needs tr', { hasText: 's = 40' })).toContainText(`s = 40${chooseLevel(128, 45, 3, { shading: 'gouraud' }).level}`);
  await expect(page.locator('#indexed')).not.toContainText('NO');
  await expect(page.locator('#level-table')).toContainText('WebGPU ours ms');
  await expect(page.locator('#speed-accuracy canvas')).toHaveAttribute('aria-label', /milliseconds per frame/);
  await page.goto('/');
  await page.getByRole('link', { name: 'the lab' }).click();
  await expect(page).toHaveURL(/\/lab\/$/);
});
