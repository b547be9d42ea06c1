#!/usr/bin/env node
// npm run grade: a student's submission (or a class of them) against this site's reference parts,
// in a report a grader can read: reference | submission | difference for every part, with numbers.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PARTS, findPartsWithNotes } from '../../files/parts.js';
import { linkedPart } from '../../class/linked-part.js';
import { readLabels, agreementText } from '../report/labels.js';
import { writeClass } from '../report/report.js';
import { partFiles } from '../../files/layout.js';
import { mergeRubric } from '../../core/rubric.js';
import { CHROMIUM, CHROMIUM_HOW, CHROMIUM_INSTALL, CHROMIUM_MISSING } from '../run/chromium.js';
import { FIREFOX, FIREFOX_INSTALL, FIREFOX_MISSING } from '../run/firefox.js';
import { versionOfExecutable, nameOfVersionLine } from '../run/browser-version.js';
import { gradeInFirefox } from '../run/grade-firefox.js';
import { gradingProgress } from './progress.js';
import { auditAgain, regatherLines } from '../run/audit-only.js';
import { takeIn } from '../sites/intake/batch.js';
import { dueTime } from '../../class/intake/formats.js';
import { readClass } from '../report/class-results.js';
import { prepareClass, teacherLines } from './teacher-loop.js';
import { runSimilarity, writeSimilarityReport, SIMILARITY_HELP, parseBound } from '../../similarity/run.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '../../..');
const RUN = path.join(here, '../run'); // (the Playwright run: its config, its harness)
const HELP = `usage: npm run grade -- <submission-folder> [--part WP04P1=<path to html>]... [--rubric <file>] [--out <dir>]
       npm run grade -- --batch <download.zip | its folder | a folder a student> [--rubric <file>] [--out <dir>]
--batch takes a course site's download as it comes (its .zip or the folder it unpacked into, either
one inside a folder around it, as a Mac zips it again) and says which it found: Brightspace (a
folder a submission, "<id>-<id> - <name> - <date>"), Canvas (files "<lastfirst>_<user id>_<file
id>_<name>"), Moodle (folders "<name>_<id>_assignsubmission_file"), or a folder a student; anything
else is refused with what was found. Each hand-in is unpacked safely into OUT/handins/ (zips in it
too; bounds: the rubric's unpack), the latest of a student's hand-ins is graded, and the student's
identity goes into report.json and the grade files.
Opens each part (WP04P1 ... WP04P5, found by folder or file name: WP04P1, Part1, p01, w4p1,
week04p01, ...) in Chromium, Chrome or Edge (WebGL or WebGPU) with time frozen, finds its controls, stops the
orbit, subdivides until the silhouette settles, and gives each part a verdict (pass, review,
fail) with reasons, from what the slide's step asks for. Our reference part is drawn beside it.
  --browser B       chromium (the default: WebGL and WebGPU) or firefox (WebGL only; a WebGPU part
                    is "not graded here", never failed): the machine's own browser, never a
                    downloaded one (CHROMIUM_PATH, FIREFOX_PATH choose another; the browsers here
                    are named below, and the report names the one that graded, with its version)
  --part P=FILE     use FILE (relative to the submission) for part P
  --rubric FILE     a rubric in place of grader/core/rubric.json (copy that file and edit it: time bounds,
                    thresholds, control patterns, what each part must show)
  --out DIR         where report.html, report.json (and grades.csv in batch mode) go
                    (default out/grade/<name>)
  --shard I/N       grade only the I-th of N shares of the parts (Playwright's sharding), to split a
                    class across machines: copy each machine's OUT/parts/ and OUT/artifacts/ into
                    one OUT, and run --batch <the download> --report-only --out OUT on it
  --report-only     rebuild the report, grade files and feedback from the parts already graded in
                    --out (with --batch: the download's identities and similarity taken in again)
  --audit-only OUT  judge the parts graded in OUT again from their saved artifacts (OUT/artifacts/), with
                    the rubric given (--rubric) and no browser, in seconds; rewrites OUT's results and
                    report (with --labels, the agreement too). A part whose gathering read a key that
                    rubric changes (a slider's change bound, how many controls to try: the keys are
                    in its facts.json, gatheredWith) is named: its verdict stands on what was
                    gathered under the old value
  --regather-changed  with --audit-only: gathers those parts again in the browser, under that rubric
  --workers N       parts graded at once (default 2)
  --verbose         a line a part as it ends (Playwright's own list; in Firefox the part's time and
                    verdict) in place of the progress line (parts and hand-ins done of all, the time
                    so far and about how long is left: rewritten in place on a terminal, a plain
                    line a part in a log)
  --labels FILE     your own labels (TSV: submission, part, label = correct | partial | broken, reasons):
                    the report and stdout add the agreement per part, a label × verdict table and
                    every disagreement with both sides' reasons (correct → pass, partial → review,
                    broken → fail)
  --overrides FILE  the teacher's verdicts (TSV: student, part, verdict, note to the student; default
                    OUT/overrides.tsv when it is there): applied by grading, --audit-only and
                    --report-only alike; the report shows the grader's beside each, the grade files
                    and the feedback use the teacher's and say so
  --roster FILE     the course site's class list export (CSV or TSV: OrgDefinedId / Username,
                    ID number / Email address, names; kept as OUT/roster.csv), for the ids its grade
                    import needs and the download does not carry (Brightspace, Moodle)
  --due "YYYY-MM-DD HH:MM"  the due date, in the course site's time: a hand-in whose time (in
                    Brightspace's names) is after it is late; Canvas's names say late themselves,
                    Moodle's carry no time
Besides report.html, report.json and grades.csv, every run writes grades-points.csv, the course
site's grade import file (grades-brightspace.csv, grades-canvas.csv or grades-moodle.csv; points:
the rubric's "points"), OUT/feedback/<student>.html (one self-contained page a student) and
feedback-<site>.zip, laid out as the course site takes feedback files back.
${SIMILARITY_HELP}
exit codes: 0 it ran (whatever the verdicts), 1 it could not run (no browser: it says the command that
installs one), 2 bad usage`;

/** The browsers this machine would grade in, for --help: name, version and where, or how to install one. */
function browsersHere() {
  const line = (title, file, install) => {
    if (!file) return `  ${title}: none found; install one with: ${install}`;
    return `  ${title}: ${versionOfExecutable(file) || '(its --version says nothing)'} at ${file}`;
  };
  return `browsers on this machine (the report names the one that graded):\n${line('chromium', CHROMIUM, CHROMIUM_INSTALL)}\n${line('firefox', FIREFOX, FIREFOX_INSTALL)}`;
}

function fail(message, code = 1) {
  console.error(`grade: ${message}`);
  process.exit(code);
}

function parseArgs(argv) {
  const o = { parts: {}, positional: [] };
  for (let k = 0; k < argv.length; k++) {
    const a = argv[k];
    // (an option's value is never the next option: "--audit-only --out x" would grade into a folder named --out)
    const next = () => (k + 1 < argv.length && !argv[k + 1].startsWith('--') ? argv[++k] : fail(`${a} needs a value\n\n${HELP}`, 2));
    if (a === '--help' || a === '-h') { console.log(`${HELP}\n${browsersHere()}`); process.exit(0); }
    else if (a === '--batch') o.batch = next();
    else if (a === '--rubric') o.rubric = next();
    else if (a === '--out') o.out = next();
    else if (a === '--shard') o.shard = next();
    else if (a === '--workers') o.workers = next();
    else if (a === '--labels') o.labels = next();
    else if (a === '--overrides') o.overrides = next();
    else if (a === '--roster') o.roster = next();
    else if (a === '--due') {
      const text = next();
      o.due = dueTime(text) ?? fail(`--due takes the due date and time as "2025-10-10 23:59" (the course site's time), not "${text}"\n\n${HELP}`, 2);
    }
    else if (a === '--browser') {
      o.browser = next().toLowerCase();
      if (!BROWSERS.includes(o.browser)) fail(`--browser takes ${BROWSERS.join(' or ')}, not "${o.browser}"\n\n${HELP}`, 2);
    }
    else if (a === '--report-only') o.reportOnly = true;
    else if (a === '--verbose') o.verbose = true;
    else if (a === '--audit-only') o.auditOnly = next();
    else if (a === '--regather-changed') o.regatherChanged = true;
    else if (a === '--similarity-only') o.similarityOnly = true;
    else if (a === '--similarity-bound') o.similarityBound = parseBound(next()) ?? fail(`--similarity-bound takes a number in (0, 1]\n\n${HELP}`, 2);
    else if (a === '--part') {
      const m = /^(WP04P[1-5])=(.+)$/i.exec(next());
      if (!m) fail(`--part takes WP04Pn=<path>\n\n${HELP}`, 2);
      o.parts[m[1].toUpperCase()] = m[2];
    } else if (a.startsWith('--')) fail(`unknown option ${a}\n\n${HELP}`, 2);
    else o.positional.push(a);
  }
  if (o.regatherChanged && !o.auditOnly) fail(`--regather-changed goes with --audit-only <out>\n\n${HELP}`, 2);
  if (o.similarityOnly && !o.batch) fail(`--similarity-only compares a class: give --batch <folder>\n\n${HELP}`, 2);
  if (!o.batch && o.positional.length !== 1 && !o.reportOnly && !o.auditOnly) fail(`give one submission folder or --batch <folder>\n\n${HELP}`, 2);
  return o;
}

const BROWSERS = ['chromium', 'firefox'];
const DEFAULT_RUBRIC = path.join(here, '../../core/rubric.json');

/** The rubric: grader/core/rubric.json, or the teacher's file in its place (keys it leaves out keep the defaults). */
function readRubric(file) {
  const load = (f) => {
    try {
      return JSON.parse(readFileSync(f, 'utf8'));
    } catch (err) {
      return fail(`cannot read the rubric ${f}: ${err.message}`, 2);
    }
  };
  try {
    return mergeRubric(load(DEFAULT_RUBRIC), file ? load(file) : null);
  } catch (err) {
    return fail(`${file}: ${err.message}`, 2);
  }
}

async function main() {
  const o = parseArgs(process.argv.slice(2));
  const rubric = readRubric(o.rubric);
  let labels = null;
  if (o.labels) {
    try {
      labels = readLabels(o.labels);
    } catch (err) {
      fail(`cannot read the labels: ${err.message}`, 2);
    }
  }
  let submissions;
  const named = o.batch ? path.basename(path.resolve(o.batch), '.zip') : path.basename(path.resolve(o.positional[0] || 'report'));
  const out = o.auditOnly ? path.resolve(o.auditOnly) : path.resolve(o.out || path.join(repo, 'out/grade', named));
  mkdirSync(out, { recursive: true });
  if (o.batch) {
    // a course site's download (its .zip or its folder), or a folder a student (intake/)
    const root = path.resolve(o.batch);
    if (!existsSync(root)) fail(`no such file or folder: ${o.batch}`);
    try {
      submissions = takeIn(root, out, rubric, { due: o.due }).submissions;
    } catch (err) {
      fail(err.message);
    }
    if (!submissions.length && !existsSync(path.join(out, 'parts'))) fail(`${o.batch} has no hand-ins`);
  } else if (!o.reportOnly && !o.auditOnly) {
    const root = path.resolve(o.positional[0]);
    if (!existsSync(root) || !statSync(root).isDirectory()) fail(`no such folder: ${o.positional[0]}`);
    submissions = [{ name: path.basename(root), root }];
  }

  if (o.auditOnly) {
    if (!existsSync(path.join(out, 'parts'))) fail(`nothing graded in ${out}: --audit-only judges a class graded before (its artifacts/ and parts/)`);
    const t0 = Date.now();
    const progress = (k, n) => { if (process.stdout.isTTY) process.stdout.write(`\rgrade: audited ${k} of ${n} parts`); };
    let { audited, without, stale, unknown } = await auditAgain(out, rubric, progress);
    console.log(`\rgrade: audited ${audited} parts from their artifacts in ${((Date.now() - t0) / 1000).toFixed(1)} s${without.length ? `; ${without.length} without an artifact kept their verdict (${without.join(', ')})` : ''}`);
    if (stale.length && o.regatherChanged) {
      // the parts whose gathering read a key this rubric changes, gathered again under it (their plan's items)
      const planned = existsSync(path.join(out, 'plan.json')) ? JSON.parse(readFileSync(path.join(out, 'plan.json'), 'utf8')).items : [];
      const items = planned.filter((x) => stale.some((s) => s.name === x.name && s.part === x.part));
      console.log(`grade: --regather-changed: gathering ${items.length} of ${stale.length} part(s) again under this rubric`);
      if (items.length) await runPlan(o, out, rubric, items, path.join(out, 'plan-regather.json'));
      ({ stale, unknown } = await auditAgain(out, rubric, progress));
    }
    for (const line of regatherLines(stale)) console.log(`grade: ${line}${o.regatherChanged ? '' : ' (--regather-changed does it)'}`);
    if (unknown.length) console.log(`grade: ${unknown.length} part(s) were gathered before artifacts kept the rubric keys their gathering read: whether this rubric would gather them otherwise is not known (grade them again to know): ${unknown.join(', ')}`);
  } else if (!o.reportOnly && !o.similarityOnly && submissions.length) {
    await gradeParts(o, out, rubric, submissions);
  }

  await reportClass(o, out, rubric, labels, submissions);
}

/** The parts of `submissions` graded in the browser the options name (Chromium through Playwright, or Firefox), into `out`. */
async function gradeParts(o, out, rubric, submissions) {
  const items = [];
  for (const s of submissions) {
    const { parts, notes } = findPartsWithNotes(s.root, o.batch ? {} : o.parts);
    for (const part of PARTS) {
      const cfg = rubric.parts[part] || {};
      const page = parts[part] && existsSync(path.join(s.root, parts[part])) ? parts[part] : null;
      // a page that only links to another part's page is graded once, as that part
      const html = page ? readFileSync(path.join(s.root, page), 'utf8') : null;
      const linksTo = page ? linkedPart(html, page, parts, { pathImpl: path }) : null;
      items.push({
        name: s.name, part, root: s.root, page,
        ...(linksTo ? { linksTo } : {}),
        ...(notes[part] ? { foundBy: notes[part] } : {}),
        referenceQuery: cfg.referenceQuery || {},
        ...partFiles(out, s.name, part),
      });
    }
  }
  // the parts that try the most first (the sliders, then the orbit's), so that the workers end
  // together on the short ones: a class's time is then near its sum over the workers
  const FIRST = ['WP04P4', 'WP04P3', 'WP04P5', 'WP04P2', 'WP04P1'];
  items.sort((a, b) => FIRST.indexOf(a.part) - FIRST.indexOf(b.part));
  await runPlan(o, out, rubric, items, path.join(out, 'plan.json'));
}

/** `items` (a plan's parts) graded in the browser the options name, under `rubric`, into `out`; the plan written to `planFile`. */
async function runPlan(o, out, rubric, items, planFile) {
  const browser = o.browser || 'chromium';
  if (browser === 'firefox' && !FIREFOX) fail(`${FIREFOX_MISSING}\n(or grade in Chromium: leave out --browser firefox)`);
  if (browser === 'chromium' && !CHROMIUM) fail(CHROMIUM_MISSING);
  const executable = browser === 'firefox' ? FIREFOX : CHROMIUM;
  // the browser's own name ("Chromium", "Google Chrome", "Mozilla Firefox"): the report adds the version that ran
  const browserName = nameOfVersionLine(versionOfExecutable(executable), browser === 'firefox' ? 'Firefox' : 'Chromium');
  const submissions = new Set(items.map((x) => x.name));
  const plan = {
    repo,
    out,
    browser,
    browserName,
    browserPath: executable,
    rubric,
    timeoutSeconds: rubric.timeoutSeconds,
    items,
  };
  writeFileSync(planFile, JSON.stringify(plan, null, 1));
  const how = browser === 'chromium' ? `, found by ${CHROMIUM_HOW}` : '';
  console.log(`grade: ${submissions.size} submission(s), ${items.length} parts in ${browserName} (${executable}${how}); ${o.workers || 2} at a time, at most ${rubric.timeoutSeconds} s for each student page`);
  if (browser === 'firefox') {
    // (--shard I/N: every N-th part from the I-th, as a class is split over machines)
    const [i, n] = (o.shard || '1/1').split('/').map(Number);
    if (!(n >= 1 && i >= 1 && i <= n)) fail(`--shard takes I/N with 1 ≤ I ≤ N\n\n${HELP}`, 2);
    try {
      const share = items.filter((_, k) => k % n === i - 1);
      await gradeInFirefox(
        { ...plan, items: share },
        { workers: Number(o.workers || 2), progress: o.verbose ? null : gradingProgress(share) },
      );
    } catch (err) {
      fail(`could not grade in Firefox: ${err.message.split('\n')[0]}`);
    }
  } else {
    const args = ['test', '-c', path.join(RUN, 'playwright.config.js')];
    if (o.shard) args.push('--shard', o.shard);
    rmSync(path.join(out, 'blob-report'), { recursive: true, force: true });
    const run = spawnSync(process.execPath, [path.join(repo, 'node_modules/@playwright/test/cli.js'), ...args], {
      cwd: RUN, stdio: 'inherit',
      env: { ...process.env, GRADE_PLAN: planFile, GRADE_WORKERS: o.workers || '2',
        ...(o.verbose ? { GRADE_VERBOSE: '1' } : { GRADE_REPORTER: path.join(here, 'progress-reporter.js') }) },
    });
    if (run.error) fail(`could not start Playwright: ${run.error.message}`);
  }
}

/** The class graded in `out` (every shard's parts): similarity, the report, grades.csv, the teacher's files, and the summary lines. */
async function reportClass(o, out, rubric, labels, submissions) {
  // gather every part graded in this out folder (all shards, once they are copied together)
  const partsDir = path.join(out, 'parts');
  const similar = o.batch ? await runSimilarity(submissions, out, { bound: o.similarityBound ?? undefined }) : null;
  if (o.similarityOnly && !existsSync(partsDir)) {
    writeSimilarityReport(out, similar, submissions.map((s) => s.name));
    console.log(`grade: similarity report at ${path.join(out, 'report.html')}`);
    return;
  }
  if (!existsSync(partsDir)) fail(`nothing graded in ${out} yet`);
  const graded = readClass(partsDir);
  let loop;
  try {
    loop = prepareClass(out, graded, { overrides: o.overrides, roster: o.roster });
  } catch (err) {
    fail(err.message, 2);
  }
  // a class (its intake.json: taken in by --batch, here or on the machine of each shard) gets its
  // grades.csv from every part in parts/, --report-only too, so none is left from one shard or
  // from before an override
  const aClass = o.batch || existsSync(path.join(out, 'intake.json'));
  const made = writeClass(out, graded, { labels, similar, aClass, site: loop.site, rubric });
  const { rows, agreed } = made;
  if (aClass && !o.batch) console.log('grade: the similarity compares the hand-ins themselves: give --batch with the download as well to have it in the report');
  for (const s of rows) {
    console.log(`${s.name}: ${s.passes} of ${PARTS.length} pass · ` + s.parts.map((p) => `${p.part} ${p.verdict}${p.api ? ` (${p.api})` : ''}`).join(', '));
  }
  if (agreed) for (const line of agreementText(agreed)) console.log(line);
  for (const line of [...loop.lines, ...teacherLines(out, made)]) console.log(`grade: ${line}`);
  const browsers = [...new Set(rows.flatMap((s) => s.parts.map((p) => p.browserVersion).filter(Boolean)))];
  if (browsers.length) console.log(`grade: graded in ${browsers.join(' and ')}`);
  console.log(`grade: report at ${path.join(out, 'report.html')}`);
}

main().catch((err) => fail(err.message));
