// The grader's harness: one Playwright test per part of the plan that grader/node/grade.js wrote
// (GRADE_PLAN). Each opens the part (playwright-page.js: served by serve-submission.js, time
// frozen, instrumented), lets drive.js bring it to a state and judge it, turns the findings into a
// verdict with reasons (verdict.js), writes the pictures, and draws our reference beside them.
import { test } from '@playwright/test';
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { compareImages } from './compare.js';
import { partOpener } from './playwright-page.js';
import { gradePart, addTime } from '../core/gather.js';
import { verdictOf, reasonsOf } from '../core/verdict.js';
import { referenceQuery, referenceStateOf } from '../core/reference-state.js';

const plan = JSON.parse(readFileSync(process.env.GRADE_PLAN, 'utf8'));
const rubric = plan.rubric;

function png(img) {
  const p = new PNG({ width: img.width, height: img.height });
  p.data.set(img.data);
  return PNG.sync.write(p);
}

function save(item, result) {
  mkdirSync(path.dirname(item.resultFile), { recursive: true });
  writeFileSync(item.resultFile, JSON.stringify(result, null, 1));
}

// a worker's parts open one after another in one page (and ours beside them in another)
let openers = null;

for (const item of plan.items) {
  test(`${item.name} ${item.part}`, async ({ browser }, testInfo) => {
    openers ??= { student: partOpener(browser, 'submission.localhost'), reference: partOpener(browser, 'reference.localhost') };
    const result = { name: item.name, part: item.part, file: item.page, status: 'timeout', verdict: 'fail', api: null,
      reasons: [`the page did not finish within the rubric's bound of ${rubric.timeoutSeconds} s (it never returns, or is far too slow)`], actions: [], controls: {},
      numbers: {}, mismatch: null, rmse: null, pass: false, comparison: null, notes: [], errors: [], blocked: [], images: null };
    save(item, result); // what stays if the page never lets go: a timeout
    if (!item.page) {
      Object.assign(result, { status: 'missing', reasons: [`no page for ${item.part} was found in the submission`] });
      return save(item, result);
    }
    const started = Date.now();
    let graded = { fail: null, checks: [], actions: [], images: {}, busy: 0 };
    let clean = false;
    // where the part's time goes: opening it, each page-interface call, closing it, writing the pictures
    const timing = result.timing = {};
    const phase = (what, t0) => addTime(timing, what, Date.now() - t0);
    try {
      const t0 = Date.now();
      const opened = await openers.student.open({ root: item.root, rel: item.page, loadSeconds: rubric.loadSeconds, log: result });
      phase('open', t0);
      if (opened.why) graded.fail = `the page could not be opened: ${opened.why}`;
      else {
        // what has been done so far stays in the result if the time bound stops the part
        // the looking stops at 70% of the bound, so that a slow page is still judged on what was seen
        const deadline = started + 0.7 * rubric.timeoutSeconds * 1000;
        graded = await gradePart(opened.driver, { part: item.part, rubric, deadline, timing, progress: (what) => {
          result.reasons = [`the page did not finish within the rubric's bound of ${rubric.timeoutSeconds} s: stopped while ${what} (a click or frame that never returns?)`];
          save(item, result);
        } });
      }
      clean = true;
    } catch (err) {
      if (/Test ended|Target page, context or browser has been closed/.test(err.message)) throw err; // the time bound: stays 'timeout'
      // the grader's own trouble with this page: never a pass on it, a teacher looks
      graded.checks = [{ level: 'review', reason: `the grader could not finish on this page: ${err.message.split('\n')[0]}` }];
    } finally {
      const t0 = Date.now();
      await openers.student.done(clean);
      phase('close', t0);
    }
    const seconds = (Date.now() - started) / 1000;
    Object.assign(result, { api: graded.api ?? null, canvas: graded.canvas, controls: graded.controls || {}, numbers: graded.numbers || {} });
    result.actions.push(...graded.actions);
    result.verdict = verdictOf(graded.checks, graded.fail);
    result.reasons = reasonsOf({ fail: graded.fail, checks: graded.checks, seconds, busySeconds: graded.busy / 1000, slowSeconds: rubric.slowSeconds,
      pageErrors: result.errors.filter((e) => /page error/.test(e)) });
    result.status = graded.fail ? 'failed' : 'ok';
    result.pass = result.verdict === 'pass';
    result.seconds = seconds;
    const dir = path.dirname(item.resultFile);
    const stem = path.basename(item.resultFile, '.json');
    result.images = {};
    const t0 = Date.now();
    for (const [k, im] of Object.entries(graded.images)) {
      writeFileSync(path.join(dir, `${stem}-${k}.png`), png(im));
      result.images[k] = `${stem}-${k}.png`;
    }
    phase('write', t0);
    save(item, result);

    // our reference at the student's size, beside theirs: evidence, not the verdict
    if (rubric.reference && graded.images.judged && !graded.fail) {
      testInfo.setTimeout(testInfo.timeout + plan.referenceSeconds * 1000);
      const refLog = { errors: [], blocked: [], notes: [] };
      const query = referenceQuery(graded.images.judged, result.numbers, rubric.thresholds, item.referenceQuery);
      let ref = null;
      try {
        const r = await openers.reference.open({ root: plan.repo, rel: `${item.part}/index.html`, query: query.toString(), log: refLog });
        if (!r.why) {
          await r.driver.tick(500, 30);
          ref = await r.driver.snap();
          const scene = await r.page.evaluate(() => window.scene || null).catch(() => null);
          result.referenceState = referenceStateOf(query, scene);
        }
        await openers.reference.done(true);
      } catch (err) {
        await openers.reference.done(false);
        result.notes.push(`our reference could not be drawn: ${err.message.split('\n')[0]}`);
      }
      const { width, height } = graded.images.judged;
      if (ref && ref.width === width && ref.height === height) {
        const cmp = compareImages(PNG.sync.read(png(ref)), PNG.sync.read(png(graded.images.judged)));
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
