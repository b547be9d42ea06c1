// Finding the parts where names carry no part number the usual way: a course site's numbered
// sections, a step's title in a name, a page's own <title> or first heading (grader/core/part-names.js),
// on disk (grader/files/parts.js) and on the check page (check/files.js) alike.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, mkdirSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { partsFound, stepOfTitle, titleOfPage } from '../../grader/core/part-names.js';
import { findPartsWithNotes } from '../../grader/files/parts.js';
import { handInFrom, partsOfHandIn, titlesOfHandIn } from '../../check/files.js';

const join = (s) => s.join('/');
const found = (paths, options) => partsFound(paths.map((p) => p.split('/')), join, options);

// a student's own course site: worksheets as numbered sections, worksheet 4's parts numbered in it
const SITE = [
  'site/index.html',
  'site/2.-Worksheets/index.html',
  'site/2.-Worksheets/2.1.-Worksheet-3/2.1.1.-Triangles/index.html',
  'site/2.-Worksheets/2.1.-Worksheet-3/2.1.2.-Colours/index.html',
  'site/2.-Worksheets/2.1.-Worksheet-3/2.1.3.-Rotation/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/3.2.1.-Sphere/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/3.2.2.-Depth-test-and-culling/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/3.2.3.-Gouraud/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/3.2.4.-Phong-shading/index.html',
  'site/2.-Worksheets/3.2.-Worksheet-4/3.2.5.-Phong-shading-per-fragment/index.html',
];
const W4 = 'site/2.-Worksheets/3.2.-Worksheet-4';

test('a course site\'s numbered sections: the run whose titles name the worksheet\'s steps, each part by its last number', () => {
  const { parts, notes } = found(SITE);
  assert.deepEqual(parts, {
    WP04P1: `${W4}/3.2.1.-Sphere/index.html`, WP04P2: `${W4}/3.2.2.-Depth-test-and-culling/index.html`,
    WP04P3: `${W4}/3.2.3.-Gouraud/index.html`, WP04P4: `${W4}/3.2.4.-Phong-shading/index.html`,
    WP04P5: `${W4}/3.2.5.-Phong-shading-per-fragment/index.html`,
  });
  // the number wins over a title that names another step, and says so
  assert.deepEqual(Object.keys(notes), ['WP04P4']);
  assert.match(notes.WP04P4, /found as WP04P4 by its section's number \(3\.2\.4\.-Phong-shading\), though its title names the step of WP04P5: the number wins/);
  // another worksheet's run (titles naming none of these steps) and the worksheet's own folder are not parts
  const other = found(SITE.filter((p) => !p.includes('Worksheet-4/3.2.')));
  assert.deepEqual(Object.values(other.parts), [null, null, null, null, null]);
  // a section number with 4 in it is read by its last number (3.4.2 is part 2, not worksheet 4's part 2 by luck)
  assert.equal(found(['w/3.4.1.-Sphere/a.html', 'w/3.4.3.-Gouraud/a.html']).parts.WP04P3, 'w/3.4.3.-Gouraud/a.html');
  assert.equal(found(['w/1.-Sphere.html', 'w/2.-Culling.html']).parts.WP04P2, 'w/2.-Culling.html');
});

test('a step\'s title in a name, where no name carries a part number; a part\'s own name still wins', () => {
  assert.equal(stepOfTitle('Phong shading'), 5);
  assert.equal(stepOfTitle('The Phong reflection model'), 4);
  assert.equal(stepOfTitle('Gouraud shading of a sphere'), 3);
  assert.equal(stepOfTitle('Back-face culling'), 2);
  assert.equal(stepOfTitle('A subdivided tetrahedron'), 1);
  assert.equal(stepOfTitle('Worksheet 4'), null);
  const { parts, notes } = found(['w4/sphere/index.html', 'w4/culling/index.html', 'w4/gouraud.html', 'w4/phong-reflection.html', 'w4/phong-shading.html']);
  assert.deepEqual(Object.values(parts), ['w4/sphere/index.html', 'w4/culling/index.html', 'w4/gouraud.html', 'w4/phong-reflection.html', 'w4/phong-shading.html']);
  assert.deepEqual(notes, {});
  assert.equal(found(['gouraud/index.html', 'part3/index.html']).parts.WP04P3, 'part3/index.html');
});

test('a page\'s own <title> or first heading names its part where its names do not, with a note', () => {
  assert.equal(titleOfPage('<html><head><title>Worksheet 4</title></head><body><h1>Part 3: <b>Gouraud</b> &amp; more</h1>'), 'Worksheet 4 · Part 3: Gouraud more');
  assert.equal(titleOfPage('<canvas></canvas>'), null);
  const titles = { 'a/index.html': 'WebGL · Hidden surface removal', 'b/index.html': 'Worksheet 4, Part 5', 'c/index.html': 'Worksheet 4' };
  const { parts, notes } = found(['a/index.html', 'b/index.html', 'c/index.html'], { titles });
  assert.deepEqual(parts, { WP04P1: null, WP04P2: 'a/index.html', WP04P3: null, WP04P4: null, WP04P5: 'b/index.html' });
  assert.match(notes.WP04P2, /found as WP04P2 by the page's title \("WebGL · Hidden surface removal"\)/);
  // a name that says the part wins over a title
  assert.equal(found(['x/index.html', 'part2/index.html'], { titles: { 'x/index.html': 'Culling' } }).parts.WP04P2, 'part2/index.html');
});

test('the grader on disk and the check page find the same parts and notes, titles read from the pages', async () => {
  const root = mkdtempSync(path.join(tmpdir(), 'part-names-'));
  try {
    const pages = {
      ...Object.fromEntries(SITE.map((p) => [p, '<html><head><title>Course site</title></head><body><canvas></canvas></body></html>'])),
      'other/index.html': '<title>Per-fragment lighting</title>',
      'unnamed/a.html': '<body><h2>Gouraud shading</h2></body>',
    };
    for (const [rel, html] of Object.entries(pages)) {
      mkdirSync(path.join(root, path.dirname(rel)), { recursive: true });
      writeFileSync(path.join(root, rel), html);
    }
    const disk = findPartsWithNotes(root);
    const files = handInFrom(Object.entries(pages).map(([p, html]) => ({ path: p, blob: new Blob([html]) })));
    const dropped = partsOfHandIn(files, await titlesOfHandIn(files));
    const posix = (o) => Object.fromEntries(Object.entries(o).map(([k, v]) => [k, v && v.split(path.sep).join('/')]));
    assert.deepEqual(posix(disk.parts), dropped.parts);
    assert.deepEqual(disk.notes, dropped.notes);
    assert.equal(dropped.parts.WP04P1, `${W4}/3.2.1.-Sphere/index.html`);
    // the worksheet's sections came first; a page named by its title only takes a part nothing else names
    assert.equal(dropped.parts.WP04P3, `${W4}/3.2.3.-Gouraud/index.html`);
    rmSync(path.join(root, 'site'), { recursive: true });
    const titled = findPartsWithNotes(root);
    assert.deepEqual(posix(titled.parts), { WP04P1: null, WP04P2: null, WP04P3: 'unnamed/a.html', WP04P4: null, WP04P5: 'other/index.html' });
    assert.match(titled.notes.WP04P3, /by the page's title \("Gouraud shading"\)/);
  } finally {
    rmSync(root, { recursive: true, force: true });
  }
});
