// One test per part of the plan that tools/grade/grade.js wrote (GRADE_PLAN): open the student's
// page and the reference's in Chromium with time frozen, let them draw, screenshot the canvas,
// compare, and write the part's result (JSON and PNGs) for grade.js to gather into the report.
import { test } from '@playwright/test';
import { readFileSync, writeFileSync, mkdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { compareImages } from './compare.js';

const plan = JSON.parse(readFileSync(process.env.GRADE_PLAN, 'utf8'));
const TYPES = { '.html': 'text/html', '.htm': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.gif': 'image/gif', '.svg': 'image/svg+xml',
  '.vert': 'text/plain', '.frag': 'text/plain', '.glsl': 'text/plain', '.txt': 'text/plain', '.wgsl': 'text/plain' };
const FROZEN = new Date('2026-01-05T09:00:00Z');
const PIN = '[data-grade-canvas] { position: fixed !important; left: 0 !important; top: 0 !important; margin: 0 !important; ' +
  'border: 0 !important; outline: none !important; z-index: 2147483647 !important; }';

/** Serves `root` at `origin` through the browser's request routing: nothing else is reachable. */
async function confine(context, root, origin, log) {
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
      log.errors.push(`missing file: ${rel}`);
      return route.fulfill({ status: 404, body: 'not found' });
    }
    return route.fulfill({ status: 200, body, contentType: TYPES[path.extname(file).toLowerCase()] || 'application/octet-stream' });
  });
}

/** Runs the rubric's actions: click a button by its label, set a slider by its label. */
async function act(page, actions, log) {
  const toRegExp = (s) => {
    const m = /^\/(.*)\/([a-z]*)$/.exec(s);
    return m ? new RegExp(m[1], m[2]) : new RegExp(s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&'), 'i');
  };
  for (const a of actions || []) {
    try {
      if (a.click) {
        const target = page.getByRole('button', { name: toRegExp(a.click) }).first();
        for (let k = 0; k < (a.times || 1); k++) {
          await target.click({ timeout: 2000 });
          await page.clock.runFor(100);
        }
      } else if (a.slider) {
        await page.getByLabel(toRegExp(a.slider)).first().fill(String(a.value), { timeout: 2000 });
        await page.clock.runFor(100);
      } else if (a.check || a.uncheck) {
        const box = page.getByRole('checkbox', { name: toRegExp(a.check || a.uncheck) }).first();
        await (a.check ? box.check({ timeout: 2000 }) : box.uncheck({ timeout: 2000 }));
        await page.clock.runFor(100);
      }
    } catch {
      log.errors.push(`rubric action could not be done: ${JSON.stringify(a)}`);
    }
  }
}

/**
 * Opens `rel` under `root` with time frozen, lets it draw, and returns the largest canvas as PNG
 * bytes, or a status: 'no-canvas', 'error'.
 */
async function capture(browser, root, rel, query, actions, log) {
  const origin = root === plan.repo ? 'http://reference.localhost' : 'http://submission.localhost';
  const context = await browser.newContext({ viewport: { width: 900, height: 900 }, deviceScaleFactor: 1 });
  try {
    await confine(context, root, origin, log);
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
    const response = await page.goto(url, { waitUntil: 'load' });
    if (!response || !response.ok()) return { status: 'error', why: `the page answered ${response ? response.status() : 'nothing'}` };
    await page.waitForLoadState('networkidle').catch(() => {});
    // frames run on the frozen clock: the same second of animation for every page
    await page.clock.runFor(1000);
    await act(page, actions, log);
    const found = await page.evaluate(() => {
      const all = [...document.querySelectorAll('canvas')].filter((c) => c.clientWidth > 0 && c.clientHeight > 0);
      if (!all.length) return null;
      const c = all.reduce((a, b) => (b.clientWidth * b.clientHeight > a.clientWidth * a.clientHeight ? b : a));
      c.setAttribute('data-grade-canvas', '');
      return { width: Math.round(c.clientWidth), height: Math.round(c.clientHeight), pixelWidth: c.width, pixelHeight: c.height };
    });
    if (!found) return { status: 'no-canvas' };
    // let it settle: two screenshots 100 ms of frozen time apart that agree, three tries at most
    let png = null;
    for (let k = 0; k < 3; k++) {
      const shot = await page.screenshot({ style: PIN, clip: { x: 0, y: 0, width: found.width, height: found.height } });
      if (png && Buffer.compare(png, shot) === 0) break;
      png = shot;
      await page.clock.runFor(100);
    }
    return { status: 'ok', png, canvas: found };
  } finally {
    await context.close();
  }
}

/** Resizes a PNG in the browser (its own resampling), to compare pictures of one size. */
async function resize(browser, png, width, height) {
  const page = await browser.newPage();
  try {
    const data = await page.evaluate(async ([b64, w, h]) => {
      const bytes = Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0));
      const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(w, h);
      const ctx = canvas.getContext('2d');
      ctx.drawImage(bitmap, 0, 0, w, h);
      return Array.from(ctx.getImageData(0, 0, w, h).data);
    }, [png.toString('base64'), width, height]);
    const out = new PNG({ width, height });
    out.data = Buffer.from(data);
    return out;
  } finally {
    await page.close();
  }
}

function save(item, result) {
  mkdirSync(path.dirname(item.resultFile), { recursive: true });
  writeFileSync(item.resultFile, JSON.stringify(result, null, 1));
}

for (const item of plan.items) {
  test(`${item.name} ${item.part}`, async ({ browser }, testInfo) => {
    const result = { name: item.name, part: item.part, file: item.page, status: 'timeout', mismatch: null, rmse: null,
      pass: false, comparison: null, notes: [], errors: [], blocked: [], images: null };
    save(item, result); // what stays if the page never lets go: a timeout
    if (!item.page) {
      result.status = 'missing';
      result.errors.push(`no page for ${item.part} was found in the submission`);
      return save(item, result);
    }
    const sub = await capture(browser, item.root, item.page, '', item.actions, result);
    if (sub.status !== 'ok') {
      result.status = sub.status;
      if (sub.why) result.errors.push(sub.why);
      return save(item, result);
    }
    // the reference at the student's canvas size, on a time budget of its own: the rubric's
    // bound is for the student's page, and our page must not eat it on a busy machine
    testInfo.setTimeout(testInfo.timeout + plan.referenceSeconds * 1000);
    const refLog = { errors: [], blocked: [] };
    const { width, height } = sub.canvas;
    // our own defaults (orbit on from angle 0, like most students' first frame) unless the rubric says otherwise
    const query = new URLSearchParams({ api: 'webgl2', size: width, height, ...item.referenceQuery });
    const ref = await capture(browser, plan.repo, `${item.part}/index.html`, query.toString(), item.actions, refLog);
    if (ref.status !== 'ok') throw new Error(`the reference ${item.part} could not be captured: ${ref.status} ${refLog.errors.join('; ')}`);
    const refImg = PNG.sync.read(ref.png);
    let subImg = PNG.sync.read(sub.png);
    let resized = null;
    if (subImg.width !== refImg.width || subImg.height !== refImg.height) {
      resized = `the submission's ${subImg.width}×${subImg.height} canvas was resized to the reference's ${refImg.width}×${refImg.height}`;
      subImg = await resize(browser, sub.png, refImg.width, refImg.height);
    }
    const cmp = compareImages(refImg, subImg);
    if (resized) cmp.notes.unshift(resized);
    Object.assign(result, { status: 'ok', mismatch: cmp.mismatch, rmse: cmp.rmse, comparison: cmp.comparison, notes: cmp.notes,
      mismatchFull: cmp.mismatchFull, mismatchObject: cmp.mismatchObject, pass: cmp.mismatch <= item.threshold });
    const dir = path.dirname(item.resultFile);
    const stem = path.basename(item.resultFile, '.json');
    writeFileSync(path.join(dir, `${stem}-reference.png`), PNG.sync.write(cmp.reference));
    writeFileSync(path.join(dir, `${stem}-submission.png`), PNG.sync.write(cmp.submission));
    writeFileSync(path.join(dir, `${stem}-diff.png`), PNG.sync.write(cmp.diff));
    result.images = { reference: `${stem}-reference.png`, submission: `${stem}-submission.png`, diff: `${stem}-diff.png` };
    save(item, result);
  });
}
