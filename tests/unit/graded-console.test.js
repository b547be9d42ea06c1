// A graded page's console: what it prints is counted in the page and goes no further (each message
// crossed the browser's protocol: tens of thousands from a page that prints a frame), and its
// errors, which the grader records, go through as they were.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { consoleScript } from '../../grader/browser/console.js';
import { gradedPageScripts } from '../../grader/node/run/graded-page-scripts.js';

/** consoleScript run in a page whose console hears each call: { window, heard }. */
function page() {
  const heard = [];
  const out = {};
  for (const name of ['log', 'info', 'debug', 'warn', 'trace', 'dir', 'table', 'error']) out[name] = (...a) => heard.push([name, ...a]);
  const window = { __grade: {}, console: out };
  globalThis.window = window;
  try {
    consoleScript();
    consoleScript(); // (an init script runs again in each frame's document: once is enough)
  } finally {
    delete globalThis.window;
  }
  return { window, heard };
}

test('what a page prints is counted and goes no further; its errors go through', () => {
  const { window, heard } = page();
  const c = window.console;
  c.log('i', 1);
  c.info('x');
  c.debug('x');
  c.warn('x');
  c.trace();
  c.dir({});
  c.table([]);
  c.error('shader failed');
  assert.deepEqual(heard, [['error', 'shader failed']]);
  assert.equal(window.__grade.printed, 7);
});

test('every graded page, in either browser, gets it', () => {
  for (const webgpu of [true, false]) assert.ok(gradedPageScripts({ webgpu }).includes(consoleScript));
});
