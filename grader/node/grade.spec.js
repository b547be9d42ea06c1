// The grader's harness: one Playwright test per part of the plan that grader/node/grade.js wrote
// (GRADE_PLAN). Each opens the part (playwright-page.js: served by serve-submission.js, time
// frozen, instrumented), gathers it and audits the artifact (grader/core/grade-part.js), saves the
// artifact (artifacts.js) and the result (part-result.js), and draws our reference beside it.
import { test } from '@playwright/test';
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { compareImages } from './compare.js';
import { partOpener } from './playwright-page.js';
import { writeArtifact, pngOf } from './artifacts.js';
import { applyAudit } from './part-result.js';
import { gradePart, addTime } from '../core/grade-part.js';
import { referenceQuery, referenceStateOf } from '../core/reference-state.js';

const plan = JSON.parse(readFileSync(process.env.GRADE_PLAN, 'utf8'));
const rubric = plan.rubric;

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
    let graded = { fail: null, checks: [], actions: [], images: {}, shown: {}, busy: 0 };
    let files = {};
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
        // the outer bound: past 85% of it a part is too slow to judge here (time is left to write what was seen)
        const deadline = started + 0.85 * rubric.timeoutSeconds * 1000;
        graded = await gradePart(opened.driver, { part: item.part, rubric, deadline, timing, progress: (what) => {
          result.reasons = [`the page did not finish within the rubric's bound of ${rubric.timeoutSeconds} s: stopped while ${what} (a click or frame that never returns?)`];
          save(item, result);
        } });
        const t0 = Date.now();
        const { facts, images } = graded.artifact;
        const saved = writeArtifact(item.artifactDir, { facts: { ...facts, blocked: result.blocked, notes: result.notes }, images });
        const rel = path.relative(plan.out, item.artifactDir).split(path.sep).join('/');
        for (const [name, file] of Object.entries(saved)) files[name] = `${rel}/${file}`;
        phase('write', t0);
      }
      clean = true;
    } catch (err) {
      if (/Test ended|Target page, context or browser has been closed/.test(err.message)) throw err; // the time bound: stays 'timeout'
      // the grader's own trouble with this page: never a pass on it, a teacher looks
      graded.checks = [{ level: 'review', reason: `the grader could not finish on this page: ${err.message.split('\n')[0]}` }];
      if (process.env.GRADE_DEBUG) console.error(err);
    } finally {
      const t0 = Date.now();
      await openers.student.done(clean);
      phase('close', t0);
    }
    applyAudit(result, graded, files);
    result.seconds = (Date.now() - started) / 1000;
    const dir = path.dirname(item.resultFile);
    const stem = path.basename(item.resultFile, '.json');
    const relDir = path.relative(plan.out, dir).split(path.sep).join('/');
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
        const cmp = compareImages(PNG.sync.read(pngOf(ref)), PNG.sync.read(pngOf(graded.images.judged)));
        Object.assign(result, { mismatch: cmp.mismatch, rmse: cmp.rmse, comparison: cmp.comparison, mismatchFull: cmp.mismatchFull, mismatchObject: cmp.mismatchObject });
        result.notes.push(...cmp.notes, `the reference is our page at the same canvas size${result.referenceState && result.referenceState.light ? ', lit from the fitted light' : ''}; the difference is evidence, the verdict comes from the checks`);
        writeFileSync(path.join(dir, `${stem}-reference.png`), PNG.sync.write(cmp.reference));
        writeFileSync(path.join(dir, `${stem}-diff.png`), PNG.sync.write(cmp.diff));
        Object.assign(result.images, { reference: `${relDir}/${stem}-reference.png`, diff: `${relDir}/${stem}-diff.png` });
      } else if (ref) result.notes.push(`our reference drew ${ref.width}×${ref.height}, not ${width}×${height}: not compared`);
      save(item, result);
    }
  });
}
