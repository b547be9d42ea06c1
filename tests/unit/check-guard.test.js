// The self-check's hold on a part's scripts (check/guard.js, check/serve.js, check/not-checked.js):
// the frame script goes before every script of a page however the page begins, guarded code
// never needs it to have run (the stand-in guard), modules and what they import are guarded as
// modules, and a part gets no verdict where the browser or the self-check is to blame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import vm from 'node:vm';
import { standIn, guardLoops as guard } from '../../check/guard.js';

// (the rubric's default loadSeconds: a loop that runs so long without returning is stopped)
const SECONDS = 20;
const STAND_IN = standIn(SECONDS);
const guardLoops = (source, o = {}) => guard(source, { ...o, seconds: SECONDS });
import { answer, handInSource, injectFrameScript } from '../../check/serve.js';
import { NOT_CHECKED, notCheckedHere, usesWebGPU } from '../../check/not-checked.js';

const TAG = '<script src="/f.js"></script>';

test('the frame script goes before the page\'s first script, whatever comes first', () => {
  // no <head>, no <html>: the doctype, then the scripts
  assert.equal(injectFrameScript('<!DOCTYPE html>\n<script src="a.js"></script><canvas>', '/f.js'), `<!DOCTYPE html>${TAG}\n<script src="a.js"></script><canvas>`);
  // scripts before <head> (and <html>): after the doctype, not after the <head> below them
  assert.equal(injectFrameScript('<!doctype html><script src="a.js"></script><html><head><title>t</title>', '/f.js'),
    `<!doctype html>${TAG}<script src="a.js"></script><html><head><title>t</title>`);
  // <html> before the scripts, <head> after them
  assert.equal(injectFrameScript('<html><script>x()</script><head>', '/f.js'), `<html>${TAG}<script>x()</script><head>`);
  // neither: at the very start
  assert.equal(injectFrameScript('<script>x()</script><head>', '/f.js'), `${TAG}<script>x()</script><head>`);
  // a <head> in a comment or in a script's text is no <head>
  assert.equal(injectFrameScript('<!doctype html><!-- <head> --><script>s = "<head>"</script>', '/f.js'), `<!doctype html>${TAG}<!-- <head> --><script>s = "<head>"</script>`);
  assert.equal(injectFrameScript('<!doctype html><html lang="en"><head><meta charset="utf-8">', '/f.js'), `<!doctype html><html lang="en"><head>${TAG}<meta charset="utf-8">`);
});

test('guarded code runs without the frame script: the stand-in defines the guard and stops a loop', () => {
  let now = 0;
  const context = vm.createContext({ performance: { now: () => (now += 1000) }, setTimeout: () => {} });
  // no __checkLoop in this global: without the stand-in, a ReferenceError
  vm.runInContext(guardLoops('var k = 0; while (k < 5000) k++;'), context);
  assert.equal(context.k, 5000);
  assert.throws(() => vm.runInContext(guardLoops('for (;;) {}'), context), /a loop ran for \d+ s without returning \(stopped by the self-check\)/);
  // the frame script's guard, where it is, is left alone
  const calls = [];
  const framed = vm.createContext({ __checkLoop: () => calls.push(1) });
  vm.runInContext(guardLoops('for (var i = 0; i < 3; i++) {}'), framed);
  assert.equal(calls.length, 3);
});

test('the stand-in goes after the directives, so "use strict" still counts', () => {
  const out = guardLoops('"use strict";\nfor (;;) { break; }');
  assert.equal(out, `"use strict";\n${STAND_IN}for (;;) {__checkLoop(); break; }`);
  assert.throws(() => vm.runInContext(guardLoops('"use strict"; for (;;) { undeclared = 1; break; }'), vm.createContext({ __checkLoop() {} })), /undeclared is not defined/);
});

test('every script served is guarded: classic, a module, and a .js a module imports', async () => {
  const files = new Map([
    ['P1/index.html', new Blob(['<!doctype html><script type="module">for (;;) {}</script><script>while (1);</script>'])],
    ['P1/loop.js', new Blob(['export let n = 0; for (;;) n++;'])],
    ['P1/loop.mjs', new Blob(['while (true) {}'])],
    ['P1/classic.js', new Blob(['do {} while (true);'])],
    ['P1/gpu.js', new Blob(['const adapter = await navigator.gpu?.requestAdapter();'])],
  ]);
  const source = handInSource(files);
  const how = { frameScript: '/* frame */', session: 's1', loopSeconds: SECONDS };
  const html = await answer(source, 'P1/', how);
  assert.equal((html.body.match(/__checkLoop\(\);/g) || []).length, 2);
  assert.match(html.body, /^<!doctype html><script src="\/check\/run\/s1\/__check_frame__\.js"><\/script>/);
  for (const [file, module] of [['P1/loop.js', true], ['P1/loop.mjs', false], ['P1/classic.js', false]]) {
    const a = await answer(source, file, { ...how, module });
    assert.match(a.body, /__checkLoop\(\);/, file);
    assert.equal(a.type, 'text/javascript');
  }
  assert.equal((await answer(source, 'P1/gpu.js', { ...how, module: true })).webgpu, true);
  assert.equal((await answer(source, 'P1/classic.js', how)).webgpu, false);
});

test('no verdict where WebGPU is missing here, or the self-check broke the page; the part\'s own errors stay its own', () => {
  assert.equal(NOT_CHECKED, 'not checked');
  for (const src of ['const a = await navigator.gpu.requestAdapter();', "c.getContext('webgpu')", 'if (!navigator . gpu) say()']) assert.ok(usesWebGPU(src), src);
  assert.ok(!usesWebGPU('const gl = canvas.getContext("webgl2"); // no gpu here'));
  const webgpu = notCheckedHere({ webgpuHere: false, usedWebGPU: true, api: null });
  assert.equal(webgpu.why, 'webgpu');
  assert.match(webgpu.reason, /^not checked here: this part uses WebGPU, which this browser does not have .* Chromium or Google Chrome/);
  // a page that falls back to WebGL itself is checked; a browser with WebGPU checks it
  assert.equal(notCheckedHere({ webgpuHere: false, usedWebGPU: true, api: 'webgl2' }), null);
  assert.equal(notCheckedHere({ webgpuHere: true, usedWebGPU: true, api: null }), null);
  const broken = notCheckedHere({ webgpuHere: true, usedWebGPU: false, api: 'webgl', broken: ["Identifier '__checkWatch' has already been declared"] });
  assert.equal(broken.why, 'instrumentation');
  assert.match(broken.reason, /the self-check's own instrumentation broke this page \(Identifier '__checkWatch'/);
  assert.equal(notCheckedHere({ webgpuHere: true, usedWebGPU: false, api: 'webgl', broken: [] }), null);
});
