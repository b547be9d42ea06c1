// The development server (tools/serve.js), tested as it runs: loopback only, nothing outside the site.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import os from 'node:os';
import { startServer } from '../../tools/browser.js';

let server;
before(async () => { server = await startServer(); });
after(() => server.stop());

// A raw request: the path goes on the wire as written (fetch would resolve the dots first).
function get(path, host = '127.0.0.1') {
  const { port } = new URL(server.url);
  return new Promise((resolve, reject) => {
    const req = http.request({ host, port, path, method: 'GET' }, (res) => {
      let body = '';
      res.on('data', (c) => { body += c; });
      res.on('end', () => resolve({ status: res.statusCode, body, headers: res.headers }));
    });
    req.on('error', reject);
    req.end();
  });
}

test('serves the site', async () => {
  const page = await get('/');
  assert.equal(page.status, 200);
  assert.match(page.body, /Lighting and shading in WebGL/);
  assert.equal((await get('/WP04P1/shader.vert')).status, 200);
});

test('a path outside the site is refused, however it is spelled', async () => {
  for (const path of ['/../package.json', '/../../etc/passwd', '/%2e%2e/%2e%2e/etc/passwd', '/..%2f..%2fetc%2fpasswd',
    '/WP04P1/../../../etc/passwd', '/%2e%2e%5c%2e%2e%5cetc%5cpasswd', '/....//....//etc/passwd', '//etc/passwd']) {
    const res = await get(path);
    assert.notEqual(res.status, 200, `${path} answered 200`);
    assert.doesNotMatch(res.body, /root:/, path);
  }
  // dot-files (.git, .ci) are not served either
  assert.equal((await get('/.git/config')).status, 404);
});

test('it listens on the loopback address only', async () => {
  const { port } = new URL(server.url);
  // 127.0.0.2 is this machine too, but a server bound to 127.0.0.1 alone does not answer there
  // (one bound to every address, 0.0.0.0, would): so the test means something on a machine whose
  // only interface is the loopback one
  const external = Object.values(os.networkInterfaces()).flat()
    .filter((a) => a && a.family === 'IPv4' && !a.internal).map((a) => a.address);
  for (const address of ['127.0.0.2', ...external]) {
    await assert.rejects(get('/', address).then(() => { throw new Error(`answered on ${address}:${port}`); }).catch((e) => {
      if (/answered/.test(e.message)) throw e;
      throw new Error('refused'); // ECONNREFUSED: nothing listens there
    }), /refused/);
  }
});

test('the bench pages, and only they, are cross-origin isolated (fine timers)', async () => {
  for (const path of ['/lab/bench.html?size=128', '/lab/bench-gpu.html', '/lab/bench-page.js']) {
    const { headers } = await get(path);
    assert.equal(headers['cross-origin-opener-policy'], 'same-origin', path);
    assert.equal(headers['cross-origin-embedder-policy'], 'require-corp', path);
  }
  for (const path of ['/', '/lab/', '/WP04P5/']) assert.equal((await get(path)).headers['cross-origin-embedder-policy'], undefined, path);
});
