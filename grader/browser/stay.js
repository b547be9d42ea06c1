// A graded page stays open where the grader opened it, as an init script (before the page's own
// scripts, in either browser and in the check page's frame): `window.close()` (`self.close()`,
// `top.close()`, `window.open('', '_self').close()`) does nothing, and once the page has loaded
// (from its load event on, its own onload handlers included), a navigation of its own window that
// would replace its document (a link, `location.href = …`, a form sent, a reload,
// `window.open(url, '_self')`, `history.back()` to another page) is cancelled before it leaves,
// through the browser's Navigation API (its `navigate` event, cancelable for each of them, in
// Chromium and in Firefox ESR 153). Firefox closes a window whose script asks it to when the window
// has one page in its history (every part in Firefox's grading): the page was gone, and the
// grader's next call failed ("Attempted to use detached Frame"). Chromium refuses that close (its
// page opened on about:blank first), but follows a link, and the part's page was gone there too.
//
// What the page tried is kept in window.__stay.read(): { what: 'close' | 'leave' | 'again' (its own
// address: a reload, a form sent to itself) | 'back', to (for 'leave': the address, on the page's own
// origin as a path from its folder), control (the grader's index of the control clicked last,
// data-grade-control, or null) }, each once, in the order first tried. The audit unit 'stays'
// (grader/core/audits/units/stays.js) says them. Same-document navigations (a #fragment,
// history.pushState) go on as the page asks.
export function stayScript() {
  if (window.__stay) return;
  const KEPT = 20; // the different attempts kept (a page that tries in every frame tries the same one)
  const tried = [];
  let control = null; // the control clicked last (its data-grade-control), or null
  let loaded = document.readyState === 'complete';
  const note = (what, to = null) => {
    if (tried.length >= KEPT || tried.some((t) => t.what === what && t.to === to && t.control === control)) return;
    tried.push({ what, to, control });
  };
  // an address on the page's own origin as a path from the page's folder (../part2/index.html: the
  // same wherever the hand-in is served), another's whole
  const shortened = (url) => {
    if (url.origin !== location.origin) return url.href;
    const from = location.pathname.split('/').slice(0, -1), to = url.pathname.split('/');
    let k = 0;
    while (k < from.length && k < to.length - 1 && from[k] === to[k]) k++;
    return ('../'.repeat(from.length - k) + to.slice(k).join('/') || './') + url.search + url.hash;
  };
  // (the browser's own addEventListener, before the grader's instrumentation wraps it)
  window.addEventListener('load', () => { loaded = true; });
  window.addEventListener('click', (e) => {
    const el = e.target && e.target.closest ? e.target.closest('[data-grade-control]') : null;
    control = el ? Number(el.getAttribute('data-grade-control')) : null;
  }, true);

  Object.defineProperty(window, 'close', { value: function close() { note('close'); }, writable: true, configurable: true });

  // a navigation in the page's own document (history.pushState or replaceState) is not leaving
  let sameDocument = false;
  const H = window.History && History.prototype;
  for (const name of H ? ['pushState', 'replaceState'] : []) {
    const own = H[name];
    if (typeof own !== 'function') continue;
    H[name] = function (...args) {
      sameDocument = true;
      try {
        return own.apply(this, args);
      } finally {
        sameDocument = false;
      }
    };
  }
  const nav = window.navigation;
  if (nav && nav.addEventListener) {
    nav.addEventListener('navigate', (e) => {
      if (!loaded || sameDocument || e.hashChange || !e.cancelable) return;
      const traverse = e.navigationType === 'traverse';
      if (traverse && e.destination.sameDocument) return;
      e.preventDefault();
      if (traverse) return note('back');
      // (a reload, or a form sent to the page's own address, opens the page again)
      const url = new URL(e.destination.url);
      const again = e.navigationType === 'reload' || (url.origin === location.origin && url.pathname === location.pathname);
      return again ? note('again') : note('leave', shortened(url));
    });
  }
  // the history's other pages (a part graded before, the empty page between two parts in
  // Chromium's grading; none in Firefox's): history.back(), forward() and go(n) stay within the
  // page's own entries (pushState's), and to any other say 'back'
  if (H && nav && nav.entries) {
    const inPage = (delta) => {
      const here = nav.currentEntry, entries = nav.entries();
      const to = here ? entries[here.index + delta] : null;
      return !!(to && to.sameDocument);
    };
    const { back, forward, go } = H;
    const moves = { back: [back, () => -1], forward: [forward, () => 1], go: [go, (n) => Math.trunc(Number(n) || 0)] };
    for (const [name, [own, deltaOf]] of Object.entries(moves)) {
      if (typeof own !== 'function') continue;
      H[name] = function (...args) {
        const delta = deltaOf(...args);
        // (go(0) reloads: the navigate event above cancels it)
        if (delta !== 0 && loaded && !inPage(delta)) return note('back');
        return own.apply(this, args);
      };
    }
  }
  const rec = { read: () => tried.map((t) => ({ ...t })) };
  Object.defineProperty(window, '__stay', { value: rec, enumerable: false });
}

/** The init script as text. */
export const stayInit = `(${stayScript})();`;
