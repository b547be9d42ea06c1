// The grading's progress as a person reads it: parts done of all, hand-ins done of all, the time
// so far and an estimate of the time left. One line rewritten in place on a terminal, a plain
// line a part in a log (CI), through progress-line.js (the tools' progress line). Chromium's run feeds it from
// its Playwright reporter (progress-reporter.js), Firefox's loop (grade-firefox.js) directly.
// Only output: nothing here touches what is gathered.
import { progressLine } from './progress-line.js';
import { verdictOfPart } from '../../files/part-verdict.js';

export { verdictOfPart };


/** A time as a clock reads: "0:07", "3:25", "1:02:09". */
export function clock(ms) {
  const s = Math.max(0, Math.round(ms / 1000));
  const two = (n) => String(n).padStart(2, '0');
  const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60);
  return h ? `${h}:${two(m)}:${two(s % 60)}` : `${m}:${two(s % 60)}`;
}

/**
 * The time left, in ms, from the parts opened in the browser so far: `elapsedMs` spread over the
 * `opened` done, for the `toOpen` still waiting (a part with no page is written at once and costs
 * nothing). Null before the first is done.
 */
export function timeLeft({ opened, toOpen, elapsedMs }) {
  if (toOpen === 0) return 0;
  if (!opened) return null;
  return (elapsedMs / opened) * toOpen;
}

/**
 * The line: "12 of 40 parts · 2 of 8 hand-ins · 0:48 so far · about 1:52 left".
 * @param {{parts: number, partsAll: number, handins: number, handinsAll: number, elapsedMs: number, leftMs: number|null}} counts
 */
export function progressText({ parts, partsAll, handins, handinsAll, elapsedMs, leftMs }) {
  const left = leftMs === null ? 'time left: after the first part' : `about ${clock(leftMs)} left`;
  return `${parts} of ${partsAll} parts · ${handins} of ${handinsAll} hand-ins · ${clock(elapsedMs)} so far · ${left}`;
}

/** The last line: "graded 40 parts of 8 hand-ins in 3:25". */
export function doneText({ parts, handinsAll, elapsedMs }) {
  return `graded ${parts} part(s) of ${handinsAll} hand-in(s) in ${clock(elapsedMs)}`;
}

/**
 * Follows a run over the plan's `items` ({ name, part, page, linksTo }): `ended(item, { verdict,
 * trouble })` as each part ends, `above(line)` for a line that stays, `finish()` at the end. On a
 * terminal the line is rewritten every second too, so that the time so far moves; in a log each
 * part ends with a line of its own, its verdict first.
 * @param {object[]} items @param {{stream?: object, now?: () => number}} [options]
 */
export function gradingProgress(items, { stream = process.stdout, now = Date.now } = {}) {
  const started = now();
  const line = progressLine('grade', { stream, interval: 0, now });
  const opens = (item) => !!item.page && !item.linksTo;
  const partsLeft = new Map();
  for (const item of items) partsLeft.set(item.name, (partsLeft.get(item.name) || 0) + 1);
  const state = { parts: 0, handins: 0, opened: 0, toOpen: items.filter(opens).length };
  const text = () => {
    const elapsedMs = now() - started;
    return progressText({
      parts: state.parts,
      partsAll: items.length,
      handins: state.handins,
      handinsAll: partsLeft.size,
      elapsedMs,
      leftMs: timeLeft({ opened: state.opened, toOpen: state.toOpen, elapsedMs }),
    });
  };
  const timer = stream.isTTY ? setInterval(() => line(text()), 1000) : null;
  timer?.unref?.();
  if (stream.isTTY) line(text());
  return {
    ended(item, { verdict = '', trouble = '' } = {}) {
      state.parts++;
      if (opens(item)) {
        state.opened++;
        state.toOpen--;
      }
      const left = partsLeft.get(item.name) - 1;
      partsLeft.set(item.name, left);
      if (left === 0) state.handins++;
      if (trouble) line.above(`grade: ${item.name} ${item.part}: ${trouble}`);
      line(stream.isTTY ? text() : `${item.name} ${item.part} ${verdict || (trouble ? 'stopped' : '')} · ${text()}`);
    },
    above: (text) => line.above(text),
    finish() {
      if (timer) clearInterval(timer);
      line.end(doneText({ parts: state.parts, handinsAll: partsLeft.size, elapsedMs: now() - started }));
    },
  };
}
