#!/usr/bin/env node
// Serves the site's folder on 127.0.0.1 only (sirv: no directory listing, no path outside the
// folder) and prints the front page's URL. Used by `npm start` and by the browser tests.
import http from 'node:http';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import sirv from 'sirv';
import { UsageError, parseOptions, wholeNumber } from './cli.js';

const root = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const HELP = `usage: node tools/serve.js [--port N] [--root DIR]
Serves DIR (default: the repository) at http://127.0.0.1:N/ (default port 8080, or $PORT).
Binds 127.0.0.1 only. Stop with Ctrl+C.
exit codes: 0 stopped, 1 could not listen, 2 bad usage`;

let port, dir;
try {
  const opt = parseOptions(process.argv.slice(2), { port: { type: 'string' }, root: { type: 'string' } });
  if (opt.help) {
    console.log(HELP);
    process.exit(0);
  }
  port = opt.port !== undefined ? wholeNumber(opt.port, '--port', 1, 65535)
    : wholeNumber(process.env.PORT || '8080', '$PORT', 1, 65535);
  dir = path.resolve(opt.root ?? root);
} catch (err) {
  if (!(err instanceof UsageError)) throw err;
  console.error(`serve: ${err.message}\n\n${HELP}`);
  process.exit(2);
}

const files = sirv(dir, { dev: true, dotfiles: false, extensions: ['html'] });
function notFound(req, res) {
  res.statusCode = 404;
  res.setHeader('Content-Type', 'text/plain; charset=utf-8');
  res.end('404: not part of this site');
}

// sirv keeps requests inside the folder; in its dev mode (files read live, so new bench results
// show at once) it does not hide dot-files, so .git and .ci are refused here, however encoded.
function hidden(url) {
  let path = url.split('?')[0];
  try {
    path = decodeURIComponent(path);
  } catch {
    return true;
  }
  return path.split(/[/\\]+/).some((part) => part.startsWith('.'));
}

// The bench pages are cross-origin isolated, so that performance.now() counts in microseconds,
// not in the 0.1 ms steps a level change at a low level takes (their files are all our own).
const ISOLATED = /^\/lab\/bench[^/]*$/;

const server = http.createServer((req, res) => {
  if (hidden(req.url)) return notFound(req, res);
  if (ISOLATED.test(req.url.split('?')[0])) {
    res.setHeader('Cross-Origin-Opener-Policy', 'same-origin');
    res.setHeader('Cross-Origin-Embedder-Policy', 'require-corp');
  }
  files(req, res, () => notFound(req, res));
});
server.on('error', (err) => {
  console.error(`serve: cannot listen on 127.0.0.1:${port}: ${err.message}` +
    (err.code === 'EADDRINUSE' ? ` (try: PORT=${port + 1} npm start)` : ''));
  process.exit(1);
});
server.listen(port, '127.0.0.1', () => {
  console.log(`Serving ${dir}\nOpen http://127.0.0.1:${port}/ in your browser (Ctrl+C stops).`);
});
