// Frozen time in a graded page, the same in the grader's Playwright page and in the check page's
// frame: an init script that stands in for Date, performance.now, setTimeout/setInterval,
// requestAnimationFrame and requestIdleCallback. Nothing fires until the runner says so:
//   __checkClock.runFor(ms)      every timer and animation frame due in the next ms, in order;
//   __checkClock.fastForward(ms) jumps ms ahead: each timer due by then fires once.
// Between two callbacks a real task passes (a MessageChannel message), so the promises a page's
// frame starts (a WebGPU readback, a fetch) settle; timers are ordered by due time, then creation;
// an animation frame is due at the next multiple of 16 ms; a timer made while one fires is due at
// least 1 ms later (the rules of Playwright's clock). Unlike Playwright's clock, whose
// performance.now() starts at the real milliseconds between its install and its pause, and which
// replays every step of every earlier document of the context, the page's time here depends only
// on what the runner asked for: a page that turns its camera by a frame's timestamp starts at the
// same angle on every run.

/** The frozen wall time a graded page starts at, the grader's and the check page's alike (2026-01-05 09:00 UTC, ms since 1970). */
export const FROZEN = Date.UTC(2026, 0, 5, 9, 0, 0);

/** The init script. `start` is the frozen wall time (ms since 1970) at performance.now() = 0; the page
 * loads 2 s later (as the grader's clock: installed at `start`, paused at `start` + 2 s). */
// eslint-disable-next-line max-lines-per-function -- over 80 lines: still to split into named parts (issue 40)
export function frameClockScript(start) {
  if (window.__checkClock) return;
  const NativeDate = Date, realPerformance = performance;
  const timers = new Map();
  let ticks = 2000, nextId = 1e12, duringTick = false;
  const channel = new MessageChannel(), tasks = [];
  channel.port1.onmessage = () => tasks.shift()();
  const realTask = () => new Promise((resolve) => { tasks.push(resolve); channel.port2.postMessage(0); });

  function add(type, func, delay, args) {
    if (typeof func !== 'function' && typeof func !== 'string') throw new TypeError(`${type}: a callback is required`);
    delay = Number.isFinite(+delay) ? Math.max(0, +delay) : 0;
    if (delay > 2 ** 31 - 1) delay = 1;
    const id = nextId++;
    timers.set(id, { id, type, func, args, delay, createdAt: ticks, callAt: ticks + (delay || (duringTick ? 1 : 0)) });
    return id;
  }
  const clear = (id) => { if (id) timers.delete(Number(id)); };
  function first(before) {
    let best = null;
    for (const t of timers.values()) {
      if (t.callAt > before) continue;
      if (!best || t.callAt < best.callAt || (t.callAt === best.callAt && (t.createdAt < best.createdAt || (t.createdAt === best.createdAt && t.id < best.id)))) best = t;
    }
    return best;
  }
  async function runTo(to) {
    to = Math.ceil(to);
    let error;
    for (let t = first(to); t; t = first(to)) {
      ticks = Math.max(ticks, t.callAt);
      if (t.type === 'interval') t.callAt += t.delay || 1;
      else timers.delete(t.id);
      duringTick = true;
      if (window.__checkWatch) window.__checkWatch.newTask(); // check/frame-watch.js: a loop is timed from here
      try {
        if (typeof t.func === 'string') (0, eval)(t.func);
        else if (t.type === 'frame') t.func(ticks);
        else if (t.type === 'idle') t.func({ didTimeout: false, timeRemaining: () => 0 });
        else t.func(...t.args);
      } catch (err) {
        error = error || err; // as under Playwright's clock: no page error, runFor rejects with the first
      } finally {
        duringTick = false;
      }
      await realTask();
    }
    ticks = Math.max(ticks, to);
    if (error) throw error;
  }

  const api = {
    setTimeout: (f, ms, ...args) => add('timeout', f, ms, args),
    setInterval: (f, ms, ...args) => add('interval', f, ms, args),
    clearTimeout: clear,
    clearInterval: clear,
    requestAnimationFrame: (f) => add('frame', f, 16 - (ticks % 16), []),
    cancelAnimationFrame: clear,
    requestIdleCallback: (f, opts) => add('idle', f, Math.min(opts && opts.timeout ? opts.timeout : Infinity, timers.size ? 50 : 0), []),
    cancelIdleCallback: clear,
  };
  for (const [name, fn] of Object.entries(api)) window[name] = fn;

  function ClockDate(...args) {
    if (!new.target) return new NativeDate(start + ticks).toString();
    return args.length ? new NativeDate(...args) : new NativeDate(start + ticks);
  }
  ClockDate.prototype = NativeDate.prototype;
  ClockDate.now = () => start + ticks;
  ClockDate.parse = NativeDate.parse;
  ClockDate.UTC = NativeDate.UTC;
  ClockDate.toString = () => NativeDate.toString();
  window.Date = ClockDate;
  Object.defineProperty(realPerformance, 'now', { value: () => ticks, configurable: true });

  Object.defineProperty(window, '__checkClock', {
    enumerable: false,
    value: {
      runFor: (ms) => runTo(ticks + Math.max(0, ms)),
      fastForward: (ms) => {
        const to = ticks + Math.trunc(Math.max(0, ms));
        for (const t of timers.values()) if (t.callAt < to) t.callAt = to;
        return runTo(to);
      },
      now: () => ticks,
      pending: () => timers.size,
    },
  });
}
