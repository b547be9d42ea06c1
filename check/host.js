// The check page as the server of its frames: registers check/sw.js (which controls only
// /check/run/) and answers the requests it carries over, each session from its own hand-in
// (check/serve.js). Also lists what a session's pages asked of other hosts (blocked).
import { BASE, answer, askedPath } from './serve.js';

const sessions = new Map(); // id → { source, frameScript, log, pending }

/** The HTTP statuses of a bad path and of a file that could not be served. */
const BAD_REQUEST = 400, SERVER_ERROR = 500;
/** A session's id: ID_BYTES random bytes in hexadecimal. */
const ID_BYTES = 8, HEX = 16;
/** The frames' requests are idle after QUIET_MS without one (IDLE_MAX_MS at most), looked at every POLL_MS: the grader's networkidle. */
const QUIET_MS = 500, IDLE_MAX_MS = 5000, POLL_MS = 50;

/** Why this browser cannot run the self-check, or null. */
export function unsupported() {
  if (!('serviceWorker' in navigator)) {
    return window.isSecureContext ? 'This browser has no service workers, which the self-check needs to show your pages to the grader in the browser. Use a current Chrome, Edge or Firefox.'
      : 'Service workers need a secure page: open the self-check over https:// or from http://localhost (or 127.0.0.1).';
  }
  return null;
}

let ready = null;
/** Registers the service worker and waits until it is active (it controls only BASE). */
export function startHost() {
  ready ??= (async () => {
    navigator.serviceWorker.onmessage = onMessage; // an onmessage handler starts the messages
    const reg = await navigator.serviceWorker.register(new URL('./sw.js', import.meta.url), { scope: BASE });
    const worker = reg.active || reg.waiting || reg.installing;
    if (worker.state !== 'activated') {
      await new Promise((resolve) => {
        const done = () => { if (worker.state === 'activated') resolve(); };
        worker.addEventListener('statechange', done);
        done();
      });
    }
    return reg;
  })();
  return ready;
}

async function onMessage(e) {
  const { type, session } = e.data || {};
  const s = sessions.get(session);
  const port = e.ports[0];
  if (!s) { if (port) port.postMessage(null); return; } // another check page's session
  if (type === 'check-blocked') {
    s.log.blocked.push(`${e.data.navigation ? 'navigation or popup' : 'request'}: ${e.data.url}`);
    if (port) port.postMessage({ ok: true });
    return;
  }
  if (type !== 'check-file' || !port) return;
  s.pending++;
  s.lastRequest = performance.now();
  try {
    const rel = askedPath(e.data.path, session);
    if (rel === null) return port.postMessage({ status: BAD_REQUEST, type: 'text/plain', body: 'bad path' });
    const a = await answer(s.source, rel, { ...s, module: !!e.data.module });
    if (a.note) s.log.notes.push(a.note);
    if (a.webgpu) s.log.webgpu = true;
    if (a.missing) s.log.errors.push(`missing file: ${a.missing}`);
    port.postMessage({ status: a.status, type: a.type, body: a.body });
  } catch (err) {
    port.postMessage({ status: SERVER_ERROR, type: 'text/plain', body: `the self-check could not serve this file: ${err.message}` });
  } finally {
    s.pending--;
    s.lastRequest = performance.now();
  }
}

/**
 * A session serving `source` (serve.js: handInSource) to frames under BASE + id + '/',
 * its scripts' loops stopped after `loopSeconds` (the rubric's loadSeconds).
 * `log.webgpu`: a page or script served since the last clearLog() calls WebGPU.
 * @returns {{ id: string, url: (path: string) => string, log: { errors: string[], blocked: string[], notes: string[], webgpu: boolean }, clearLog: () => void, idle: (ms: number, max: number) => Promise<void>, close: () => void }}
 */
export function openSession(source, frameScript, loopSeconds) {
  const id = Array.from(crypto.getRandomValues(new Uint8Array(ID_BYTES)), (b) => b.toString(HEX).padStart(2, '0')).join('');
  const s = {
    source,
    frameScript,
    loopSeconds,
    session: id,
    log: { errors: [], blocked: [], notes: [], webgpu: false },
    pending: 0,
    lastRequest: performance.now(),
  };
  sessions.set(id, s);
  return {
    id,
    log: s.log,
    url: (path) => `${BASE}${id}/${path.split('/').map(encodeURIComponent).join('/')}`,
    /** Resolves once no request has been open for `quiet` ms (at most `max` ms): the grader's networkidle. */
    idle: async (quiet = QUIET_MS, max = IDLE_MAX_MS) => {
      const until = performance.now() + max;
      while (performance.now() < until && (s.pending || performance.now() - s.lastRequest < quiet)) {
        await new Promise((r) => setTimeout(r, POLL_MS));
      }
    },
    /** Forgets what the last part's frames did (before the next part). */
    clearLog: () => {
      s.log.errors.length = s.log.blocked.length = s.log.notes.length = 0;
      s.log.webgpu = false;
    },
    close: () => sessions.delete(id),
  };
}
