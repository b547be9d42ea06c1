// The grader's paths under Windows' rules (path.win32: C:\..., backslashes) and POSIX's on any
// machine: the part finder (grader/files/parts.js on a made-up file system), the out folder's
// layout (grader/files/layout.js) and the submission server's mapping between URLs and files
// (grader/node/run/serve-submission.js), with folder names with spaces and æøå. A part finder that
// splits a path on '/' finds the wrong part under Windows' rules here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { findParts } from '../../grader/files/parts.js';
import { partFiles, hrefOf, fileOfHref, safeName } from '../../grader/files/layout.js';
import { fileOf, urlOf } from '../../grader/node/run/serve-submission.js';

const SYSTEMS = [
  { name: 'Windows', p: path.win32, root: 'C:\\Users\\Åse Ødegård\\Downloads\\02561 hand-ins\\Søren Æbelø', out: 'C:\\Users\\Åse Ødegård\\grading out' },
  { name: 'POSIX', p: path.posix, root: '/home/åse/02561 hand-ins/Søren Æbelø', out: '/home/åse/grading out' },
];

/** A made-up file system of `files` (paths relative to `root`, as names), in path `p`'s syntax. */
function fileSystem(p, root, files) {
  const all = files.map((names) => p.join(root, ...names));
  const dirs = new Set(files.flatMap((names) => names.slice(0, -1).map((_, k) => p.join(root, ...names.slice(0, k + 1)))));
  dirs.add(p.join(root));
  return {
    readdir: (dir) => {
      if (!dirs.has(p.join(dir))) throw Object.assign(new Error(`ENOENT: ${dir}`), { code: 'ENOENT' });
      return [...new Set([...all, ...dirs].filter((f) => p.dirname(f) === p.join(dir) && f !== p.join(dir)).map((f) => p.basename(f)))];
    },
    isDirectory: (file) => (dirs.has(p.join(file)) ? true : all.includes(p.join(file)) ? false : null),
  };
}

// a submission as students lay them out: folders with spaces and Danish letters, and one folder
// whose name says another part than the folder inside it (a '/'-split under Windows reads it whole)
const HANDIN = [
  ['Uge 4 – Øvelse', 'Del 1 (kugle)', 'index.html'],
  ['Uge 4 – Øvelse', 'Del 1 (kugle)', 'main.js'],
  ['WP04P2 gammel', 'Part3', 'index.html'],
  ['Lys og skygge', 'del_4', 'Phong – æøå.html'],
  ['Lys og skygge', 'w04p05.html'],
];

for (const { name, p, root } of SYSTEMS) {
  test(`${name}: the part finder walks folders with spaces and æøå, and writes each part's path in ${name}'s syntax`, () => {
    const parts = findParts(root, {}, { fs: fileSystem(p, root, HANDIN), pathImpl: p });
    assert.deepEqual(parts, {
      WP04P1: p.join('Uge 4 – Øvelse', 'Del 1 (kugle)', 'index.html'),
      WP04P2: null,
      WP04P3: p.join('WP04P2 gammel', 'Part3', 'index.html'),
      WP04P4: p.join('Lys og skygge', 'del_4', 'Phong – æøå.html'),
      WP04P5: p.join('Lys og skygge', 'w04p05.html'),
    });
    if (p === path.win32) assert.equal(parts.WP04P3, 'WP04P2 gammel\\Part3\\index.html');
    // a drive's root as the submission
    const drive = p === path.win32 ? 'D:\\' : '/';
    assert.equal(findParts(drive, {}, { fs: fileSystem(p, drive, [['Part 2', 'index.html']]), pathImpl: p }).WP04P2, p.join('Part 2', 'index.html'));
  });

  test(`${name}: the out folder's layout: a part's result and artifact under its safe name, and report.html's links to them`, () => {
    const { out } = SYSTEMS.find((s) => s.p === p);
    const files = partFiles(out, 'Søren Æbelø', 'WP04P3', p);
    assert.deepEqual(files, {
      resultFile: p.join(out, 'parts', 'Søren_Æbelø', 'WP04P3.json'),
      artifactDir: p.join(out, 'artifacts', 'Søren_Æbelø', 'WP04P3'),
    });
    if (p === path.win32) assert.equal(files.resultFile, 'C:\\Users\\Åse Ødegård\\grading out\\parts\\Søren_Æbelø\\WP04P3.json');
    assert.equal(hrefOf(out, p.join(files.artifactDir, 'judged.png'), p), 'artifacts/S%C3%B8ren_%C3%86bel%C3%B8/WP04P3/judged.png');
    assert.equal(new URL(hrefOf(out, p.join(files.artifactDir, 'judged.png'), p), 'http://x/report/').pathname, '/report/artifacts/S%C3%B8ren_%C3%86bel%C3%B8/WP04P3/judged.png');
    assert.throws(() => hrefOf(out, p.join(out, '..', 'elsewhere.png'), p), /is not under/);
    // and back: the feedback page reads the picture a report's link names (æ, ø, not %C3%A6)
    assert.equal(fileOfHref(out, hrefOf(out, p.join(files.artifactDir, 'judged.png'), p), p), p.join(files.artifactDir, 'judged.png'));
    assert.equal(fileOfHref(out, '../elsewhere.png', p), null);
  });

  test(`${name}: the submission server maps its URLs to files under the root and back, and nothing outside`, () => {
    const origin = 'http://p1.submission.localhost';
    for (const names of HANDIN) {
      const rel = p.join(...names);
      const url = urlOf(origin, root, rel, 'api=webgl&level=3', p);
      assert.equal(url.origin, origin);
      assert.equal(url.search, '?api=webgl&level=3');
      assert.equal(fileOf(root, url.href, p), p.join(root, rel), url.href);
      assert.ok(!url.pathname.includes('\\'), url.pathname);
    }
    assert.equal(urlOf(origin, root, p.join('Uge 4 – Øvelse', 'Del 1 (kugle)', 'index.html'), '', p).pathname,
      '/Uge%204%20%E2%80%93%20%C3%98velse/Del%201%20(kugle)/index.html');
    // a page's own requests, as the browser sends them
    assert.equal(fileOf(root, `${origin}/Uge%204%20%E2%80%93%20%C3%98velse/common/MV.js`, p), p.join(root, 'Uge 4 – Øvelse', 'common', 'MV.js'));
    assert.equal(fileOf(root, `${origin}/`, p), p.join(root, p.sep));
    assert.equal(fileOf(root, `${origin}/a%20b%23c%3Fd.js?x=1#y`, p), p.join(root, 'a b#c?d.js'));
    // outside the submission, or no file name: null (the server answers 403)
    assert.equal(fileOf(root, `${origin}/..%2F..%2Fsecret.txt`, p), null);
    assert.equal(fileOf(root, `${origin}/%2e%2e/%2e%2e/secret.txt`, p), p.join(root, 'secret.txt')); // (the URL parser takes the dots away)
    if (p === path.win32) {
      assert.equal(fileOf(root, `${origin}/..%5C..%5Csecret.txt`, p), null);
      assert.equal(fileOf(root, `${origin}/C:%5CWindows%5Cwin.ini`, p), null);
    }
  });
}

test('safe names: letters (æøå too) and digits kept; never hidden, "..", a trailing dot or a Windows device name', () => {
  assert.deepEqual(['Søren Æbelø', 'anna', 'a/b\\c:d*e?f"g<h>i|j', '..', '.hidden', 'name.', 'CON', 'con.txt', 'Lpt1', 'console', '', '  '].map(safeName),
    ['Søren_Æbelø', 'anna', 'a_b_c_d_e_f_g_h_i_j', '__', '_hidden', 'name', '_CON', '_con.txt', '_Lpt1', 'console', '_', '_']);
  // (the same name, composed or not, is one folder)
  assert.equal(safeName('A\u030Ase'), safeName('Åse'));
});
