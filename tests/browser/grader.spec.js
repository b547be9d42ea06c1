// The grader (npm run grade) in a browser: the WebGPU capture returns exactly what a page drew; the
// kept page serves each part apart; a few hand-ins of our labelled fixture class gathered live give
// exactly their recorded artifacts (which tests/unit/grader-class.test.js audits against the class's
// labels); and the course's real hand-ins, gathered live, against their labels.
import { spawn, spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect, chromium } from '@playwright/test';
import { buildClass } from '../fixtures/build.js';
import { copyHandins } from '../fixtures/handins.js';
import { readArtifact } from '../../grader/node/run/artifacts.js';
import { findParts, partNumber } from '../../grader/files/parts.js';
import { partOpener } from '../../grader/node/run/playwright-page.js';
import { CHROMIUM, CHROMIUM_ARGS, WEBGPU_ARGS } from '../../grader/node/run/chromium.js';
import { webgpuCaptureScript, readWebGPUFrame } from '../../grader/browser/webgpu-capture.js';
import { launchFirefox } from '../../grader/node/run/firefox.js';
import { checkClassInFirefox, NO_WEBGPU, partsByName } from './check-helpers.js';

const RECORDED = path.resolve(import.meta.dirname, '../fixtures/artifacts');
/** A report's verdicts and reasons, a line a part, sorted: what --audit-only must give again. */
const verdicts = (r) => r.submissions.flatMap((x) => x.parts.map((p) => `${x.name} ${p.part} ${p.verdict}: ${p.reasons.join(' | ')}`)).sort();

test('parts are found by the names students give them', () => {
  for (const [name, n] of [['WP04P1', 1], ['Part2', 2], ['part3', 3], ['p4', 4], ['p05', 5], ['w4p1', 1], ['week04p03', 3], ['part-2', 2],
    ['w04p05', 5], ['02561_w4p3', 3], ['part03', 3], ['Del1', 1], ['del_4', 4]]) {
    expect(partNumber(name), name).toBe(n);
  }
  for (const name of ['week04', 'worksheet4', 'index', 'p12', 'exercise5', 'Lab 4', 'model1']) expect(partNumber(name), name).toBeNull();
});

test.describe('the WebGPU capture', () => {
  // eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
  test.beforeEach(({}, testInfo) => test.skip(testInfo.project.name !== 'webgl2', 'its own Chromium with WebGPU; once is enough'));

  test('gives back the pixels the page drew: clear colour, triangle, both formats, padded rows', async ({ baseURL }) => {
    const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS, ...WEBGPU_ARGS] });
    try {
      for (const format of ['bgra8unorm', 'rgba8unorm']) {
        const context = await browser.newContext();
        await context.addInitScript(webgpuCaptureScript);
        const page = await context.newPage();
        await page.goto(`${baseURL}/tests/fixtures/webgpu-capture.html?format=${format}`);
        await page.waitForFunction(() => window.drawn);
        const info = await readWebGPUFrame(page);
        expect(info, format).toMatchObject({ frames: 1, captured: 1, width: 100, height: 60, format, errors: [] });
        // read the canvas as the page shows it (the capture put the frame on it)
        const px = await page.evaluate(() => {
          const c = document.getElementById('c');
          const copy = Object.assign(document.createElement('canvas'), { width: c.width, height: c.height });
          const g = copy.getContext('2d');
          g.drawImage(c, 0, 0);
          return Array.from(g.getImageData(0, 0, c.width, c.height).data);
        });
        const at = (x, y) => px.slice(4 * (y * 100 + x), 4 * (y * 100 + x) + 4);
        const clear = [51, 102, 204, 255], orange = [255, 128, 0, 255]; // 0.2, 0.4, 0.8 and 1, 0.5, 0 in bytes
        // the triangle covers the lower-left half: below the diagonal from top-left to bottom-right
        let inside = 0, outside = 0, wrong = 0;
        for (let y = 0; y < 60; y++) {
          for (let x = 0; x < 100; x++) {
            const u = (x + 0.5) / 100, v = (y + 0.5) / 60; // v grows downwards
            const margin = u + (1 - v) - 1; // < 0: inside the triangle (NDC x + y < 0)
            if (Math.abs(margin) < 0.03) continue; // the edge itself
            const want = margin < 0 ? orange : clear;
            const got = at(x, y);
            if (got.some((c, k) => Math.abs(c - want[k]) > 1)) wrong++;
            else if (margin < 0) inside++;
            else outside++;
          }
        }
        expect(wrong, `${format}: pixels not as drawn`).toBe(0);
        expect(inside, format).toBeGreaterThan(2500);
        expect(outside, format).toBeGreaterThan(2500);
        expect(at(0, 59), format).toEqual(orange);
        expect(at(99, 0), format).toEqual(clear);
        await context.close();
      }
    } finally {
      await browser.close();
    }
  });
});

test.describe("the grader's kept page", () => {
  // eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
  test.beforeEach(({}, testInfo) => test.skip(testInfo.project.name !== 'webgl2', 'its own Chromium; once is enough'));

  test('parts one after another: each its own folder, time frozen anew, storage apart; a crashed page is replaced', async () => {
    const dir = mkdtempSync(path.join(os.tmpdir(), 'kept-'));
    for (const name of ['one', 'two']) {
      mkdirSync(path.join(dir, name));
      writeFileSync(path.join(dir, name, 'index.html'),
        `<script>document.title = ['${name}', new Date().toISOString(), localStorage.n = Number(localStorage.n || 0) + 1].join(' ');</script>`);
    }
    const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
    try {
      const opener = partOpener(browser, 'submission.localhost');
      const open = (name) => opener.open({ root: path.join(dir, name), rel: 'index.html', loadSeconds: 20, log: { errors: [], blocked: [], notes: [] } });
      const loaded = '2026-01-05T09:00:02.000Z';
      const a = await open('one');
      expect(await a.page.title()).toBe(`one ${loaded} 1`);
      await a.driver.tick(5000, 0); // time moves in the first part
      await opener.done(true);
      const b = await open('two');
      expect(b.page, 'the same page, kept').toBe(a.page);
      expect(await b.page.title(), 'its own folder, the time frozen where it starts, no storage from the part before').toBe(`two ${loaded} 1`);
      await opener.done(true);
      await b.page.goto('chrome://crash').catch(() => {});
      const c = await open('one');
      expect(c.page, 'a new page for the one that crashed').not.toBe(b.page);
      expect(await c.page.title()).toBe(`one ${loaded} 1`);
      const navigations = (page) => { const seen = []; page.on('framenavigated', (f) => { if (f === page.mainFrame()) seen.push(f.url()); }); return seen; };
      const seen = navigations(c.page);
      await opener.done(true);
      await open('two');
      expect(seen.length, `a student's page is left for an empty one first: ${seen}`).toBe(2);
    } finally {
      await browser.close();
    }
  });
});

// A few hand-ins of our fixture class gathered live: their artifacts must be the recorded ones
// (tests/fixtures/artifacts/, which tests/unit/grader-class.test.js audits against the class's
// labels): the same facts, the same pictures pixel for pixel. This holds the gathering's
// determinism (the page's time, counts for budgets) and that what the unit tests judge is what the
// grader sees. ada: WebGL, level 0 first, orbiting; bo: WebGPU, WGSL fetched by name; cecilie
// (hand-written): a camera turned by performance.now(), as real hand-ins do (the frozen clock's
// performance.now left real, her pictures differ run to run). Beside them one more, in turn, a
// day each (UTC), from the rest of the class (LIVE_HANDIN=name picks one): over the weeks every
// recorded artifact is held against what gathering gives that day, not only these three.
const FIXED = ['ada', 'bo', 'cecilie'];
const LIVE = [...FIXED, inTurn(Math.floor(Date.now() / 86_400_000))];

/** The fixture hand-in whose turn it is on `day` (LIVE_HANDIN names one), of those recorded and not in FIXED. */
function inTurn(day) {
  if (process.env.LIVE_HANDIN) return process.env.LIVE_HANDIN;
  const rest = readdirSync(RECORDED, { withFileTypes: true }).filter((e) => e.isDirectory() && !FIXED.includes(e.name)).map((e) => e.name).sort();
  return rest[day % rest.length];
}

test.describe(`gathering live gives the recorded artifacts (${LIVE.join(', ')})`, () => {
  test.describe.configure({ mode: 'serial', timeout: 1_260_000 });
  let dir, out, run;
  // eslint-disable-next-line no-empty-pattern -- Playwright wants the fixtures argument destructured
  test.beforeAll(async ({}, testInfo) => {
    test.skip(testInfo.project.name !== 'webgl2', 'the grader runs its own Chromium; once is enough');
    dir = mkdtempSync(path.join(os.tmpdir(), 'live-'));
    buildClass(path.join(dir, 'all'));
    copyHandins(path.join(dir, 'all'));
    for (const name of LIVE) cpSync(path.join(dir, 'all', name), path.join(dir, 'class', name), { recursive: true });
    out = path.join(dir, 'report');
    run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--batch', path.join(dir, 'class'), '--rubric', 'tests/fixtures/test-rubric.json', '--out', out],
      { encoding: 'utf8', timeout: 1_200_000 });
    expect(run.status, run.stderr + run.stdout.slice(-3000)).toBe(0);
  });

  test('every part gathered live equals its recorded artifact: facts exactly, pictures pixel for pixel', () => {
    const differ = [];
    for (const name of LIVE) {
      for (const part of ['WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5']) {
        const live = readArtifact(path.join(out, 'artifacts', name, part));
        const kept = readArtifact(path.join(RECORDED, name, part));
        expect(!!live, `${name} ${part} gathered`).toBe(!!kept);
        if (!live) continue;
        const facts = (a) => ({ ...a.facts, blocked: undefined, notes: undefined });
        try {
          expect(facts(live)).toEqual(facts(kept));
        } catch (err) {
          differ.push(`${name} ${part}: facts: ${err.message.split('\n').slice(0, 12).join(' ')}`);
        }
        for (const k of new Set([...Object.keys(live.images), ...Object.keys(kept.images)])) {
          const a = live.images[k], b = kept.images[k];
          if (!a || !b || a.width !== b.width || a.height !== b.height || Buffer.compare(Buffer.from(a.data), Buffer.from(b.data)) !== 0) differ.push(`${name} ${part}: picture ${k}`);
        }
      }
    }
    expect(differ, `gathered live today, these differ from tests/fixtures/artifacts: if the change is meant, record again (node tests/fixtures/record.js --only '^(${LIVE.join('|')})$'), look at what changed and say why in the commit`).toEqual([]);
  });

  test('report.html opens on the class grid with the artifacts\' pictures; grades.csv has a column per part; --audit-only gives the same verdicts', () => {
    const report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    const html = readFileSync(path.join(out, 'report.html'), 'utf8');
    expect(html).toContain('<table id="grid">');
    expect(html).toContain('href="#bo-WP04P3"');
    expect(html).toMatch(/class="badge (pass|review|fail)"/);
    const bo3 = report.submissions.find((x) => x.name === 'bo').parts.find((x) => x.part === 'WP04P3');
    expect(bo3.api).toBe('webgpu');
    expect(existsSync(path.join(out, bo3.images.judged)), bo3.images.judged).toBe(true);
    expect(html).toContain(`src="${bo3.images.first}"`);
    const csv = readFileSync(path.join(out, 'grades.csv'), 'utf8').trim().split('\n');
    expect(csv[0]).toMatch(/^name,passes,WP04P1,WP04P2,WP04P3,WP04P4,WP04P5,/);
    expect(csv.find((l) => l.startsWith('ada,')).split(',').slice(1, 7)).toEqual(['5', 'pass', 'pass', 'pass', 'pass', 'pass']);
    expect(findParts(path.join(dir, 'all', 'cy')).WP04P3).toBe(path.join('Lab 4', 'w04', 'w04p03.html'));
    expect(findParts(path.join(dir, 'all', 'bo')).WP04P2).toBe(path.join('week04', 'part02', 'index.html'));
    const again = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--audit-only', out, '--rubric', 'tests/fixtures/test-rubric.json'], { encoding: 'utf8' });
    expect(again.status, again.stderr).toBe(0);
    expect(verdicts(JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')))).toEqual(verdicts(report));
  });
});

// Real hand-ins of this worksheet with a careful reader's labels (../shared/handins beside this
// checkout, or HANDINS_DIR): the grader is judged on hand-ins it was not written for. Graded with
// the shipped rubric and its own time bounds, as a teacher runs it (our reference left out). While
// the grader runs, the check page in Firefox (where many students are, and where there is no
// WebGPU) checks every third hand-in's .zip by name (all with FIREFOX_CHECK=all: ../shared/handins'
// seven took 128 s in Firefox beside the grading, quiet otherwise), and must give the grader's
// verdicts on the WebGL parts (all 30 of them with FIREFOX_CHECK=all).
const HANDINS = process.env.HANDINS_DIR || path.resolve(import.meta.dirname, '../../../shared/handins');
const checkedInFirefox = (names) => (process.env.FIREFOX_CHECK === 'all' ? names : names.filter((_, k) => k % 3 === 0));
// Parts where the engines really differ in verdict, and why (any other difference fails the test).
// None now: niklasrosenkilde's WP04P1 enables a color attribute on a buffer it never fills, which
// Chromium draws as zeros (alpha 0: the background through the silhouette) and Firefox's llvmpipe
// not at all; both give review, each for its engine's own reason ("one colour", "nothing seen").
const ENGINES_DIFFER = {};

/** `node args` as a promise of { status, stdout, stderr }. */
function run(args, timeout) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, args, { timeout });
    let stdout = '', stderr = '';
    child.stdout.on('data', (d) => { stdout += d; });
    child.stderr.on('data', (d) => { stderr += d; });
    child.on('close', (status) => resolve({ status, stdout, stderr }));
  });
}

test.describe('grading real hand-ins against their labels', () => {
  test.describe.configure({ timeout: 2_460_000 });
  test('the grader agrees with the labels: every labelled part, none left not graded, every correct part passes, no broken or partial part passes; --audit-only gives the same; the check page in Firefox gives its verdicts on the WebGL parts', async ({ baseURL }, testInfo) => {
    test.skip(testInfo.project.name !== 'handins', 'the grader runs its own Chromium; once is enough (project handins)');
    test.skip(!existsSync(path.join(HANDINS, 'labels.tsv')), `no labelled hand-ins at ${HANDINS} (set HANDINS_DIR): skipped`);
    const out = mkdtempSync(path.join(os.tmpdir(), 'handins-'));
    // the shipped rubric, without our reference beside each part (evidence for a teacher, not the verdict)
    const rubric = path.join(out, 'rubric.json');
    writeFileSync(rubric, JSON.stringify({ reference: false, timeoutSeconds: 300 }));
    const names = readdirSync(HANDINS).filter((n) => statSync(path.join(HANDINS, n)).isDirectory()).sort();
    // the real class has no broken part: beside it one of ours, eve (a page that throws, one that draws
    // nothing, one with no canvas, a shader that does not compile; her page that never returns left
    // out, for time), labelled broken, so that "no broken part passed" is a test that can fail
    const cls = mkdtempSync(path.join(os.tmpdir(), 'handins-class-'));
    cpSync(HANDINS, cls, { recursive: true });
    const fixtures = mkdtempSync(path.join(os.tmpdir(), 'handins-fixtures-'));
    buildClass(fixtures);
    cpSync(path.join(fixtures, 'eve'), path.join(cls, 'eve'), { recursive: true });
    rmSync(path.join(cls, 'eve', 'Part3.html'));
    const eve = JSON.parse(readFileSync(path.join(fixtures, 'labels.json'), 'utf8')).eve;
    const broken = ['WP04P1', 'WP04P2', 'WP04P4', 'WP04P5'].map((part) => ['eve', part, 'broken', 'WebGL', '', `${eve[part].because} (a fixture of ours)`].join('\t'));
    writeFileSync(path.join(cls, 'labels.tsv'), `${readFileSync(path.join(HANDINS, 'labels.tsv'), 'utf8').trimEnd()}\n${broken.join('\n')}\n`);
    const started = Date.now();
    const firefox = await launchFirefox();
    const [graded, checked] = await Promise.all([
      run(['grader/node/cli/grade.js', '--batch', cls, '--labels', path.join(cls, 'labels.tsv'), '--rubric', rubric, '--out', out], 2_400_000),
      checkClassInFirefox(firefox, baseURL, HANDINS, checkedInFirefox(names), mkdtempSync(path.join(os.tmpdir(), 'handins-zip-'))).finally(() => firefox.close()),
    ]);
    expect(graded.status, graded.stderr + graded.stdout.slice(-3000)).toBe(0);
    const report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    const a = report.labels;
    const summary = graded.stdout.split('\n').filter((l) => l.startsWith('labels:')).join('\n');
    console.log(`graded and checked in Firefox ${HANDINS} in ${((Date.now() - started) / 1000).toFixed(0)} s\n${summary}`);
    // what is measured, with the labels of 2026-12-07: 34 of 34, 14 of 14 correct passed, 0 of 20
    // partial, every part judged; and eve's 4 broken parts failed
    expect(a.broken, summary).toBe(4);
    expect(a.agree, summary).toBe(a.total);
    expect(a.notGraded, summary).toEqual([]);
    expect(a.correctPassed, summary).toBe(a.correct);
    expect(a.brokenPassed, summary).toBe(0);
    expect(a.partialPassed, summary).toBe(0);
    // judged again from the saved artifacts, with no browser: the same verdicts and reasons
    const again = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--audit-only', out, '--rubric', rubric], { encoding: 'utf8' });
    expect(again.status, again.stderr).toBe(0);
    expect(verdicts(JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')))).toEqual(verdicts(report));
    // the check page in Firefox: the grader's verdict on every WebGL part, but where the engines
    // really differ; a WebGPU part is "not checked here", said at the top, never a fail
    const grade = partsByName(report);
    const rows = [];
    for (const { name, parts, message } of checked) {
      for (const p of parts) {
        const want = grade[name] && grade[name][p.part];
        if (!want || want.status === 'missing') continue;
        if (want.api === 'webgpu' || /uses WebGPU/.test(p.reasons[0])) {
          expect([p.verdict, message], `${name} ${p.part} (WebGPU)`).toEqual(['not checked', expect.stringMatching(NO_WEBGPU)]);
          continue;
        }
        rows.push({ part: `${name} ${p.part}`, firefox: p.verdict, grade: want.verdict });
        if (p.verdict !== want.verdict) console.log(`differs: ${name} ${p.part}: Firefox ${p.verdict} (${p.reasons.join(' | ')}); grader ${want.verdict} (${want.reasons.join(' | ')})`);
      }
    }
    const differ = rows.filter((r) => r.firefox !== r.grade).map((r) => r.part);
    console.log(`check in Firefox = grade in Chromium on ${rows.length - differ.length} of ${rows.length} WebGL parts${differ.length ? `; differ: ${differ.join(', ')}` : ''}`);
    const seen = new Set(checked.flatMap(({ name, parts }) => parts.map((p) => `${name} ${p.part}`)));
    const gradedParts = checked.flatMap(({ name }) => Object.values(grade[name] || {}).filter((p) => p.status !== 'missing').map((p) => `${name} ${p.part}`));
    expect(gradedParts.filter((k) => !seen.has(k)), 'parts graded that the check page did not check').toEqual([]);
    expect(rows.length, 'WebGL parts checked in Firefox').toBeGreaterThanOrEqual(5);
    expect(rows.filter((r) => r.firefox === 'not checked'), 'no WebGL part left unchecked').toEqual([]);
    expect(differ.filter((k) => !ENGINES_DIFFER[k]), 'parts where Firefox\'s check and Chromium\'s grader differ, not named in ENGINES_DIFFER').toEqual([]);
  });
});

// dagny's P5 draws 786,432 vertices a frame (level 8, and 3 million at level 9): correct, and far
// slower than 5 seconds allow without a GPU (its gathering takes 25 s here, quiet). A page that runs
// past the gathering's deadline draws: it is "not graded here: too slow on this machine", never
// fail. The deadline is a quarter of a 20-s bound, so that the step in flight at the deadline (the
// page's opening takes 3 s of it here, quiet, and twice that beside busy processes) ends, and the
// part is written, long before the outer bound closes the page: with a 3-s bound and the default
// share (0.85), a busy machine's opening ran past the outer bound and the part stayed a timeout.
test('a heavy page past the rubric\'s bound is not graded here, never failed', ({}, testInfo) => { // eslint-disable-line no-empty-pattern
  test.skip(testInfo.project.name !== 'webgl2', 'the grader runs its own Chromium; once is enough');
  const out = mkdtempSync(path.join(os.tmpdir(), 'heavy-'));
  writeFileSync(path.join(out, 'rubric.json'), JSON.stringify({ timeoutSeconds: 20, deadlineShare: 0.25, reference: false }));
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', 'tests/fixtures/heavy/dagny', '--rubric', path.join(out, 'rubric.json'), '--out', out], { encoding: 'utf8', timeout: 120_000 });
  expect(run.status, run.stderr).toBe(0);
  const p5 = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')).submissions[0].parts.find((p) => p.part === 'WP04P5');
  expect([p5.verdict, p5.status]).toEqual(['not graded here', 'too slow']);
  expect(p5.reasons[0]).toMatch(/^not graded here: too slow on this machine: the rubric's bound of 20 s ran out while /);
});

// The same page under a budget of work it cannot meet (gatherWork, a count of vertices): "not graded
// here: too heavy", at a step that depends on the page and the count alone, never on the machine.
test('a heavy page past the rubric\'s budget of work is not graded here, never failed', ({}, testInfo) => { // eslint-disable-line no-empty-pattern
  test.skip(testInfo.project.name !== 'webgl2', 'the grader runs its own Chromium; once is enough');
  const out = mkdtempSync(path.join(os.tmpdir(), 'heavy-'));
  writeFileSync(path.join(out, 'rubric.json'), JSON.stringify({ thresholds: { gatherWork: 20e6 }, reference: false }));
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', 'tests/fixtures/heavy/dagny', '--rubric', path.join(out, 'rubric.json'), '--out', out], { encoding: 'utf8', timeout: 120_000 });
  expect(run.status, run.stderr).toBe(0);
  const p5 = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8')).submissions[0].parts.find((p) => p.part === 'WP04P5');
  expect([p5.verdict, p5.status]).toEqual(['not graded here', 'too heavy']);
  expect(p5.reasons[0]).toMatch(/^not graded here: too heavy to grade: the page's own work over the grading \(20 million vertices, draw calls at 80 each\) passed the rubric's budget of 20 million \(gatherWork\) while sampling the orbit/);
});

test('a submission folder that does not exist: a clear message and exit code 1; a bad rubric: exit code 2', () => {
  const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '/nonexistent/student'], { encoding: 'utf8' });
  expect(run.status).toBe(1);
  expect(run.stderr).toContain('grade: no such folder: /nonexistent/student');
  const usage = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--bogus'], { encoding: 'utf8' });
  expect(usage.status).toBe(2);
  const rubric = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--rubric', '/nonexistent/rubric.json', mkdtempSync(path.join(os.tmpdir(), 'empty-'))], { encoding: 'utf8' });
  expect(rubric.status).toBe(2);
  expect(rubric.stderr).toContain('cannot read the rubric');
  const badMust = path.join(mkdtempSync(path.join(os.tmpdir(), 'rubric-')), 'mine.json');
  writeFileSync(badMust, JSON.stringify({ parts: { WP04P3: { must: ['diffuse', 'difuse'] } } }));
  const must = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--rubric', badMust, mkdtempSync(path.join(os.tmpdir(), 'empty-'))], { encoding: 'utf8' });
  expect(must.status).toBe(2);
  expect(must.stderr).toContain('mine.json: the rubric\'s parts.WP04P3.must names "difuse", which no audit has');
  expect(findParts('/nonexistent')).toEqual({ WP04P1: null, WP04P2: null, WP04P3: null, WP04P4: null, WP04P5: null });
});
