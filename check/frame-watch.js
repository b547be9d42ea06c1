// What the check page hears from a part's frame, as the grader hears it from Playwright: page
// errors, console errors, dialogs (alert, confirm, prompt: dismissed, their text kept), popups
// (blocked), and loops that never return. An init script (a function, put at the top of the
// part's HTML as source text, before the clock and the grader's instrumentation).
//
// A script that never returns would freeze the check page too (a same-origin frame shares its
// thread), so every loop in the part's scripts calls __checkLoop() (check/guard.js puts the call
// in): a loop still running `loopSeconds` after its task began (the frame last had a free moment,
// or the check page started a task there: newTask) throws, the frame is marked hung, and every
// later loop throws at once.

//
// What the self-check itself broke is kept apart (watch.broken), for the check page gives no
// verdict on such a page: a script of the page ran before this one (check/guard.js's stand-in
// guard was there first), or an error names one of the frame script's globals.

/** The init script. options: { loopSeconds }. Publishes window.__checkWatch. */
export function frameWatchScript(options) {
  if (window.__checkWatch) return;
  const watch = { errors: [], blocked: [], hung: null, broken: [] };
  Object.defineProperty(window, '__checkWatch', { value: watch, enumerable: false });
  const json = (x) => { try { return JSON.stringify(x); } catch { return String(x); } };
  const text = (x) => (x instanceof Error ? x.message : typeof x === 'string' ? x : json(x));
  if (typeof window.__checkLoop === 'function') watch.broken.push('a script of the page ran before the self-check\'s own script');
  // the frame script's globals (here, grader/browser/clock.js, instrument.js, webgpu-capture.js, stay.js)
  const OURS = /\b__(check\w*|grade\w*|webgpuCapture|stay)\b/;
  const pageError = (message) => {
    watch.errors.push(`page error: ${message}`);
    if (OURS.test(message)) watch.broken.push(message);
  };

  window.addEventListener('error', (e) => {
    if (e.error !== undefined || e.message) pageError(e.error ? text(e.error) : e.message);
  });
  window.addEventListener('unhandledrejection', (e) => pageError(text(e.reason)));
  const consoleError = console.error.bind(console);
  console.error = (...args) => {
    watch.errors.push(`console: ${args.map(text).join(' ')}`);
    consoleError(...args);
  };
  const dialog = (answer) => (message) => {
    watch.errors.push(`dialog: ${message === undefined ? '' : String(message)}`);
    return answer;
  };
  window.alert = dialog(undefined);
  window.confirm = dialog(false);
  window.prompt = dialog(null);
  window.open = (url) => {
    watch.blocked.push(`popup: ${url === undefined ? '' : new URL(String(url), location.href).href}`);
    return null;
  };
  // the grader's pages have devicePixelRatio 1: a canvas sized from clientWidth × devicePixelRatio
  // is as big here as there, on any screen
  Object.defineProperty(window, 'devicePixelRatio', { get: () => 1, configurable: true });
  // ... and no scrollbars (headless Chromium hides them): a canvas sized from clientWidth is as wide
  document.documentElement.style.scrollbarWidth = 'none';

  // (a script put into the frame as text imports nothing: its milliseconds a second are its own;
  // the beat's period; a loop looks at the clock once in LOOK_EVERY_MASK + 1 calls, a power of 2)
  const MS_A_SECOND = 1000, BEAT_MS = 100, LOOK_EVERY_MASK = 1023;
  // the loop guard: a beat on the real clock (taken before grader/browser/clock.js stands in for it)
  const realSetTimeout = setTimeout.bind(window), realNow = performance.now.bind(performance);
  let beat = 0, seen = -1, taskStart = 0, calls = 0;
  const tick = () => { beat++; realSetTimeout(tick, BEAT_MS); };
  tick();
  // a new task begun by the check page (a timer or frame its clock runs, a click, a key, a slider
  // step): a loop there is timed from here, not from before the check page's own work in between
  watch.newTask = () => { beat++; };
  // loading has the rubric's loadSeconds; once loaded, a task may take up to the part's whole bound
  // (a quadratic flatten() at a high level takes tens of seconds on a slow machine, as under the grader)
  let limit = MS_A_SECOND * options.loopSeconds;
  watch.setLoopSeconds = (seconds) => { limit = MS_A_SECOND * seconds; };
  Object.defineProperty(window, '__checkLoop', {
    enumerable: false,
    value: () => {
      if (watch.hung) throw new Error(watch.hung);
      if ((++calls & LOOK_EVERY_MASK) !== 0) return;
      const now = realNow();
      if (beat !== seen) { seen = beat; taskStart = now; return; }
      if (now - taskStart > limit) {
        watch.hung = `a loop ran for ${Math.round((now - taskStart) / MS_A_SECOND)} s without returning (stopped by the self-check)`;
        throw new Error(watch.hung);
      }
    },
  });
}
