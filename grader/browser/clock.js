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

/**
 * The init script's body (its parts are passed in as arguments: the script is their text, see
 * clockScript). `start` is the frozen wall time (ms since 1970) at performance.now() = 0; the page
 * loads 2 s later (as the grader's clock: installed at `start`, paused at `start` + 2 s).
 */
function frameClock(start, timersOf, frozenDate) {
  if (window.__checkClock) return;
  const C = timersOf();
  const { timers, add, clear, runTo } = C;
  const api = {
    setTimeout: (f, ms, ...args) => add('timeout', f, ms, args),
    setInterval: (f, ms, ...args) => add('interval', f, ms, args),
    clearTimeout: clear,
    clearInterval: clear,
    requestAnimationFrame: (f) => add('frame', f, 16 - (C.ticks % 16), []),
    cancelAnimationFrame: clear,
    requestIdleCallback: (f, opts) =>
      add('idle', f, Math.min(opts && opts.timeout ? opts.timeout : Infinity, timers.size ? 50 : 0), []),
    cancelIdleCallback: clear,
  };
  for (const [name, fn] of Object.entries(api)) window[name] = fn;
  window.Date = frozenDate(Date, () => start + C.ticks);
  Object.defineProperty(performance, 'now', { value: () => C.ticks, configurable: true });

  Object.defineProperty(window, '__checkClock', {
    enumerable: false,
    value: {
      runFor: (ms) => runTo(C.ticks + Math.max(0, ms)),
      fastForward: (ms) => {
        const to = C.ticks + Math.trunc(Math.max(0, ms));
        for (const t of timers.values()) if (t.callAt < to) t.callAt = to;
        return runTo(to);
      },
      now: () => C.ticks,
      pending: () => timers.size,
      // the animation frames run so far, and how many callbacks the last one ran (the page's loops)
      frames: () => ({ count: C.frameCount, loops: C.frameCalls }),
    },
  });
}

/**
 * The page's timers, ordered by due time, then creation: { ticks (the page's time, ms), timers,
 * add(type, func, delay, args), clear(id), runTo(ms) } (every timer due by then fired in order, a
 * real task between two).
 */
function timersOf() {
  const C = { ticks: 2000, timers: new Map(), frameAt: null, frameCount: 0, frameCalls: 0 };
  const { timers } = C;
  let nextId = 1e12, duringTick = false;
  const channel = new MessageChannel(), tasks = [];
  channel.port1.onmessage = () => tasks.shift()();
  const realTask = () => new Promise((resolve) => { tasks.push(resolve); channel.port2.postMessage(0); });

  C.add = function add(type, func, delay, args) {
    if (typeof func !== 'function' && typeof func !== 'string') throw new TypeError(`${type}: a callback is required`);
    delay = Number.isFinite(+delay) ? Math.max(0, +delay) : 0;
    if (delay > 2 ** 31 - 1) delay = 1;
    const id = nextId++;
    timers.set(id, {
      id,
      type,
      func,
      args,
      delay,
      createdAt: C.ticks,
      callAt: C.ticks + (delay || (duringTick ? 1 : 0)),
    });
    return id;
  };
  C.clear = (id) => { if (id) timers.delete(Number(id)); };
  function first(before) {
    let best = null;
    for (const t of timers.values()) {
      if (t.callAt > before) continue;
      if (
        !best ||
        t.callAt < best.callAt ||
        (t.callAt === best.callAt &&
          (t.createdAt < best.createdAt || (t.createdAt === best.createdAt && t.id < best.id)))
      ) {
        best = t;
      }
    }
    return best;
  }
  C.runTo = async function runTo(to) {
    to = Math.ceil(to);
    let error;
    // (a frame followed by another in this run is seen by nobody: grader/browser/unseen-frames.js)
    const unseen = window.__grade && window.__grade.unseen;
    for (let t = first(to); t; t = first(to)) {
      C.ticks = Math.max(C.ticks, t.callAt);
      if (t.type === 'interval') t.callAt += t.delay || 1;
      else timers.delete(t.id);
      if (t.type === 'frame') {
        // every callback due at one time is one animation frame: a page with two loops runs two in it
        if (t.callAt !== C.frameAt) {
          Object.assign(C, { frameAt: t.callAt, frameCount: C.frameCount + 1, frameCalls: 0 });
        }
        C.frameCalls++;
      }
      duringTick = true;
      if (unseen && t.type === 'frame') unseen.frame(t.callAt, t.callAt + 16 <= to);
      if (window.__checkWatch) window.__checkWatch.newTask(); // check/frame-watch.js: a loop is timed from here
      try {
        if (typeof t.func === 'string') (0, eval)(t.func);
        else if (t.type === 'frame') t.func(C.ticks);
        else if (t.type === 'idle') t.func({ didTimeout: false, timeRemaining: () => 0 });
        else t.func(...t.args);
      } catch (err) {
        error = error || err; // as under Playwright's clock: no page error, runFor rejects with the first
      } finally {
        duringTick = false;
      }
      await realTask();
      if (unseen) unseen.endFrame();
    }
    if (unseen) unseen.endRun();
    C.ticks = Math.max(C.ticks, to);
    if (error) throw error;
  };
  return C;
}

/** Date as the page sees it: `now()` for "now", the native Date for everything else. */
function frozenDate(NativeDate, now) {
  function ClockDate(...args) {
    if (!new.target) return new NativeDate(now()).toString();
    return args.length ? new NativeDate(...args) : new NativeDate(now());
  }
  ClockDate.prototype = NativeDate.prototype;
  ClockDate.now = now;
  ClockDate.parse = NativeDate.parse;
  ClockDate.UTC = NativeDate.UTC;
  ClockDate.toString = () => NativeDate.toString();
  return ClockDate;
}

/** The init script (a string) with the page's time frozen at `start` (FROZEN). */
export const clockScript = (start) => `(${frameClock})(${JSON.stringify(start)}, ${timersOf}, ${frozenDate});`;
