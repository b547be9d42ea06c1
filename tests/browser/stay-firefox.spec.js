// A graded page cannot close or leave itself (grader/browser/stay.js), graded live in both browsers
// as a teacher runs npm run grade: signe's WP04P1 has a "Close this window" button
// (onclick="self.close()") that the grader clicks looking for a coarsen button, and malte's WP04P1
// two buttons that set window.location.href (the course's index, the next part). Both parts are
// right otherwise and get their labels (pass), each with a note that names the button and says
// the grader kept the page. In Firefox, without the no-op close, the page closed itself and the
// part was "not graded here" (Attempted to use detached Frame); without the take-back the page was
// gone in either browser (a review: the grader could not finish). Project "firefox" only (it
// launches both browsers itself, through the grader's command).
import { spawnSync } from 'node:child_process';
import { cpSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test, expect } from '@playwright/test';

const HANDINS = path.resolve(import.meta.dirname, '../fixtures/handins');

for (const browser of ['firefox', 'chromium']) {
  test(`--browser ${browser}: a page's close button and the buttons that leave it are kept from acting, noted, and the parts get their labels`, () => {
    test.setTimeout(180_000);
    const dir = mkdtempSync(path.join(os.tmpdir(), `stay-${browser}-`));
    cpSync(path.join(HANDINS, 'signe/worksheet4/part1.html'), path.join(dir, 'class/signe/worksheet4/part1.html'));
    cpSync(path.join(HANDINS, 'malte/uge04/part1'), path.join(dir, 'class/malte/uge04/part1'), { recursive: true });
    const labels = path.join(dir, 'labels.tsv');
    writeFileSync(labels, 'submission\tpart\tlabel\treasons\nsigne\tWP04P1\tcorrect\ta close button\nmalte\tWP04P1\tcorrect\tbuttons that leave\n');
    const out = path.join(dir, 'out');
    const run = spawnSync(process.execPath, ['grader/node/cli/grade.js', '--batch', path.join(dir, 'class'), '--browser', browser, '--workers', '1',
      '--rubric', 'tests/fixtures/test-rubric.json', '--labels', labels, '--out', out], { encoding: 'utf8', timeout: 170_000 });
    expect(run.status, run.stderr + run.stdout.slice(-3000)).toBe(0);
    const report = JSON.parse(readFileSync(path.join(out, 'report.json'), 'utf8'));
    const got = Object.fromEntries(report.submissions.flatMap((s) => s.parts.filter((p) => p.status !== 'missing').map((p) => [`${s.name} ${p.part}`, p])));
    const signe = got['signe WP04P1'], malte = got['malte WP04P1'];
    expect([signe.verdict, signe.api], signe.reasons.join(' | ')).toEqual(['pass', 'webgl']);
    expect(signe.reasons).toContain('note: the button "Close this window" tried to close the window: the grader kept it open (not a mistake of the step; the grading went on)');
    expect([malte.verdict, malte.api], malte.reasons.join(' | ')).toEqual(['pass', 'webgl2']);
    for (const to of ['../../index.html', '../part2/index.html']) {
      expect(malte.reasons.join(' | ')).toContain(`tried to leave the page for ${to}: the grader kept the page`);
    }
    expect(report.labels).toMatchObject({ agree: 2, total: 2 });
  });
}
