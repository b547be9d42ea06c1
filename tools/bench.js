#!/usr/bin/env node
// npm run bench: speed against accuracy, method by method and level by level, in one Chromium run.
// Writes out/bench/bench.json and .csv; a full run also publishes lab/results.json and the chart
// lab/speed-accuracy.png that the lab page and the README show.
//
// It drives lab/bench.html (WebGL 2) and lab/bench-gpu.html (WebGPU) through their window.bench
// interfaces (documented in lab/bench-page.js and lab/bench-gpu.js), in one Chromium with the
// WebGPU flags, and the exercise pages themselves for the edge cases. The steps, in the order
// main() runs them:
//   measureFrames        ms per frame and error against the reference, every method and level, per API
//   measureLevelChanges  ms per level change (ours, classic, bound) and the indexed layout, WebGL
//   measureGPULevelChanges  the same level change in WebGPU (writeBuffer), beside the WebGL one
//   measureStability     how the highlight moves over an orbit, Gouraud against Phong shading
//   measureEdgeCases     where each method breaks, on WP04P4 and WP04P5
//   writeResults, publishResults
import { mkdirSync, writeFileSync, copyFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { renderReference } from '../common/exact-render.js';
import { compareToReference, shadingError, silhouetteErrorPx } from './reference/measure.js';
import { toRGBA8 } from './reference/png.js';
import { PNG } from 'pngjs';
import { canvasScreenshot, startServer } from './browser.js';
import { CHROMIUM_ARGS, WEBGPU_ARGS, launchChromium } from '../grader/node/run/chromium.js';
import { parseOptions, progressLine, runCommand } from './cli.js';
import { chooseLevel } from '../common/sphere.js';
import { EDGE_CASES, STEP } from './edge-cases.js';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const HELP = `usage: npm run bench -- [--quick] [--out DIR] [--no-publish]
Measures flat, Gouraud (WP04P4), Phong shading (WP04P5) and an exact impostor at every level,
in WebGL 2 and in WebGPU: ms per frame and error against the exact reference, level-change time
against the classic and the bound baselines; then (WebGL 2) the indexed layout and highlight
stability over an orbit.
  --quick       levels 0-5, one 128 px canvas, fewer frames, the first 2 edge cases (npm test's
                edge-cases spec holds them all); does not publish
  --out DIR     where bench.json and bench.csv go (default out/bench)
  --no-publish  do not update lab/results.json and lab/speed-accuracy.png (a full run does)
exit codes: 0 done, 1 it failed (the message says why), 2 bad usage`;

const OPTIONS = { quick: { type: 'boolean' }, out: { type: 'string' }, 'no-publish': { type: 'boolean' } };

/** How much to measure: the quick run is for tests and a first look, the full one is published. */
const PLANS = {
  quick: { sizes: [128], maxLevel: 5, frames: 3, warmup: 1, repeats: 2, changeRepeats: 3, orbitSize: 128, angles: 12, changeLevels: 6, edgeCases: 2 },
  full: { sizes: [256, 512], maxLevel: 8, frames: 15, warmup: 3, repeats: 5, changeRepeats: 15, orbitSize: 256, angles: 90, changeLevels: 8, edgeCases: EDGE_CASES.length },
};
const METHODS = ['flat', 'gouraud', 'phong'];
/** The stability run's material: its highlight never clamps (kd + ks + ka La = 0.94). */
const STABLE = { kd: 0.3, ka: 0.3, ks: 0.6, s: 40 };

// ---------------------------------------------------------------------------------------------
// Small helpers: statistics, progress, pictures
// ---------------------------------------------------------------------------------------------

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const quantile = (xs, q) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.round(q * (s.length - 1))))];
};
const round = (x, d = 4) => (x === null || x === undefined ? x : Number(x.toFixed(d)));
const rms = (xs) => Math.sqrt(xs.reduce((s, x) => s + x * x, 0) / xs.length);

const progress = progressLine('bench');

/** window.bench.capture()'s base64 RGBA as an image for the error measures. */
function decode(base64, width, height) {
  return { width, height, data: Buffer.from(base64, 'base64') };
}

// The highlight: its peak (the brightest pixel, 0..1) and where it is (the centroid of the pixels
// within 2/255 of the peak), over the sphere's interior only (the reference's coverage shrunk by
// two pixels, so no background pixel at a coarse mesh's edge counts).
function interiorMask(ref) {
  const { width, height, coverage } = ref;
  const mask = new Uint8Array(coverage.length);
  for (let j = 2; j < height - 2; j++) {
    for (let i = 2; i < width - 2; i++) {
      let all = 1;
      for (let dj = -2; dj <= 2 && all; dj++) for (let di = -2; di <= 2; di++) if (!coverage[(j + dj) * width + i + di]) { all = 0; break; }
      mask[j * width + i] = all;
    }
  }
  return mask;
}
function highlight(image, mask) {
  let peak = 0;
  const lum = (o) => (image.data[o] + image.data[o + 1] + image.data[o + 2]) / (3 * 255);
  for (let p = 0; p < mask.length; p++) if (mask[p]) peak = Math.max(peak, lum(4 * p));
  let sx = 0, sy = 0, n = 0;
  for (let p = 0; p < mask.length; p++) {
    if (mask[p] && lum(4 * p) >= peak - 2 / 255) { sx += p % image.width; sy += Math.floor(p / image.width); n++; }
  }
  return { peak, x: sx / n, y: sy / n };
}

/** The bench page of each API. */
const BENCH_PAGES = { webgl2: 'bench.html', webgpu: 'bench-gpu.html' };

/** Opens the bench page of `api` with a size × size canvas (or target) and waits for window.bench. */
async function openBench(browser, base, size, api = 'webgl2') {
  const page = await browser.newPage({ viewport: { width: size + 40, height: size + 200 }, deviceScaleFactor: 1 });
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  await page.goto(`${base}/lab/${BENCH_PAGES[api]}?size=${size}`);
  await page.waitForFunction(() => window.benchReady || document.querySelector('#messages .error'), null, { timeout: 60_000 });
  const error = await page.evaluate(() => document.querySelector('#messages .error')?.textContent);
  if (error || problems.length) throw new Error(`the bench page failed: ${error || problems.join('; ')}`);
  return page;
}

// ---------------------------------------------------------------------------------------------
// The measurements
// ---------------------------------------------------------------------------------------------

/**
 * One method on the mesh the page holds: ms per frame (median and quartiles) and the error
 * against the exact reference `ref` of `refScene`.
 */
async function measureMethod(page, plan, { api, method, level, size, ref, refScene }) {
  progress(`${api} ${size}px level ${level} ${method}`);
  const times = await page.evaluate(([m, f, w]) => { window.bench.setMethod(m); return window.bench.frameTimes(f, w); }, [method, plan.frames, plan.warmup]);
  const img = decode(await page.evaluate(() => window.bench.capture()), size, size);
  const stats = compareToReference(img, ref);
  return {
    api, method, level, size, msMedian: round(median(times)), msP25: round(quantile(times, 0.25)), msP75: round(quantile(times, 0.75)),
    rmse: round(stats.rmse, 6), maxError: round(stats.maxError, 6), silhouetteMismatch: stats.silhouetteMismatch,
    // the measure of common/shading-table.js (npm run calibrate): silhouette aside, in 8-bit steps
    shadingError: round(shadingError(img, ref), 3),
    silhouetteErrorPx: round(silhouetteErrorPx(img, ref, refScene), 3), spherePixels: stats.spherePixels,
  };
}

/**
 * Every method at every level, then the impostor, on one canvas size, on the bench page of `api`
 * (webgl2 or webgpu; the page's calls are awaited either way): the rows of results.frames.
 */
async function measureFrames(page, plan, size, api) {
  const refScene = await page.evaluate(() => window.bench.scene());
  const ref = renderReference(refScene, size, size);
  const rows = [];
  for (let level = 0; level <= plan.maxLevel; level++) {
    const mesh = await page.evaluate(([l]) => window.bench.setMesh(l), [level]);
    for (const method of METHODS) {
      rows.push({ ...(await measureMethod(page, plan, { api, method, level, size, ref, refScene })), vertices: mesh.vertices, bytes: mesh.bytes });
    }
  }
  rows.push({ ...(await measureMethod(page, plan, { api, method: 'impostor', level: null, size, ref, refScene })), vertices: 6, bytes: 48 });
  return rows;
}

/** The level each exercise picks for a canvas; flat shading has no page, so the silhouette alone. */
function chosenLevels(size) {
  return { flat: chooseLevel(size, 45, 3).level, gouraud: chooseLevel(size, 45, 3, { shading: 'gouraud' }).level,
    phong: chooseLevel(size, 45, 3, { shading: 'phong' }).level };
}

/**
 * Level changes (ours against the classic and the bound baselines) and the indexed layout against
 * drawArrays (time to change, time per frame, the same pixels), level by level.
 * @returns {Promise<{levelChange: object[], indexed: object[]}>}
 */
async function measureLevelChanges(page, plan) {
  const levelChange = [], indexed = [];
  for (let level = 0; level <= plan.changeLevels; level++) {
    progress(`level change ${level}`);
    const t = await page.evaluate(([l, r]) => window.bench.levelChange(l, r), [level, plan.changeRepeats]);
    const ours = median(t.ours), cold = median(t.cold), classic = median(t.classic), bound = median(t.bound);
    levelChange.push({ level, vertices: 12 * 4 ** level, bytes: 36 * 4 ** level * 4,
      oursMs: round(ours), coldMs: round(cold), classicMs: round(classic), boundMs: round(bound),
      classicOverOurs: round(classic / ours, 2), oursOverBound: round(ours / bound, 2), coldOverBound: round(cold / bound, 2) });

    progress(`indexed ${level}`);
    await page.evaluate(([l]) => window.bench.setMesh(l, 'arrays'), [level]);
    const arraysTimes = await page.evaluate(([f, w]) => { window.bench.setMethod('phong'); return window.bench.frameTimes(f, w); }, [plan.frames, plan.warmup]);
    const arraysImg = await page.evaluate(() => window.bench.capture());
    const change = await page.evaluate(([l, r]) => window.bench.indexedChange(l, r), [level, plan.repeats]);
    const info = await page.evaluate(([l]) => window.bench.setMesh(l, 'indexed'), [level]);
    const indexedTimes = await page.evaluate(([f, w]) => window.bench.frameTimes(f, w), [plan.frames, plan.warmup]);
    const indexedImg = await page.evaluate(() => window.bench.capture());
    indexed.push({ level, vertices: info.vertices, indexBits: info.indexBits, bytes: info.bytes, bytesArrays: 36 * 4 ** level * 4,
      changeMs: round(median(change)), changeMsArrays: round(ours), frameMs: round(median(indexedTimes)),
      frameMsArrays: round(median(arraysTimes)), pixelsEqual: indexedImg === arraysImg });
    await page.evaluate(([l]) => window.bench.setMesh(l, 'arrays'), [level]);
  }
  return { levelChange, indexed };
}

/**
 * The level change in WebGPU, level by level, added to the WebGL rows of `levelChange`: ours
 * (a click: the level built ahead, one queue.writeBuffer into the one buffer made for the
 * largest level), cold (built on the spot), classic and
 * the copy-only bound, each timed to the end of the upload (queue.onSubmittedWorkDone).
 */
async function measureGPULevelChanges(page, plan, levelChange) {
  for (const row of levelChange) {
    progress(`webgpu level change ${row.level}`);
    const t = await page.evaluate(([l, r]) => window.bench.levelChange(l, r), [row.level, plan.changeRepeats]);
    const ours = median(t.ours), cold = median(t.cold), classic = median(t.classic), bound = median(t.bound);
    Object.assign(row, { gpuOursMs: round(ours), gpuColdMs: round(cold), gpuClassicMs: round(classic), gpuBoundMs: round(bound),
      gpuClassicOverOurs: round(classic / ours, 2), gpuOursOverBound: round(ours / bound, 2), gpuColdOverBound: round(cold / bound, 2) });
  }
}

/**
 * Temporal stability over a full orbit, with the STABLE material, counted at the angles where the
 * exact highlight shows: how far the highlight's peak and position stray from the exact ones, and
 * the largest jump of the peak's error from one angle to the next. The rows of results.stability.
 */
async function measureStability(browser, base, plan) {
  const size = plan.orbitSize;
  const page = await openBench(browser, base, size);
  const chosen = chooseLevel(size, 45, 3).level;
  await page.evaluate(([m]) => window.bench.setMaterial(m), [STABLE]);
  const refs = [];
  for (let k = 0; k < plan.angles; k++) {
    await page.evaluate(([x]) => window.bench.setAngle(x), [(2 * Math.PI * k) / plan.angles]);
    const ref = renderReference(await page.evaluate(() => window.bench.scene()), size, size);
    const mask = interiorMask(ref);
    const h = highlight({ width: ref.width, data: toRGBA8(ref) }, mask);
    refs.push({ mask, h, shows: h.peak > STABLE.kd + STABLE.ka * 0.2 + 0.05 });
    progress(`orbit reference ${k + 1}/${plan.angles}`);
  }
  const rows = [];
  for (const level of [...new Set([3, chosen])]) {
    await page.evaluate(([l]) => window.bench.setMesh(l), [level]);
    for (const method of ['gouraud', 'phong']) {
      await page.evaluate(([m]) => window.bench.setMethod(m), [method]);
      const peaks = [], pos = [], jumps = [];
      let prev = null;
      for (let k = 0; k < plan.angles; k++) {
        progress(`orbit ${method} level ${level} ${k + 1}/${plan.angles}`);
        if (!refs[k].shows) { prev = null; continue; }
        await page.evaluate(([x]) => window.bench.setAngle(x), [(2 * Math.PI * k) / plan.angles]);
        const img = decode(await page.evaluate(() => window.bench.capture()), size, size);
        const h = highlight(img, refs[k].mask);
        const e = refs[k].h;
        peaks.push(h.peak - e.peak);
        pos.push(Math.hypot(h.x - e.x, h.y - e.y));
        if (prev) jumps.push(Math.abs((h.peak - prev.h.peak) - (e.peak - prev.e.peak)));
        prev = { h, e };
      }
      rows.push({ method, level, size, angles: plan.angles, anglesWithHighlight: peaks.length,
        material: STABLE, peakErrorRms: round(rms(peaks), 5), peakErrorMax: round(Math.max(...peaks.map(Math.abs)), 5),
        positionErrorRmsPx: round(rms(pos), 3), positionErrorMaxPx: round(Math.max(...pos), 3),
        peakJumpMax: round(Math.max(0, ...jumps), 5) });
    }
  }
  await page.close();
  return rows;
}

/** Where each method breaks: the plan's edge cases (all in a full run) on WP04P4 and WP04P5. The rows of results.edgeCases. */
async function measureEdgeCases(browser, base, plan) {
  const page = await browser.newPage({ viewport: { width: 900, height: 900 }, deviceScaleFactor: 1 });
  const rows = [];
  for (const c of EDGE_CASES.slice(0, plan.edgeCases)) {
    for (const step of ['WP04P4', 'WP04P5']) {
      progress(`edge case ${c.name} ${step}`);
      const query = new URLSearchParams({ orbit: 0, angle: 0, size: 128, ...c.params });
      await page.goto(`${base}/${step}/?${query}`);
      await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
      const scene = await page.evaluate(() => window.scene);
      const img = PNG.sync.read(await canvasScreenshot(page));
      const stats = compareToReference(img, renderReference(scene, img.width, img.height));
      const why = [stats.nanLike && 'NaN-black pixels', stats.saturated && 'saturates', stats.rmse > 2 * STEP && 'error over 2/255'].filter(Boolean);
      rows.push({ case: c.name, method: step === 'WP04P4' ? 'gouraud' : 'phong', level: scene.level,
        rmse: round(stats.rmse, 6), maxError: round(stats.maxError, 6), silhouetteMismatch: stats.silhouetteMismatch,
        nanLike: stats.nanLike, saturated: stats.saturated, fails: why.join(', ') });
    }
  }
  await page.close();
  return rows;
}

// ---------------------------------------------------------------------------------------------
// Results
// ---------------------------------------------------------------------------------------------

/** Writes bench.json and bench.csv (the frames) into outDir; returns bench.json's path. */
function writeResults(results, outDir) {
  mkdirSync(outDir, { recursive: true });
  const jsonPath = path.join(outDir, 'bench.json');
  writeFileSync(jsonPath, JSON.stringify(results, null, 1));
  const cols = ['api', 'method', 'level', 'size', 'vertices', 'bytes', 'msMedian', 'msP25', 'msP75', 'rmse', 'maxError', 'silhouetteMismatch', 'silhouetteErrorPx'];
  const csv = [`# ${results.meta.machine}; ${results.meta.browser}; ${results.meta.renderer}`, cols.join(',')]
    .concat(results.frames.map((r) => cols.map((c) => r[c] ?? '').join(','))).join('\n') + '\n';
  writeFileSync(path.join(outDir, 'bench.csv'), csv);
  return jsonPath;
}

/** Copies bench.json to lab/results.json and screenshots the lab page's chart to lab/speed-accuracy.png. */
async function publishResults(browser, base, jsonPath) {
  copyFileSync(jsonPath, path.join(root, 'lab/results.json'));
  progress('chart PNG');
  const chartPage = await browser.newPage({ viewport: { width: 900, height: 1400 }, deviceScaleFactor: 1 });
  await chartPage.goto(`${base}/lab/`);
  await chartPage.waitForFunction(() => window.labReady);
  await chartPage.locator('#speed-accuracy').screenshot({ path: path.join(root, 'lab/speed-accuracy.png') });
  await chartPage.close();
}

// ---------------------------------------------------------------------------------------------
// The command
// ---------------------------------------------------------------------------------------------

/** The options, checked: { quick, outDir, publish }, or { help: true }. Throws a UsageError. */
function readOptions(argv) {
  const opt = parseOptions(argv, OPTIONS);
  if (opt.help) return opt;
  const quick = !!opt.quick;
  return { quick, outDir: path.resolve(opt.out ?? path.join(root, 'out/bench')), publish: !quick && !opt['no-publish'] };
}

/** The whole bench, every measurement in one browser; returns the results as bench.json holds them. */
async function runBench(browser, base, { plan, quick, started }) {
  const loadAtStart = os.loadavg()[0];
  const results = { meta: {}, chosen: {}, frames: [], levelChange: [], indexed: [], stability: [], edgeCases: [] };
  for (const size of plan.sizes) {
    const page = await openBench(browser, base, size);
    if (!results.meta.renderer) {
      Object.assign(results.meta, await page.evaluate(() => ({ renderer: window.bench.renderer, api: window.bench.api })));
    }
    results.chosen[size] = chosenLevels(size);
    results.frames.push(...(await measureFrames(page, plan, size, 'webgl2')));
    if (size === plan.sizes[0]) { // level changes and the indexed layout, on the smaller canvas
      const { levelChange, indexed } = await measureLevelChanges(page, plan);
      results.levelChange.push(...levelChange);
      results.indexed.push(...indexed);
    }
    const glError = await page.evaluate(() => window.bench.glError());
    if (glError) throw new Error(`gl.getError() = 0x${glError.toString(16)} during the bench`);
    await page.close();

    // The same in WebGPU, in the same browser
    const gpuPage = await openBench(browser, base, size, 'webgpu');
    results.meta.rendererWebGPU ??= await gpuPage.evaluate(() => window.bench.renderer);
    results.frames.push(...(await measureFrames(gpuPage, plan, size, 'webgpu')));
    if (size === plan.sizes[0]) await measureGPULevelChanges(gpuPage, plan, results.levelChange);
    const gpuErrors = await gpuPage.evaluate(() => window.bench.gpuErrors());
    if (gpuErrors.length) throw new Error(`WebGPU errors during the bench: ${gpuErrors.join('; ')}`);
    await gpuPage.close();
  }
  results.stability = await measureStability(browser, base, plan);
  results.edgeCases = await measureEdgeCases(browser, base, plan);
  results.meta = {
    ...results.meta, date: new Date().toISOString(), quick, seconds: Math.round((Date.now() - started) / 1000),
    machine: `${os.cpus().length} × ${os.cpus()[0]?.model || 'cpu'}, ${Math.round(os.totalmem() / 2 ** 30)} GiB, ${os.platform()} ${os.release()}`,
    browser: `Chromium ${browser.version()}`, node: process.version,
    // how busy the machine was (1-minute load average, at the start and the end): noise, not speed
    load: [loadAtStart, os.loadavg()[0]].map((x) => round(x, 1)),
    view: 'eye (0,0,3) orbiting, fovy 45°, directional light (0,0,-1,0), kd 0.8, ks 0.5, s 40, Le 1, La 0.2, Phong',
  };
  return results;
}

/** Runs the whole bench with the options read; returns its exit code. */
async function bench(opt) {
  const { quick, outDir, publish } = opt;
  const started = Date.now();
  const server = await startServer(root);
  let browser = null;
  try {
    browser = await launchChromium({ args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] });
    const results = await runBench(browser, server.url, { plan: quick ? PLANS.quick : PLANS.full, quick, started });
    const jsonPath = writeResults(results, outDir);
    if (publish) await publishResults(browser, server.url, jsonPath);
    process.stderr.write(`\r[bench] done in ${results.meta.seconds} s`.padEnd(90) + '\n');
    console.log(`bench: wrote ${jsonPath} and bench.csv${publish ? ', lab/results.json and lab/speed-accuracy.png' : ''}`);
    return 0;
  } finally {
    await browser?.close();
    server.stop();
  }
}

runCommand({ name: 'bench', help: HELP, readOptions, run: bench, progress });
