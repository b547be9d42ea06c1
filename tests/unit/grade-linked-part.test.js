// A part's page that is only a link to another part's page is graded once, as
// the part it links to; the linking part says so. Read from the page's HTML, with POSIX and Windows
// paths, and with the class page's own '/'-paths (POSIX_PATHS).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { linkedPart as linkedWith, POSIX_PATHS } from '../../grader/class/linked-part.js';

const parts = { WP04P1: null, WP04P2: null, WP04P3: null, WP04P4: 'uge4/del4/index.html', WP04P5: 'uge4/del5/index.html' };
const page = (body) => `<!DOCTYPE html><html><head><title>Del 5</title></head><body>${body}</body></html>`;

for (const [name, pathImpl] of [['node:path', path.posix], ['the class page\'s', POSIX_PATHS]]) {
  const linkedPart = (html, rel, ps) => linkedWith(html, rel, ps, { pathImpl });
  test(`a page with no canvas and no script that links to another part's page links to that part (${name})`, () => {
    assert.deepEqual(linkedPart(page('<p>See <a href="../del4/index.html">part 4</a></p>'), parts.WP04P5, parts), { part: 'WP04P4', page: parts.WP04P4 });
    assert.deepEqual(linkedPart(page("<a class=x href='../del4/index.html#top'>4</a>"), parts.WP04P5, parts), { part: 'WP04P4', page: parts.WP04P4 });
    assert.deepEqual(linkedPart('<meta http-equiv="refresh" content="0; url=../del4/index.html">', parts.WP04P5, parts), { part: 'WP04P4', page: parts.WP04P4 });
    assert.deepEqual(linkedPart(page('<a href="../del4/">4</a> <a href="../del4/index.html">4</a>'), parts.WP04P5, parts), { part: 'WP04P4', page: parts.WP04P4 });
  });

  test(`a page that draws, links elsewhere or to itself is not a link to another part (${name})`, () => {
    assert.equal(linkedPart(page('<canvas></canvas><a href="../del4/index.html">previous part</a>'), parts.WP04P5, parts), null);
    assert.equal(linkedPart(page('<script src="main.js"></script><a href="../del4/index.html">4</a>'), parts.WP04P5, parts), null);
    assert.equal(linkedPart(page('<a href="https://example.org/del4/index.html">4</a> <a href="mailto:x@y">me</a>'), parts.WP04P5, parts), null);
    assert.equal(linkedPart(page('<a href="index.html">this page</a> <a href="../del3/index.html">3</a>'), parts.WP04P5, parts), null);
    assert.equal(linkedPart(page('<a href="%E0%A4%A">broken</a>'), parts.WP04P5, parts), null);
  });
}

test('Windows paths: the link is resolved with path.win32', () => {
  const win = { WP04P4: 'uge4\\del4\\index.html', WP04P5: 'uge4\\del5\\index.html' };
  assert.deepEqual(linkedWith(page('<a href="../del4/index.html">4</a>'), win.WP04P5, win, { pathImpl: path.win32 }), { part: 'WP04P4', page: win.WP04P4 });
});
