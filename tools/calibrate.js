#!/usr/bin/env node
// npm run calibrate: measures the numbers chooseLevel rests on and writes them to
// common/shading-table.js (MAX_DEVIATION, SHININESS, SHADING_TABLE). Nobody edits that file by
// hand; tests/browser/calibration.spec.js re-measures its entries (at 512 px a sample), --check all.
//
//  - MAX_DEVIATION[level]: measured from the mesh itself (meshDeviation), in Node.
//  - SHADING_BY_SIZE: each lighting step's shaders (lab/bench.html draws with WP04P3's, WP04P4's
//    and WP04P5's own) at every level and, for the two with a highlight, every shininess in
//    SHININESS, against the exact reference, by shadingError (the lab's and the tests' measure
//    too), at each canvas size. SHADING_TABLE, what chooseLevel reads, is the largest over the
//    sizes, taken when the module loads: every number in the file is a measurement.
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { renderReference } from '../common/exact-render.js';
import { meshDeviation, shadingError } from './reference/measure.js';
import { startServer } from './browser.js';
import { CHROMIUM_ARGS, launchChromium } from '../grader/node/run/chromium.js';
import { isMainScript, parseOptions, progressLine, runCommand, wholeNumber } from './cli.js';
import { MAX_LEVEL, sphereMesh } from '../common/sphere.js';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const TABLE = path.join(root, 'common/shading-table.js');
const HELP = `usage: npm run calibrate -- [--sizes 128,256,512] [--out FILE]
Measures how far each lighting step's shading is from the exact picture at every subdivision
level (and, with a highlight, every shininess the table holds), and how far the mesh falls inside
the sphere, and writes them to common/shading-table.js, which chooseLevel and the pages' level
hint read. Takes about two minutes.
  --sizes LIST  canvas sizes in px to measure at, each kept; chooseLevel reads the largest (default 128,256,512)
  --out FILE    where to write the table (default common/shading-table.js)
  --check       measure, and compare with the table instead of writing it (exit 1 if an entry differs
                by more than 0.02/255)
exit codes: 0 done, 1 it failed or (--check) the table differs (the message says why), 2 bad usage`;

/** The shininess values the table is measured at: the slider's range, 0 to 500, denser where it changes fastest. */
export const SHININESS = [0, 1, 2, 5, 10, 20, 40, 80, 160, 320, 500];

const progress = progressLine('calibrate');
const round = (x, d) => Number(x.toFixed(d));

/**
 * Every entry of the shading table at one canvas size, in the bench page: { diffuse: [level],
 * gouraud: [k][level], phong: [k][level] } with k the index in `shininess`.
 * @param {import('playwright-core').Page} page lab/bench.html at that size, ready
 * @param {number} size
 * @param {number[]} shininess
 * @param {number[]} levels
 */
export async function measureShading(page, size, shininess, levels, say = () => {}) {
  const capture = async () => ({ width: size, height: size, data: Buffer.from(await page.evaluate(() => window.bench.capture()), 'base64') });
  const errorAt = async (method, level, ref) => {
    await page.evaluate(([m, l]) => { window.bench.setMesh(l); window.bench.setMethod(m); }, [method, level]);
    return shadingError(await capture(), ref);
  };
  const referenceOf = async (method) => {
    await page.evaluate(([m]) => window.bench.setMethod(m), [method]);
    return renderReference(await page.evaluate(() => window.bench.scene()), size, size);
  };
  const table = { diffuse: [], gouraud: [], phong: [] };
  const diffuseRef = await referenceOf('diffuse');
  for (const level of levels) table.diffuse.push(await errorAt('diffuse', level, diffuseRef));
  for (const [k, s] of shininess.entries()) {
    say(`${size} px, s = ${s} (${k + 1}/${shininess.length})`);
    await page.evaluate(([x]) => window.bench.setMaterial({ s: x }), [s]);
    const ref = await referenceOf('phong'); // the exact picture: the same for both methods
    for (const method of ['gouraud', 'phong']) {
      const row = [];
      for (const level of levels) row.push(await errorAt(method, level, ref));
      table[method].push(row);
    }
  }
  await page.evaluate(() => window.bench.setMaterial({ s: 40 }));
  const glError = await page.evaluate(() => window.bench.glError());
  if (glError) throw new Error(`gl.getError() = 0x${glError.toString(16)} while measuring`);
  return table;
}

/** Opens lab/bench.html at `size` px in WebGL 2 and waits for it. */
export async function openBenchPage(browser, base, size) {
  const page = await browser.newPage({ viewport: { width: size + 40, height: size + 200 }, deviceScaleFactor: 1 });
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  await page.goto(`${base}/lab/bench.html?size=${size}`);
  await page.waitForFunction(() => window.benchReady || document.querySelector('#messages .error'), null, { timeout: 60_000 });
  const error = await page.evaluate(() => document.querySelector('#messages .error')?.textContent);
  if (error || problems.length) throw new Error(`the bench page failed: ${error || problems.join('; ')}`);
  return page;
}

/** The table module's text. */
function tableModule({ maxDeviation, bySize, sizes, browser, seconds }) {
  const rows = (xs) => `[${xs.map((x) => round(x, 2)).join(', ')}]`;
  const perShininess = (table, method) => `[\n${table[method].map((row, k) => `      ${rows(row)}, // s = ${SHININESS[k]}`).join('\n')}\n    ]`;
  const oneSize = (size) => `  ${size}: {
    diffuse: ${rows(bySize[size].diffuse)},
    gouraud: ${perShininess(bySize[size], 'gouraud')},
    phong: ${perShininess(bySize[size], 'phong')},
  },`;
  return `// Written by \`npm run calibrate\` (tools/calibrate.js) on ${new Date().toISOString().slice(0, 10)}, measured in
// ${browser} at ${sizes.join(', ')} px in ${seconds} s. Do not edit: run the command again.
// tests/browser/calibration.spec.js re-measures every entry but some at 512 px; \`npm run calibrate -- --check\` every one.

/**
 * How far the mesh at each level falls inside the unit sphere at worst: 1 − the least distance
 * from the origin to a triangle's plane (tools/reference/measure.js meshDeviation).
 */
export const MAX_DEVIATION = [${maxDeviation.map((x) => x.toExponential(4)).join(', ')}];

/** The shininess values of the shading tables' rows. */
export const SHININESS = [${SHININESS.join(', ')}];

/**
 * How far each lighting step's shading is off at each level, in 8-bit steps (1 = 1/255), at each
 * canvas size: the interior RMSE against the exact render with the silhouette left out
 * (shadingError), for the exercises' default view (eye (0, 0, 3), light along the view, kd 0.8,
 * ks 0.5, Le 1, La 0.2). 0.29 is what rounding to 8 bits alone costs.
 *  - diffuse[level]: WP04P3 (Gouraud, diffuse light only: no shininess)
 *  - gouraud[k][level]: WP04P4 (Gouraud, the Phong reflection model) with s = SHININESS[k]
 *  - phong[k][level]: WP04P5 (Phong shading) with s = SHININESS[k]
 */
export const SHADING_BY_SIZE = {
${sizes.map(oneSize).join('\n')}
};

const largest = (a, b) => (typeof a === 'number' ? Math.max(a, b)
  : Array.isArray(a) ? a.map((x, k) => largest(x, b[k])) : Object.fromEntries(Object.keys(a).map((m) => [m, largest(a[m], b[m])])));
/** SHADING_BY_SIZE's largest entry over the sizes, entry by entry: what chooseLevel reads. */
export const SHADING_TABLE = Object.values(SHADING_BY_SIZE).reduce((table, t) => largest(table, t));
`;
}

/**
 * Every entry of \`measured\` (measureShading's, at the shininess values \`shininess\`) against
 * \`expected\` (one size of SHADING_BY_SIZE): the ones that differ by more than \`tolerance\`.
 */
export function compareShading(measured, expected, { shininess = SHININESS, tolerance = 0.02 } = {}) {
  const wrong = [];
  const rows = [['diffuse', measured.diffuse, expected.diffuse]];
  for (const method of ['gouraud', 'phong']) {
    shininess.forEach((s, k) => rows.push([`${method} s = ${s}`, measured[method][k], expected[method][SHININESS.indexOf(s)]]));
  }
  for (const [name, got, table] of rows) {
    got.forEach((m, level) => {
      if (!(Math.abs(m - table[level]) <= tolerance)) wrong.push(`${name} level ${level}: measured ${m.toFixed(2)}, table ${table[level]}`);
    });
  }
  return wrong;
}

/** The options, checked: { sizes, out } or { help: true }. Throws a UsageError. */
function readOptions(argv) {
  const opt = parseOptions(argv, { sizes: { type: 'string' }, out: { type: 'string' }, check: { type: 'boolean' } });
  if (opt.help) return opt;
  const sizes = (opt.sizes ?? '128,256,512').split(',').map((x) => wholeNumber(x.trim(), '--sizes', 16, 2048));
  return { sizes, out: path.resolve(opt.out ?? TABLE), check: !!opt.check };
}

/** Measures and writes the table; returns the exit code. */
async function calibrate(opt) {
  const started = Date.now();
  const levels = Array.from({ length: MAX_LEVEL + 1 }, (_, l) => l);
  progress('the mesh');
  const maxDeviation = levels.map((l) => meshDeviation(sphereMesh(l)));
  const server = await startServer(root);
  let browser = null;
  try {
    browser = await launchChromium({ args: CHROMIUM_ARGS });
    const bySize = {};
    for (const size of opt.sizes) {
      const page = await openBenchPage(browser, server.url, size);
      bySize[size] = await measureShading(page, size, SHININESS, levels, progress);
      await page.close();
    }
    const seconds = Math.round((Date.now() - started) / 1000);
    process.stderr.write(`\r[calibrate] done in ${seconds} s`.padEnd(80) + '\n');
    if (opt.check) {
      const { SHADING_BY_SIZE, MAX_DEVIATION } = await import(pathToFileURL(opt.out).href);
      const wrong = maxDeviation.flatMap((d, l) => (Math.abs(d - MAX_DEVIATION[l]) <= 1e-4 * d ? [] : [`MAX_DEVIATION level ${l}: measured ${d}, table ${MAX_DEVIATION[l]}`]));
      for (const size of opt.sizes) {
        if (!SHADING_BY_SIZE[size]) wrong.push(`${size} px: not in the table`);
        else wrong.push(...compareShading(bySize[size], SHADING_BY_SIZE[size]).map((w) => `${size} px, ${w}`));
      }
      if (wrong.length) {
        console.error(`calibrate: ${wrong.length} entries of ${path.relative(process.cwd(), opt.out)} differ from what was measured:\n  ${wrong.join('\n  ')}`);
        return 1;
      }
      console.log(`calibrate: every entry at ${opt.sizes.join(', ')} px is what was measured (within 0.02/255)`);
      return 0;
    }
    writeFileSync(opt.out, tableModule({ maxDeviation, bySize, sizes: opt.sizes, browser: `Chromium ${browser.version()}`, seconds }));
    console.log(`calibrate: wrote ${path.relative(process.cwd(), opt.out) || opt.out}`);
    return 0;
  } finally {
    await browser?.close();
    server.stop();
  }
}

if (isMainScript(import.meta.url)) runCommand({ name: 'calibrate', help: HELP, readOptions, run: calibrate, progress });
