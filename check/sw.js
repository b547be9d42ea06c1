// The check page's service worker: it controls only the frames under run/<session>/ beside it
// (/check/run/<session>/, or under the path the site is published at) and
// carries their requests to the check page that owns the session, which answers them from the
// dropped files (check/serve.js). It keeps nothing itself (a worker the browser stops and starts
// again loses nothing). Requests to other hosts are blocked and reported; nothing leaves the browser.
/* global clients */
const BASE = new URL('./run/', self.location).pathname;
const owners = new Map(); // session → the check page's client id

/** How long the check page is waited for: a file it serves, a blocked request it hears of; the status where it is gone. */
const ASK_MS = 15000, BLOCKED_ASK_MS = 2000, UNAVAILABLE = 503;

self.addEventListener('install', () => self.skipWaiting());
self.addEventListener('activate', (event) => event.waitUntil(clients.claim()));

/** The session of a request: from its own URL (a frame's page) or from the frame that asked. */
async function sessionOf(event, url) {
  if (url.origin === location.origin && url.pathname.startsWith(BASE)) {
    const s = url.pathname.slice(BASE.length).split('/')[0];
    if (s) return s;
  }
  const client = event.clientId && (await clients.get(event.clientId));
  if (!client) return null;
  const path = new URL(client.url).pathname;
  return path.startsWith(BASE) ? path.slice(BASE.length).split('/')[0] : null;
}

/** Sends `message` to the check page that owns `session` (asking every check page the first time). */
async function ask(session, message, timeout = ASK_MS) {
  const known = owners.get(session) && (await clients.get(owners.get(session)));
  const pages = known ? [known] : (await clients.matchAll({ type: 'window', includeUncontrolled: true }))
    .filter((c) => !new URL(c.url).pathname.startsWith(BASE));
  return new Promise((resolve) => {
    const timer = setTimeout(() => resolve(null), timeout);
    for (const page of pages) {
      const channel = new MessageChannel();
      channel.port1.onmessage = (e) => {
        if (!e.data) return; // not this page's session
        clearTimeout(timer);
        owners.set(session, page.id);
        resolve(e.data);
      };
      page.postMessage({ ...message, session }, [channel.port2]);
    }
  });
}

async function respond(event) {
  const url = new URL(event.request.url);
  const session = await sessionOf(event, url);
  if (!session) return Response.error();
  if (url.origin !== location.origin) {
    const blocked = { type: 'check-blocked', url: url.href, navigation: event.request.mode === 'navigate' };
    if (!/^(data|blob):/.test(url.protocol)) ask(session, blocked, BLOCKED_ASK_MS);
    return Response.error();
  }
  // a module script (and what a module imports) is fetched in cors mode, a classic script in no-cors
  const module = event.request.destination === 'script' && event.request.mode === 'cors';
  const a = await ask(session, { type: 'check-file', path: url.pathname, module });
  if (!a) return new Response('the check page that opened this part is gone', { status: UNAVAILABLE, headers: { 'Content-Type': 'text/plain' } });
  return new Response(a.body, { status: a.status, headers: { 'Content-Type': a.type, 'Cache-Control': 'no-store' } });
}

self.addEventListener('fetch', (event) => {
  const url = new URL(event.request.url);
  if (/^(data|blob):/.test(url.protocol)) return;
  event.respondWith(respond(event));
});
