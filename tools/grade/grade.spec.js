// One test per part of the plan that tools/grade/grade.js wrote (GRADE_PLAN). For each part the
// grader does what a teacher does by hand: open the page (time frozen, only the submission's own
// files reachable), see which API it uses and what it draws, find its controls, stop or sample
// the orbit, coarsen and subdivide until the silhouette stops changing, then judge the picture by
// the properties the slide's step asks for (tools/grade/judge.js), and write a verdict with
// reasons, the actions done, and the pictures (first, judged, our reference, difference).
import { test } from '@playwright/test';
import { readFileSync, readdirSync, writeFileSync, mkdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { compareImages } from './compare.js';
import { instrumentScript } from './instrument.js';
import { webgpuCaptureScript, readWebGPUFrame } from '../webgpu-capture.js';
import { analyse, samples, normalColours, diffuseFit, silhouetteChange, shadingChange, pictureChange, pointLightFit, perspectiveSamples, darkSpots, highlightAbove } from './judge.js';

const plan = JSON.parse(readFileSync(process.env.GRADE_PLAN, 'utf8'));
const rubric = plan.rubric;
const T = rubric.thresholds;
const TYPES = { '.html': 'text/html', '.htm': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.gif': 'image/gif', '.svg': 'image/svg+xml',
  '.vert': 'text/plain', '.frag': 'text/plain', '.glsl': 'text/plain', '.txt': 'text/plain', '.wgsl': 'text/plain' };
const FROZEN = new Date('2026-01-05T09:00:00Z');
const fmt = (x, d = 2) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toFixed(d));

/** Every file under `root` (relative paths, '/'-separated), up to a depth and a count: for findStandIn. */
function filesUnder(root, dir = '', out = [], depth = 0) {
  if (depth > 8 || out.length > 5000) return out;
  let names;
  try {
    names = readdirSync(path.join(root, dir), { withFileTypes: true });
  } catch {
    return out;
  }
  for (const d of names) {
    if (d.name.startsWith('.') || d.name === 'node_modules') continue;
    const rel = dir ? `${dir}/${d.name}` : d.name;
    if (d.isDirectory()) filesUnder(root, rel, out, depth + 1);
    else out.push(rel);
  }
  return out;
}

/**
 * A file the page asked for that is not where it asked, found as the student's own machine or a
 * teacher would: the same path in other letter case (Windows and macOS ignore case: "Common/MV.js"
 * for "common/mv.js"), else the one file of that name in the submission, or the one whose folders
 * match the asked path's the furthest from the end ("../../Common/MV.js" from a part folder that
 * went up past the submission's root). Null when there is none or no single best.
 */
function findStandIn(root, rel, files) {
  const asked = rel.replace(/^\/+/, '').split('/').filter(Boolean);
  if (!asked.length) return null;
  const lower = asked.join('/').toLowerCase();
  const all = files();
  const sameCase = all.filter((f) => f.toLowerCase() === lower);
  if (sameCase.length === 1) return sameCase[0];
  const name = asked.at(-1).toLowerCase();
  const named = all.filter((f) => f.split('/').at(-1).toLowerCase() === name);
  if (named.length <= 1) return named[0] ?? null;
  const shared = (f) => {
    const a = f.toLowerCase().split('/').reverse(), b = asked.map((x) => x.toLowerCase()).reverse();
    let k = 0;
    while (k < a.length && k < b.length && a[k] === b[k]) k++;
    return k;
  };
  const best = Math.max(...named.map(shared));
  const top = named.filter((f) => shared(f) === best);
  return top.length === 1 ? top[0] : null;
}

/** Serves `root` at `origin` through the browser's request routing: nothing else is reachable. */
async function confine(context, root, origin, log) {
  let files = null; // the submission's files, listed on the first miss
  await context.route('**/*', async (route) => {
    const url = new URL(route.request().url());
    if (url.origin !== origin) {
      const kind = route.request().isNavigationRequest() ? 'navigation or popup' : 'request';
      if (!url.protocol.startsWith('data') && !url.protocol.startsWith('blob')) log.blocked.push(`${kind}: ${url.href}`);
      return route.abort('blockedbyclient');
    }
    let rel;
    try {
      rel = decodeURIComponent(url.pathname);
    } catch {
      return route.fulfill({ status: 400, body: 'bad path' });
    }
    let file = path.resolve(root, `.${rel}`);
    if (file !== root && !file.startsWith(root + path.sep)) {
      log.blocked.push(`outside the submission: ${rel}`);
      return route.fulfill({ status: 403, body: 'outside the submission' });
    }
    const st = statSync(file, { throwIfNoEntry: false });
    if (st && st.isDirectory()) file = path.join(file, 'index.html');
    let body;
    try {
      body = readFileSync(file);
    } catch {
      const standIn = findStandIn(root, rel, () => (files ??= filesUnder(root)));
      if (!standIn) {
        log.errors.push(`missing file: ${rel}`);
        return route.fulfill({ status: 404, body: 'not found' });
      }
      file = path.join(root, standIn);
      body = readFileSync(file);
      log.notes.push(`served ${standIn} for ${rel}, which is not in the submission as written (letter case, or a folder above the submission)`);
    }
    return route.fulfill({ status: 200, body, contentType: TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream' });
  });
}

/** A page under the grader's eyes: the capture and instrument scripts in, time frozen. */
async function openPage(browser, root, rel, query, log) {
  const origin = root === plan.repo ? 'http://reference.localhost' : 'http://submission.localhost';
  const context = await browser.newContext({ viewport: { width: 1000, height: 1000 }, deviceScaleFactor: 1 });
  await confine(context, root, origin, log);
  await context.addInitScript(webgpuCaptureScript);
  await context.addInitScript(instrumentScript);
  const page = await context.newPage();
  page.on('popup', (popup) => {
    log.blocked.push(`popup: ${popup.url()}`);
    popup.close().catch(() => {});
  });
  page.on('pageerror', (e) => log.errors.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) log.errors.push(`console: ${m.text()}`); });
  page.on('dialog', (d) => { log.errors.push(`dialog: ${d.message()}`); d.dismiss().catch(() => {}); });
  await page.clock.install({ time: FROZEN });
  await page.clock.pauseAt(new Date(FROZEN.getTime() + 2000)); // from here time moves only when we say so
  const url = `${origin}/${rel.split(path.sep).map(encodeURIComponent).join('/')}${query ? `?${query}` : ''}`;
  let response;
  try {
    response = await page.goto(url, { waitUntil: 'load', timeout: (rubric.loadSeconds ?? 20) * 1000 });
  } catch (err) {
    if (!/Timeout/i.test(err.message)) throw err;
    return { context, page, why: `it did not finish loading in ${rubric.loadSeconds ?? 20} s (a script that never returns?)` };
  }
  if (!response || !response.ok()) return { context, page, why: `the page answered ${response ? response.status() : 'nothing'}` };
  await page.waitForLoadState('networkidle', { timeout: 5000 }).catch(() => {});
  return { context, page };
}

/** The canvas as { width, height, data } (RGBA), after the last WebGPU frame is copied; or null. */
async function snap(page) {
  await readWebGPUFrame(page);
  const r = await page.evaluate(() => window.__grade.pixels());
  if (!r) return null;
  return { width: r.width, height: r.height, api: r.api, data: Buffer.from(r.rgba, 'base64') };
}

/** Lets `ms` of frozen time pass (animation frames run), and counts the wall time it took. */
async function tick(ctx, ms, frames = 2) {
  const t0 = Date.now();
  // jump ahead (due timers and one animation frame fire once), then `frames` frames at 60 Hz: a slow
  // page with many loops is not made to draw every frame of the time skipped
  if (ms > 16 * frames + 8) await ctx.page.clock.fastForward(ms - 16 * frames);
  await ctx.page.clock.runFor(Math.min(ms, 16 * frames));
  await readWebGPUFrame(ctx.page);
  ctx.busy += Date.now() - t0;
}

const re = (s) => new RegExp(s, 'i');
/** The controls a teacher would use, by role: { subdivide, coarsen, levelSlider, orbit, depth, cull, clockwise, kd, ... }. */
function roles(controls) {
  const P = rubric.controls;
  const out = {};
  const take = (role, c) => { if (!out[role]) out[role] = c; };
  Object.defineProperty(out, 'orbitAll', { value: [], enumerable: false }); // every control that may start or stop the orbit
  for (const c of controls) {
    // an id is read as words too: kdSlider, slider_kd, light-Le
    const words = (s) => s && s.replace(/([a-z])([A-Z])/g, '$1 $2').replace(/[_-]+/g, ' ');
    const names = [c.id, words(c.id), c.name, words(c.name), c.text].filter(Boolean);
    const is = (role) => names.some((t) => re(P[role]).test(t));
    const clickable = ['button', 'submit', 'a', 'div', 'span'].includes(c.type) || c.type === 'image';
    if ((clickable || c.type === 'checkbox') && is('orbit') && !is('subdivide') && !is('coarsen')) out.orbitAll.push(c);
    if (clickable) {
      // "Decrement subdivision" names the level it lowers: coarsen is tried before subdivide
      if (is('coarsen')) take('coarsen', c);
      else if (is('subdivide')) take('subdivide', c);
      else if (is('orbit')) take('orbit', c);
      else if (is('depth')) take('depth', c);
      else if (is('cull')) take('cull', c);
      else if (is('clockwise')) take('clockwise', c);
    } else if (c.type === 'checkbox') {
      for (const role of ['orbit', 'depth', 'clockwise', 'cull']) if (is(role)) { take(role, c); break; }
    } else if (c.type === 'range' || c.type === 'number' || c.type === 'select') {
      if (is('levelSlider')) take('levelSlider', c);
      else for (const role of ['kd', 'ks', 's', 'Le', 'La']) if (is(role)) { take(role, c); break; }
    }
  }
  return out;
}

/** Clicks a control; false when it is disabled or cannot be clicked (said in the actions). */
async function click(ctx, c, what) {
  const target = ctx.page.locator(`[data-grade-control="${c.index}"]`);
  const name = `${what} ("${(c.text || c.id).slice(0, 40)}")`;
  if (await target.isDisabled().catch(() => false)) {
    ctx.actions.push(`${name} is disabled`);
    return false;
  }
  try {
    await target.click({ timeout: 3000 });
  } catch (err) {
    ctx.actions.push(`could not click ${name}: ${err.message.split('\n')[0]}`);
    return false;
  }
  ctx.actions.push(`clicked ${name}`);
  await tick(ctx, 100);
  return true;
}

function png(img) {
  const p = new PNG({ width: img.width, height: img.height });
  img.data.copy(p.data);
  return PNG.sync.write(p);
}

/** Brings the part to a comparable state and judges it. Returns { verdict, reasons, ... }. */
async function gradeOpen(ctx, item, result) {
  const { page } = ctx;
  const must = new Set((rubric.parts[item.part] || {}).must || []);
  const checks = []; // { level: 'pass'|'review'|'fail', reason }
  // 'mistake': the page draws, but misses a point of the slide's step; the rubric says what that
  // costs (review by default: a careful reader calls such a part partial, not broken)
  const say = (level, reason) => checks.push({ level: level === 'mistake' ? rubric.mistakeVerdict || 'review' : level, reason });
  await tick(ctx, 1000);
  // a page may start drawing only after promises that take real time (shaders fetched, a WebGPU
  // adapter and device): wait for its first draw call, within firstFrameSeconds
  const waitUntil = Date.now() + (rubric.firstFrameSeconds ?? 10) * 1000;
  for (let k = 0; Date.now() < waitUntil; k++) {
    const state = await page.evaluate(() => ({ api: window.__grade.api, frames: window.__webgpuCapture ? window.__webgpuCapture.frames : 0,
      adapter: window.__grade.adapter, draws: window.__grade.draws, errors: window.__grade.shaderErrors.length }));
    if (state.draws > 0 && (state.api !== 'webgpu' || state.frames > 0)) break;
    if (state.adapter === null || state.errors || (!state.api && k >= 20)) break;
    if (k >= 10 && result.errors.some((e) => /^(page error|dialog)/.test(e))) break; // it threw or alerted: no need to wait longer
    await new Promise((resolve) => setTimeout(resolve, 100));
    await tick(ctx, 16); // one frame: the orbit's phase should depend on the machine's load as little as can be
  }
  const g = await page.evaluate(() => ({ api: window.__grade.api, draws: window.__grade.draws, shaderErrors: window.__grade.shaderErrors,
    gpuErrors: window.__grade.gpuErrors, adapter: window.__grade.adapter }));
  result.api = g.api;
  const first = await snap(page);
  if (!first) return { fail: 'no canvas on the page' };
  result.canvas = { width: first.width, height: first.height };
  ctx.images.first = first;
  for (const e of g.shaderErrors) say('fail', e);
  if (g.api === 'webgpu' && g.adapter === null) say('fail', 'no WebGPU adapter: the page could not start WebGPU');
  let an = analyse(first, T);
  const firstAn = an;
  if (an.blank) {
    const why = g.shaderErrors[0] || g.gpuErrors[0] || result.errors.find((e) => /page error|dialog/.test(e));
    if (!g.api) return { fail: `drew nothing: the page never got a WebGL or WebGPU context${why ? ` (${why})` : ''}` };
    if (!g.draws) return { fail: `drew nothing: the canvas is one colour, no draw call${why ? ` (${why})` : ''}` };
    return { fail: `drew nothing visible: the canvas is one colour${why ? ` (${why})` : ''}` };
  }

  const controls = await page.evaluate(() => window.__grade.controls());
  const R = roles(controls);
  result.controls = Object.fromEntries(Object.entries(R).map(([k, c]) => [k, `${c.type} "${(c.text || c.id).slice(0, 40)}"${c.events.length ? ` (listens: ${c.events.join(', ')})` : ''}`]));

  // ---- the orbit: is it moving? sample it, then stop it where the sphere is well lit ----
  let cur = first;
  await tick(ctx, 500);
  let next = await snap(page);
  const moving = pictureChange(cur, next) > 0.001;
  cur = next;
  let orbitToggles = false, stopped = !moving;
  const shadedPart = must.has('diffuse');
  const orbitFits = []; // the diffuse fit at each lit orbit position seen
  const viewFits = []; // ... and at every lit view seen (the first one too)
  const look = (im, orbiting = true) => { // is the view lit? lit views' fits are kept
    const a = analyse(im, T);
    if (a.blank) return false;
    const fit = diffuseFit(samples(im, a, { max: 1500 }), T);
    // lit: a clear spread of brightness, or a clean diffuse fit with a clear diffuse term (a light
    // from the eye's side spreads brightness little over the disc: n·w_i from 0.5 to 1 in the samples)
    const lit = fit && a.roundness < 0.3 && (fit.spread >= T.litSpread * 1.5 ||
      (fit.spread >= T.litSpread / 2 && fit.r2 >= T.diffuseR2 && fit.diffuse >= T.diffuseMin));
    if (lit) {
      viewFits.push(fit);
      if (orbiting) orbitFits.push(fit);
    }
    return !!lit;
  };
  if (shadedPart) look(first, false);
  const sampleOrbit = async (im) => {
    // the light may be behind the sphere at first: look along the orbit (a few positions at least)
    // and a few positions at least, to see the lit side turn with the orbit (a light fixed in the world)
    // (many pages turn the camera a fixed step per frame, or per setInterval tick, not per second:
    // each sample runs frames, more as the search goes on, so such an orbit gets round too)
    let k = 0;
    for (; k < T.orbitSamples && (!look(im) || k < 2); k++) {
      await tick(ctx, T.orbitSampleSeconds * 1000, Math.min(8 << k, Math.round(60 * T.orbitSampleSeconds)));
      im = await snap(page);
    }
    ctx.actions.push(`sampled the orbit at ${k} positions ${fmt(T.orbitSampleSeconds, 1)} s apart (${orbitFits.length} lit)`);
    return im;
  };
  // the controls that may start or stop the orbit: one toggle, or a Start and a Stop button
  const orbitControls = R.orbit ? [R.orbit, ...R.orbitAll.filter((c) => c !== R.orbit)].slice(0, 3) : [];
  // clicks the orbit controls in turn, the one that started it first, until the picture stands still
  const stopOrbit = async (starter) => {
    for (const c of [starter, ...orbitControls.filter((x) => x !== starter)]) {
      await click(ctx, c, 'the orbit control');
      const a = await snap(page);
      await tick(ctx, 400);
      cur = await snap(page);
      if (pictureChange(a, cur) <= 0.001) {
        ctx.actions.push('the orbit stopped');
        return true;
      }
      ctx.actions.push('the picture still moves after the orbit control');
    }
    return false;
  };
  let startedByUs = false;
  if (moving) {
    ctx.actions.push('the picture moves by itself (an orbit or animation)');
    if (shadedPart) cur = await sampleOrbit(cur);
    if (R.orbit && await stopOrbit(R.orbit)) orbitToggles = stopped = true;
  } else if (R.orbit && shadedPart) {
    let starter = null;
    for (const c of orbitControls) {
      await click(ctx, c, 'the orbit control');
      await tick(ctx, 400);
      const b = await snap(page);
      const started = pictureChange(cur, b) > 0.001;
      cur = b;
      if (started) { starter = c; break; }
    }
    if (starter) {
      orbitToggles = startedByUs = true;
      ctx.actions.push('the orbit started');
      await sampleOrbit(cur);
      stopped = await stopOrbit(starter);
    }
  }

  // ---- the level: coarsen to the bottom, then subdivide until the silhouette stops changing ----
  let last = { img: cur, an: analyse(cur, T) };
  // coarsening goes on until the picture stops changing (the bottom level); subdividing until the
  // silhouette does (the finest level that matters at this size)
  const step = async (c, what, bound, settled) => {
    const got = [];
    for (let k = 0; k < bound; k++) {
      if (!await click(ctx, c, what)) break;
      const img = await snap(page);
      const a = analyse(img, T);
      const done = settled(last, { img, an: a });
      last = { img, an: a };
      got.push(last);
      if (done) break;
    }
    return got;
  };
  const same = (a, b) => pictureChange(a.img, b.img) <= 0.0005;
  // settled: the silhouette no longer changes, or it is already as round as pixels allow (a
  // teacher stops there too; the levels above cost seconds a click on slow pages)
  const settledSilhouette = (a, b) => silhouetteChange(a.an, b.an) <= T.silhouetteSettled || (!b.an.blank && b.an.roundness <= T.roundEnough);
  let ladder = [last];
  let coarsened = false;
  // (down first only where a coarse level is judged: P5's highlight per fragment)
  if (R.coarsen && stopped && must.has('perFragment')) {
    // down until the picture stops changing, or the silhouette is coarse (level 1 or so)
    const down = await step(R.coarsen, 'Coarsen', T.maxCoarsenings, (a, b) => same(a, b) || b.an.blank || b.an.roundness > 2 * T.coarseRoundness);
    ladder = [down.length ? down[down.length - 1] : last];
    coarsened = down.length > 0;
  }
  if (R.subdivide) {
    ladder.push(...await step(R.subdivide, 'Subdivide', T.maxSubdivisions + (coarsened ? T.maxCoarsenings : 0), settledSilhouette));
  } else if (R.levelSlider && ['range', 'number', 'select'].includes(R.levelSlider.type)) {
    // a level slider or <select> (which may start at level 0): stepped from its least up, as
    // Subdivide is clicked, until the silhouette settles (at most maxSubdivisions steps)
    const c = R.levelSlider;
    const values = [];
    if (c.type === 'select') values.push(...(c.options || []).slice(0, T.maxSubdivisions + 1));
    else {
      const lo = Number(c.min || 0), hi = Math.min(c.max === '' || c.max === undefined ? 8 : Number(c.max), lo + T.maxSubdivisions);
      for (let v = lo; v <= hi; v++) values.push(v);
    }
    ladder = [];
    for (const v of values) {
      await page.evaluate(([i, val]) => window.__grade.setValue(i, val), [c.index, v]);
      await tick(ctx, 100);
      const img = await snap(page);
      const a = analyse(img, T);
      const settled = ladder.length && settledSilhouette(ladder[ladder.length - 1], { img, an: a });
      ladder.push({ img, an: a });
      if (settled) break;
    }
    ctx.actions.push(`set the level ${c.type === 'select' ? 'menu' : 'slider'} from ${values[0]} up to ${values[ladder.length - 1]}`);
  }
  // a page that goes blank at a higher level (a buffer too small, an index type too narrow) is
  // judged at the last level it drew, and the blank level is a mistake
  let judged = ladder[ladder.length - 1];
  if (judged.an.blank) {
    const drawn = ladder.filter((x) => !x.an.blank);
    if (drawn.length) {
      judged = drawn[drawn.length - 1];
      say('mistake', 'the picture goes blank at a higher level: judged at the last level that drew');
    }
  }
  let img = judged.img;
  an = judged.an;
  ctx.images.judged = img;
  if (must.has('subdivideControls')) {
    if (R.subdivide || R.levelSlider) say('pass', 'has controls to subdivide');
    else say('review', 'no button to subdivide or coarsen was found (the slide asks for them)');
    if (R.subdivide && !R.coarsen && !R.levelSlider) say('review', 'no button to coarsen was found');
  }

  // ---- the sphere ----
  if (an.blank) return { fail: 'the picture went blank after the controls were used', checks };
  result.numbers = { radius: an.radius, roundness: an.roundness, fill: an.fill, coverage: an.coverage, firstRoundness: firstAn.roundness,
    levelsSeen: ladder.length };
  // a dark unlit side on a dark background: the outline is the lit edge's circle
  const c = an.circle;
  if (!(an.roundness <= T.roundness && an.fill >= T.fill) && c && c.roundness <= T.roundness && c.arc >= 180 && !an.touches) {
    Object.assign(an, { cx: c.cx, cy: c.cy, radius: c.r, roundness: c.roundness, fill: 1 });
    say('pass', `part of the sphere is as dark as the background: its outline was fitted to the lit edge (${c.arc}° of a circle)`);
  }
  if (an.radius < T.minRadiusPixels) say('review', `the sphere is very small on screen (${fmt(an.radius, 0)} px radius): hard to judge`);
  else if (an.roundness <= T.roundness && an.fill >= T.fill) {
    say('pass', `a round closed sphere (radius ${fmt(an.radius, 0)} px, roundness ${fmt(an.roundness, 3)})`);
  } else if (an.touches) say('review', 'the object touches the canvas edge: its silhouette cannot be judged');
  else say('mistake', `the object is not a round closed sphere (roundness ${fmt(an.roundness, 3)}, fill ${fmt(an.fill)}${ladder.length > 1 ? ', after subdividing' : ''})`);
  if (ladder.length > 2) {
    const rs = ladder.map((s) => s.an.roundness).filter((r) => Number.isFinite(r));
    if (rs[0] > rs[rs.length - 1] + 0.02) say('pass', `rounder with each level (roundness ${fmt(rs[0], 3)} → ${fmt(rs[rs.length - 1], 3)})`);
  }

  // ---- P1/P2: the normals as colours ----
  if (must.has('normalColours') || must.has('frontFaces')) {
    let nc = normalColours(samples(img, an));
    const judgeFaces = () => nc && nc.det >= T.facingDeterminant && nc.residual <= T.facingResidual;
    if (must.has('frontFaces') && nc && !judgeFaces()) {
      // the page may start with the depth test off or culling on the wrong side: set them as the step ends
      for (const [role, want] of [['depth', true], ['cull', true], ['clockwise', false]]) {
        const c = R[role];
        if (!c || (c.type === 'checkbox' && c.checked === want)) continue;
        await click(ctx, c, role === 'clockwise' ? 'the clockwise-front-faces control' : `the ${role} control`);
        img = await snap(page);
        an = analyse(img, T);
        if (an.blank) break;
        nc = normalColours(samples(img, an));
        ctx.images.judged = img;
        if (judgeFaces()) break;
      }
    }
    result.numbers.normals = nc;
    if (!nc) say('mistake', 'too little of the sphere to read its colours');
    else if (nc.spread < T.normalsSpread) say('mistake', 'the sphere is one colour: the normals are not used for the colour (0.5·n + 0.5)');
    else if (nc.unitError > T.normalsUnitError) {
      say('mistake', `the colours are not 0.5·n + 0.5: 2c − 1 is not a unit vector (off by ${fmt(nc.unitError)} on average)`);
    } else say('pass', `colours decode to unit normals 2c − 1 (off by ${fmt(nc.unitError, 3)})`);
    if (must.has('frontFaces') && nc && nc.spread >= T.normalsSpread) {
      if (judgeFaces()) say('pass', 'the visible colours are the normals facing the viewer: front faces only');
      else if (nc.det < 0 && nc.residual <= T.facingResidual) say('mistake', 'the inside of the far side shows (the normals face away from the viewer): the front faces are culled, or the depth test is off and the far side is drawn last');
      else say('mistake', `back faces show through the front (normals do not vary smoothly across the picture, misfit ${fmt(nc.residual)}): depth test or culling missing`);
    }
  }

  // ---- P3–P5: the reflection model ----
  let fit = null, pointLight = null;
  if (must.has('diffuse') || must.has('highlight')) {
    fit = diffuseFit(samples(img, an), T);
    pointLight = fit && fit.spread >= T.litSpread ? fitPointLight(img, an, fit, result) : null;
    result.numbers.fit = fit && { r2: fit.r2, ambient: fit.ambient, diffuse: fit.diffuse, light: fit.light, highlightPeak: fit.highlightPeak, spread: fit.spread };
    // lit on both sides shows where the light comes from the side: any view seen on the orbit
    // (or over all pixels: a crescent lit from behind is left out of the first fit as if a highlight; on
    // a page lit one-sided, |n·w_i| never explains all pixels better, it lights the dark side)
    const twoSided = [fit, ...viewFits].filter(Boolean).find((f) => (f.r2TwoSided > f.r2 + 0.03 && f.r2 < 0.97) ||
      (f.r2TwoSidedAll > f.r2All + 0.015 && f.r2TwoSidedAll >= T.diffuseR2));
    if (!fit) say('mistake', 'too little of the sphere to read its shading');
    else if (fit.spread < T.litSpread / 2) say('mistake', 'the sphere is evenly bright: no diffuse shading to see (from any orbit position tried)');
    else if (twoSided) {
      say('mistake', `the sphere is lit on both sides: brightness follows |n·w_i| (R² ${fmt(twoSided.r2TwoSided)}), not max(n·w_i, 0) (R² ${fmt(twoSided.r2)})`);
    } else if (!must.has('highlight') && orbitFits.length && Math.min(...orbitFits.map((f) => f.r2)) < T.diffuseR2 - 0.1) {
      const worst = orbitFits.reduce((a, b) => (b.r2 < a.r2 ? b : a));
      say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient at every orbit position (R² down to ${fmt(worst.r2)}): lit where it should be dark?`);
    } else if (fit.r2 >= T.diffuseR2 && fit.diffuse >= T.diffuseMin) {
      say('pass', `brightness follows max(n·w_i, 0)·kd·Le + ambient (R² ${fmt(fit.r2)}, fitted light ${fit.light.map((v) => fmt(v)).join(', ')})`);
    } else if (nearPointLight(pointLight) && fit.diffuse >= T.diffuseMin) {
      const f = pointLight[nearPointLight(pointLight)];
      say('pass', `brightness follows max(n·w_i, 0)·kd·L_i + ambient for a point light ${fmt(f.distance, 1)} radii from the centre (R² ${fmt(f.r2)})`);
    } else say('mistake', `brightness does not follow max(n·w_i, 0)·kd·Le + ambient for any light direction (R² ${fmt(fit.r2)})`);
  }
  if (shadedPart && orbitFits.length >= 2) {
    const angle = (a, b) => (180 / Math.PI) * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
    let turn = 0;
    for (let i = 1; i < orbitFits.length; i++) turn = Math.max(turn, angle(orbitFits[0].light, orbitFits[i].light));
    result.numbers.lightTurn = turn;
    if (turn < T.lightTurnDegrees) {
      say('review', `while the camera orbits, the lit side stays where it is on screen (the fitted light turns ${fmt(turn, 1)}°): the light moves with the camera (light and normals in different spaces?)`);
    } else say('pass', `the lit side turns as the camera orbits (${fmt(turn, 0)}°): the light stays in the world`);
  }
  if (must.has('orbitToggle')) {
    if (orbitToggles) say('pass', 'a control toggles the orbit on and off');
    else if (R.orbit) {
      say('review', 'an orbit control was found, but the picture does not change with it: the light moves with the camera (light and normals in different spaces?) or the orbit does not run');
    }
    else if (moving) say('review', 'the camera orbits, but no button toggles the orbit on/off (the slide asks for one)');
    else say('review', 'no orbit: no moving camera and no button toggling it');
  }
  if (pointLight) judgePointLight(pointLight, say);
  // a near point light with 1/r² makes a bright spot a directional fit reads as a highlight: then the
  // highlight is what rises above the point-light model (a page without a specular term has none)
  const nearModel = clearlyNearFalloff(pointLight) ? pointLight.falloff.model : null;
  if (fit && nearModel) fit.highlightPeak = pointLight.falloff.highlightPeak;
  if (must.has('highlight') && fit) {
    if (fit.highlightPeak >= T.highlightPeak) say('pass', `a specular highlight (up to ${fmt(100 * fit.highlightPeak, 0)}% of the way from the diffuse fit to white)`);
    else say('mistake', `no specular highlight: nothing brighter than the diffuse fit (${fmt(fit.highlightPeak)})`);
  }

  // ---- P4: the sliders ----
  if (must.has('sliders')) {
    const want = (rubric.parts[item.part] || {}).sliders || [];
    const missing = want.filter((k) => !R[k]);
    if (missing.length) say('review', `no slider found for ${missing.join(', ')} (the slide asks for sliders for kd, ks, s, Le, La)`);
    else say('pass', `sliders for ${want.join(', ')}`);
    const base = img;
    const baseFit = fit;
    let inputOk = 0, changeOnly = 0, dead = 0;
    for (const k of want.filter((x) => R[x])) {
      const c = R[k];
      if (c.type !== 'range' && c.type !== 'number') continue;
      const lo = Number(c.min || 0), hi = Number(c.max || 1);
      const target = k === 's' ? (Number(c.value) > (lo + hi) / 2 ? lo : hi) : lo; // s: far from where it is; others: to the least
      await page.evaluate(([i, v]) => window.__grade.setValue(i, v, ['input']), [c.index, target]);
      await tick(ctx, 100);
      let after = await snap(page);
      let how = 'input';
      if (pictureChange(base, after) <= T.sliderChange) {
        await page.evaluate(([i, v]) => window.__grade.setValue(i, v, ['change']), [c.index, target]);
        await tick(ctx, 100);
        after = await snap(page);
        how = pictureChange(base, after) > T.sliderChange ? 'change' : 'none';
      }
      ctx.actions.push(`set slider ${k} to ${target} (${how === 'none' ? 'no visible change' : `the picture changed on the ${how} event`})`);
      if (how === 'input') inputOk++;
      else if (how === 'change') changeOnly++;
      else dead++;
      if (how !== 'none' && baseFit && k === 'ks') {
        const a = analyse(after, T);
        // the highlight left with ks at its least: above the base picture's near point-light model (its
        // 1/r² spot stays and is no highlight), or above the after picture's own directional fit
        const f = a.blank ? null : nearModel ? { highlightPeak: highlightAbove(perspectiveSamples(after, an, T.pointLightFovy, { max: 1500 }), nearModel, T) }
          : diffuseFit(samples(after, a), T);
        if (k === 'ks' && f && f.highlightPeak >= baseFit.highlightPeak * 0.5 && f.highlightPeak >= T.highlightPeak) {
          say('review', `ks at ${target} leaves the highlight as it was (${fmt(f.highlightPeak)}): is ks used in the specular term?`);
        }
      }
      // back to where it was (drawn with the next slider's frame, or the last one below)
      await page.evaluate(([i, v]) => window.__grade.setValue(i, v, ['input', 'change']), [c.index, c.value]);
    }
    await tick(ctx, 100);
    if (must.has('sliderInputEvent') && changeOnly) say('review', `${changeOnly} slider(s) update the picture only on the change event, not while sliding (the slide asks for the input event)`);
    else if (must.has('sliderInputEvent') && inputOk) say('pass', 'the sliders update the picture on the input event');
    if (must.has('sliderEffects') && dead) say('review', `${dead} slider(s) change nothing in the picture`);
  }

  if (must.has('highlight') && fit && stopped && R.s) await judgeShininessZero(ctx, R.s, img, an, fit, result, say);

  // ---- P5: the highlight per fragment, seen at a coarse level ----
  if (must.has('perFragment') && fit) {
    const coarse = stopped ? ladder.find((s) => !s.an.blank && s.an.roundness < T.coarseRoundness && s !== judged) : null;
    const frag = await page.evaluate(() => {
      const g = window.__grade;
      const fs = g.glsl.filter((s) => /gl_FragColor|out\s+vec4/.test(s) && !/gl_Position/.test(s));
      // a WGSL fragment entry point and the functions it calls
      const wg = g.wgsl.map((s) => {
        const body = s.split(/@fragment/)[1] || '';
        const called = [...body.matchAll(/([A-Za-z_]\w*)\s*\(/g)].map((m) => m[1]);
        return body + called.map((name) => (s.split(new RegExp(`fn\\s+${name}\\s*\\(`))[1] || '').split(/\n}\s*\n/)[0]).join('\n');
      });
      return [...fs, ...wg].some((s) => /pow\s*\(/.test(s));
    });
    if (coarse && coarse.img.width === judged.img.width) {
      const change = shadingChange(coarse.img, coarse.an, judged.img, judged.an);
      result.numbers.coarseShadingChange = change;
      ctx.images.coarse = coarse.img;
      if (change !== null && change <= T.phongCoarseChange) say('pass', `the shading at a coarse level (roundness ${fmt(coarse.an.roundness)}) stays as smooth as at the finest (RMS ${fmt(change, 3)}): per fragment`);
      else say('mistake', `the highlight follows the triangles at a coarse level (RMS ${fmt(change, 3)} from the finest): shading is per vertex, not per fragment (or the normals are not re-normalised in the fragment shader)`);
    } else if (frag) say('review', 'no coarse level to compare; the fragment shader evaluates the specular term (pow), so probably per fragment');
    else say('mistake', 'no coarse level to compare, and no pow() in the fragment shader: the model seems evaluated per vertex');
  }
  if (!stopped && (moving || startedByUs)) say('review', 'the orbit could not be stopped: pictures were judged while moving');
  return { checks };
}

/**
 * A point light without the 1/r² fall-off (the slides: L_i = I/‖p_ℓ − x‖²): the judged picture's
 * brightness fitted with a point light at a fitted distance, with and without 1/r². Said only where
 * the light is near (the fall-off across the sphere is measurable) and one model is clearly better;
 * a directional or far light fits both alike and is not mentioned.
 */
function fitPointLight(img, an, fit, result) {
  const pl = pointLightFit(perspectiveSamples(img, an, T.pointLightFovy, { max: 1500 }), { ...T, around: fit.light });
  if (pl) result.numbers.pointLight = pl;
  return pl;
}
/** 'falloff' or 'none': the model a near point light fits well (R² ≥ diffuseR2), or null. */
function nearPointLight(pl) {
  if (!pl) return null;
  const good = ['falloff', 'none'].filter((k) => pl[k].r2 >= T.diffuseR2 && pl[k].distance <= T.pointLightNear);
  return good.sort((a, b) => pl[b].r2 - pl[a].r2)[0] || null;
}
/** Model `a` ('falloff' or 'none') clearly beats model `b`: a near light, R² higher by pointLightGain, RMS lower by pointLightRmsRatio. */
function clearlyBetter(pl, a, b) {
  return pl[a].r2 - pl[b].r2 >= T.pointLightGain && pl[a].distance <= T.pointLightNear && pl[b].rms >= T.pointLightRmsRatio * pl[a].rms;
}
/** A light clearly near and falling off as 1/r²: it fits, and better than without the fall-off. */
function clearlyNearFalloff(pl) {
  return !!pl && clearlyBetter(pl, 'falloff', 'none') && pl.falloff.r2 >= T.diffuseR2;
}
function judgePointLight(pl, say) {
  if (clearlyBetter(pl, 'none', 'falloff')) {
    say('review', `point light without the 1/r² fall-off: brightness fits a light ${fmt(pl.none.distance, 1)} radii from the centre with no fall-off (R² ${fmt(pl.none.r2, 3)}) better than with L_i = I/‖p_ℓ − x‖² (R² ${fmt(pl.falloff.r2, 3)})`);
  } else if (clearlyBetter(pl, 'falloff', 'none')) {
    say('pass', `a point light ${fmt(pl.falloff.distance, 1)} radii from the centre, with the 1/r² fall-off (R² ${fmt(pl.falloff.r2, 3)}; without it ${fmt(pl.none.r2, 3)})`);
  }
}

/**
 * s at its least (where that is 0 or below): the Phong term max(cos φ, 0)^s with s = 0 is pow(0, 0)
 * where cos φ ≤ 0, undefined (NaN: black on many GPUs). One capture at the least s, compared with
 * the judged picture (same view), then s back where it was.
 */
async function judgeShininessZero(ctx, c, img, an, fit, result, say) {
  const lo = c.min === '' || c.min === undefined || c.min === null ? 0 : Number(c.min); // a range's min defaults to 0
  if (!(lo <= 0) || (c.type !== 'range' && c.type !== 'number')) return;
  await ctx.page.evaluate(([i, v]) => window.__grade.setValue(i, v, ['input', 'change']), [c.index, lo]);
  await tick(ctx, 100);
  const after = await snap(ctx.page);
  await ctx.page.evaluate(([i, v]) => window.__grade.setValue(i, v, ['input', 'change']), [c.index, c.value]);
  await tick(ctx, 100);
  if (!after || after.width !== img.width || after.height !== img.height) return;
  const spots = darkSpots(img, an, after, fit, T);
  if (!spots) return;
  result.numbers.darkSpotsAtLeastS = spots;
  ctx.images.leastS = after;
  ctx.actions.push(`set slider s to its least, ${lo} (${spots.count} sampled pixels inside the sphere turned dark)`);
  if (spots.share >= T.darkSpotShare && spots.count >= 5) {
    say('review', `s = ${lo} gives black spots inside the sphere (${fmt(100 * spots.share, 1)}% of it darker than diffuse + ambient): pow(0, 0) is undefined; guard it (e.g. cos φ > 0 ? pow(cos φ, s) : 0)`);
  } else say('pass', `s = ${lo} leaves no dark spots inside the sphere (pow(0, 0) guarded)`);
}

/**
 * Our reference's light, as the judge fitted the student's (P3–P5): the fitted direction toward the
 * light is in view space, and our page at angle 0 has view = world (eye on +z), so a directional
 * light shines along −l; a near point light with 1/r² sits at d·l (our sphere is a unit sphere,
 * as the fit's). The level stays ours for the canvas size: a student's own level is not known.
 */
function referenceLight(result) {
  const fit = result.numbers && result.numbers.fit;
  if (!fit || !fit.light) return {};
  const pl = result.numbers.pointLight;
  const xyz = (v) => ({ lx: fmt(v[0], 3), ly: fmt(v[1], 3), lz: fmt(v[2], 3) });
  if (pl && nearPointLight(pl) === 'falloff') return { light: 'point', ...xyz(pl.falloff.light.map((v) => v * pl.falloff.distance)) };
  return { light: 'directional', ...xyz(fit.light.map((v) => -v)) };
}
/** The state our reference was drawn at, for report.json: its light (and where it came from) and level. */
function referenceStateOf(query, scene) {
  const q = Object.fromEntries(query.entries());
  return {
    level: scene && Number.isFinite(scene.level) ? scene.level : null,
    levelFrom: 'ours: the least level that looks round and shades within tolerance at this canvas size (the student\'s level is not known)',
    light: q.light ? { kind: q.light, xyz: [q.lx, q.ly, q.lz].map(Number) } : null,
    lightFrom: q.light ? 'the light direction (or near point light) the judge fitted to the judged picture, in our view at angle 0' : 'none (no lit step)',
    query: query.toString(),
  };
}

function verdictOf(checks, fail) {
  if (fail) return 'fail';
  if (checks.some((c) => c.level === 'fail')) return 'fail';
  if (checks.some((c) => c.level === 'review')) return 'review';
  return 'pass';
}

function save(item, result) {
  mkdirSync(path.dirname(item.resultFile), { recursive: true });
  writeFileSync(item.resultFile, JSON.stringify(result, null, 1));
}

for (const item of plan.items) {
  test(`${item.name} ${item.part}`, async ({ browser }, testInfo) => {
    const result = { name: item.name, part: item.part, file: item.page, status: 'timeout', verdict: 'fail', api: null,
      reasons: ['the page did not finish within the time bound (it never returns, or is far too slow)'], actions: [], controls: {},
      numbers: {}, mismatch: null, rmse: null, pass: false, comparison: null, notes: [], errors: [], blocked: [], images: null };
    save(item, result); // what stays if the page never lets go: a timeout
    if (!item.page) {
      Object.assign(result, { status: 'missing', reasons: [`no page for ${item.part} was found in the submission`] });
      return save(item, result);
    }
    const started = Date.now();
    const ctx = { busy: 0, actions: result.actions, images: {} };
    let outcome;
    let opened;
    try {
      opened = await openPage(browser, item.root, item.page, '', result);
      Object.assign(ctx, opened);
      if (opened.why) outcome = { fail: `the page could not be opened: ${opened.why}` };
      else outcome = await gradeOpen(ctx, item, result);
    } catch (err) {
      if (/Test ended|Target page, context or browser has been closed/.test(err.message)) throw err; // the time bound: stays 'timeout'
      // the grader's own trouble with this page: never a pass on it, a teacher looks
      outcome = { checks: [{ level: 'review', reason: `the grader could not finish on this page: ${err.message.split('\n')[0]}` }] };
    } finally {
      if (opened) await opened.context.close().catch(() => {});
    }
    const checks = outcome.checks || [];
    const reasons = [];
    if (outcome.fail) reasons.push(outcome.fail);
    for (const lvl of ['fail', 'review', 'pass']) for (const c of checks) if (c.level === lvl) reasons.push(lvl === 'pass' ? c.reason : `${lvl.toUpperCase()}: ${c.reason}`);
    const seconds = (Date.now() - started) / 1000;
    if (seconds > rubric.slowSeconds) reasons.push(`slow: ${fmt(seconds, 0)} s to grade (${fmt(ctx.busy / 1000, 0)} s drawing frames) on a software renderer`);
    const pageErrors = result.errors.filter((e) => /page error/.test(e));
    if (!outcome.fail && pageErrors.length) reasons.push(`the page reported errors: ${pageErrors[0]}`);
    result.verdict = verdictOf(checks, outcome.fail);
    result.reasons = reasons;
    result.status = outcome.fail ? 'failed' : 'ok';
    result.pass = result.verdict === 'pass';
    result.seconds = seconds;
    const dir = path.dirname(item.resultFile);
    const stem = path.basename(item.resultFile, '.json');
    result.images = {};
    for (const [k, im] of Object.entries(ctx.images)) {
      writeFileSync(path.join(dir, `${stem}-${k}.png`), png(im));
      result.images[k] = `${stem}-${k}.png`;
    }
    save(item, result);

    // our reference at the student's size and level, beside theirs: evidence, not the verdict
    if (rubric.reference && ctx.images.judged && !outcome.fail) {
      testInfo.setTimeout(testInfo.timeout + plan.referenceSeconds * 1000);
      const refLog = { errors: [], blocked: [], notes: [] };
      const { width, height } = ctx.images.judged;
      const fitted = referenceLight(result);
      const query = new URLSearchParams({ api: 'webgl2', size: width, height, orbit: 0, ...(fitted.light ? { angle: 0 } : {}), ...fitted, ...item.referenceQuery });
      let ref = null;
      try {
        const r = await openPage(browser, plan.repo, `${item.part}/index.html`, query.toString(), refLog);
        try {
          if (!r.why) {
            await r.page.clock.runFor(500);
            ref = await snap(r.page);
            const scene = await r.page.evaluate(() => window.scene || null).catch(() => null);
            result.referenceState = referenceStateOf(query, scene);
          }
        } finally {
          await r.context.close().catch(() => {});
        }
      } catch (err) {
        result.notes.push(`our reference could not be drawn: ${err.message.split('\n')[0]}`);
      }
      if (ref && ref.width === width && ref.height === height) {
        const cmp = compareImages(PNG.sync.read(png(ref)), PNG.sync.read(png(ctx.images.judged)));
        Object.assign(result, { mismatch: cmp.mismatch, rmse: cmp.rmse, comparison: cmp.comparison, mismatchFull: cmp.mismatchFull, mismatchObject: cmp.mismatchObject });
        result.notes.push(...cmp.notes, `the reference is our page at the same canvas size${result.referenceState && result.referenceState.light ? ', lit from the fitted light' : ''}; the difference is evidence, the verdict comes from the checks`);
        writeFileSync(path.join(dir, `${stem}-reference.png`), PNG.sync.write(cmp.reference));
        writeFileSync(path.join(dir, `${stem}-diff.png`), PNG.sync.write(cmp.diff));
        Object.assign(result.images, { reference: `${stem}-reference.png`, diff: `${stem}-diff.png` });
      } else if (ref) result.notes.push(`our reference drew ${ref.width}×${ref.height}, not ${width}×${height}: not compared`);
      save(item, result);
    }
  });
}
