// A progress line for a long run, as every command here shows one (tools/cli.js gives it to the
// tools, progress.js to the grader): rewritten in place on a terminal, plain lines in a log.

/** How often a log (not a terminal) gets a progress line, at most. */
const LOG_INTERVAL_MS = 2000;

/**
 * A progress line for a long run: rewritten in place on a terminal, and in a log file a plain
 * line every `interval` ms at most (every call with 0). `progress(text)` shows it;
 * `progress.above(line)` prints a line that stays, above it; `progress.end(text)` leaves `text`
 * as the last line; `progress.last` is the last text shown.
 * @param {string} name the command's name, e.g. "bench"
 * @param {{stream?: {write: (s: string) => void, isTTY?: boolean, columns?: number}, interval?: number, now?: () => number}} [options]
 *   where it goes (stderr), how often a log gets a line (2000 ms), the clock (Date.now)
 */
export function progressLine(name, { stream = process.stderr, interval = LOG_INTERVAL_MS, now = Date.now } = {}) {
  let printed = -Infinity, shown = false;
  const tty = !!stream.isTTY;
  // on a terminal: back to the line's start, the text cut to the terminal's width, the rest cleared
  const draw = (text) => stream.write(`\r${`[${name}] ${text}`.slice(0, Math.max(20, (stream.columns || 80) - 1))}\x1b[K`);
  const progress = (text) => {
    progress.last = text;
    if (tty) {
      draw(text);
      shown = true;
    } else if (now() - printed >= interval) {
      printed = now();
      stream.write(`[${name}] ${text}\n`);
    }
  };
  progress.above = (line) => {
    if (tty && shown) stream.write('\r\x1b[K');
    stream.write(`${line}\n`);
    if (tty && shown) draw(progress.last);
  };
  progress.end = (text) => {
    progress.last = text;
    if (tty) stream.write(`${shown ? '\r' : ''}[${name}] ${text}\x1b[K\n`);
    else stream.write(`[${name}] ${text}\n`);
    shown = false;
  };
  progress.last = '';
  return progress;
}
