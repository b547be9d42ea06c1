// The Playwright reporter of the grader's Chromium run (playwright.config.js; --verbose puts
// Playwright's own list in its place): each test is a part of the plan (harness.js titles it
// "<name> <part>"), and its end moves the progress line of progress.js. A test that fails is the
// grader's own trouble, said in a line that stays.
import { readFileSync } from 'node:fs';
import { gradingProgress, verdictOfPart } from './progress.js';

export default class ProgressReporter {
  /** @param {{plan?: string, items?: object[], stream?: object, now?: () => number}} options the plan's file (or its items), where to print, the clock */
  constructor({ plan, items, stream = process.stdout, now = Date.now } = {}) {
    this.items = items || JSON.parse(readFileSync(plan, 'utf8')).items;
    this.stream = stream;
    this.now = now;
  }

  printsToStdio() {
    return true;
  }

  onBegin(config, suite) {
    const byTitle = new Map(this.items.map((item) => [`${item.name} ${item.part}`, item]));
    // the parts of this run: with --shard, this machine's share of the plan
    this.itemOf = new Map(suite.allTests().map((t) => [t, byTitle.get(t.title) || { name: t.title, part: '' }]));
    this.progress = gradingProgress([...this.itemOf.values()], { stream: this.stream, now: this.now });
  }

  onTestEnd(test, result) {
    const item = this.itemOf.get(test) || { name: test.title, part: '' };
    // (a part its time bound stopped is a timeout: its result says so)
    const trouble = result.status === 'failed' || result.status === 'interrupted' ? `the grader's own trouble: ${(result.error?.message || result.status).split('\n')[0]}` : '';
    this.progress.ended(item, { verdict: verdictOfPart(item), trouble });
  }

  onStdOut(chunk) {
    this.progress?.above(String(chunk).replace(/\n$/, ''));
  }

  onStdErr(chunk) {
    this.progress?.above(String(chunk).replace(/\n$/, ''));
  }

  onError(error) {
    const line = `grade: ${(error.message || String(error.value)).split('\n')[0]}`;
    if (this.progress) this.progress.above(line);
    else this.stream.write(`${line}\n`);
  }

  onEnd() {
    this.progress?.finish();
  }
}
