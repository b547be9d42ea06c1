// The self-check's reading of a dropped hand-in (check/files.js, check/serve.js): the root, what is
// left out, what is refused, the parts found as the grader finds them, and paths asked from a frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CheckInputError, MAX_BYTES, handInFrom, partsOfHandIn } from '../../check/files.js';
import { askedPath, injectFrameScript } from '../../check/serve.js';
import { STAND_IN, guardLoops, guardInlineScripts } from '../../check/guard.js';

const blob = (size = 10) => ({ size });
const entries = (paths, size) => paths.map((p) => ({ path: p, blob: blob(size) }));

test('a picked folder is the root; dot-files, node_modules and __MACOSX are left out', () => {
  const files = handInFrom(entries(['ada/Part1/index.html', 'ada/.git/config', 'ada/node_modules/x.js', 'ada/__MACOSX/Part1/._index.html', 'ada/common/MV.js']));
  assert.deepEqual([...files.keys()], ['Part1/index.html', 'common/MV.js']);
  // several things dropped at once: no common top folder to take off
  assert.deepEqual([...handInFrom(entries(['Part1/index.html', 'notes.txt'])).keys()], ['Part1/index.html', 'notes.txt']);
});

test('more than a worksheet is refused with what to do', () => {
  assert.throws(() => handInFrom(entries(['big/a.mp4', 'big/b.mp4', 'big/Part1/index.html'], MAX_BYTES / 2)),
    (err) => err instanceof CheckInputError && /3 files, 150 MB: more than a worksheet .* Drop the worksheet's own folder/.test(err.message));
});

test('parts are found as the grader finds them; no page or no part name is said', () => {
  const files = handInFrom(entries(['s/Lab 4/w04/w04p03.html', 's/week04/part02/index.html']));
  const { parts } = partsOfHandIn(files);
  assert.equal(parts.WP04P3, 'Lab 4/w04/w04p03.html');
  assert.equal(parts.WP04P2, 'week04/part02/index.html');
  assert.equal(parts.WP04P1, null);
  assert.throws(() => partsOfHandIn(handInFrom(entries(['s/a.txt']))), /No HTML page in what you dropped \(1 files\)/);
  assert.throws(() => partsOfHandIn(handInFrom(entries(['s/hello.html', 's/x.txt']))), /None of the HTML pages is named for a part .*hello\.html/);
});

test('a frame\'s paths: its session\'s folder, and root-absolute or one folder too far up land on the hand-in\'s root', () => {
  assert.equal(askedPath('/check/run/abc/Part1/index.html', 'abc'), 'Part1/index.html');
  assert.equal(askedPath('/check/run/Common/MV.js', 'abc'), 'Common/MV.js'); // ../../Common/MV.js from Part1/
  assert.equal(askedPath('/common/MV.js', 'abc'), 'common/MV.js');
  assert.equal(askedPath('/check/run/abc/My%20Part/', 'abc'), 'My Part/');
  assert.equal(askedPath('/check/run/abc/%E0%A4%A', 'abc'), null);
});

test('the frame script goes first; every loop gets the guard, shaders and other scripts stay', () => {
  assert.equal(injectFrameScript('<!doctype html><html><head><title>t</title>', '/f.js'), '<!doctype html><html><head><script src="/f.js"></script><title>t</title>');
  assert.equal(injectFrameScript('<p>bare', '/f.js'), '<script src="/f.js"></script><p>bare');
  assert.equal(guardLoops('while (true) x++;'), `${STAND_IN}while (true) {__checkLoop();x++;}`);
  assert.equal(guardLoops('for (;;) { f(); }'), `${STAND_IN}for (;;) {__checkLoop(); f(); }`);
  assert.equal(guardLoops('let a = 1; a +'), 'let a = 1; a +'); // does not parse: as it is
  assert.equal(guardLoops('let a = 1;'), 'let a = 1;'); // no loop: as it is
  const html = '<script type="x-shader/x-vertex">for (int i = 0; i < 3; i++) {}</script><script>do { i++ } while (i < 3)</script>';
  assert.equal(guardInlineScripts(html), `<script type="x-shader/x-vertex">for (int i = 0; i < 3; i++) {}</script><script>${STAND_IN}do {__checkLoop(); i++ } while (i < 3)</script>`);
});

test('a review or a fail names the slide sentence it misses', async () => {
  const { missedSlides } = await import('../../check/slides.js');
  const slide = (reason) => missedSlides([reason]).map((m) => m.slide.split(' ').slice(0, 4).join(' '))[0];
  assert.equal(slide('REVIEW: the colours are not 0.5·n + 0.5: 2c − 1 is not a unit vector'), 'Get the normal from');
  assert.equal(slide('REVIEW: the orbit does not show in the shading: the light moves with the camera (light and normals in different spaces?)'), 'Add a tick function');
  assert.equal(slide('REVIEW: 2 slider(s) update the picture only on the change event, not while sliding'), 'Use the input event');
  assert.equal(slide('drew nothing: the canvas is one colour, no draw call'), 'Draw a solid sphere');
  assert.equal(slide('REVIEW: the highlight follows the triangles at a coarse level (RMS 0.043 from the finest): shading is per vertex, not per fragment'), 'We implement it by');
  assert.equal(slide('REVIEW: nothing found that makes the sphere finer: 2 controls tried'), 'Insert buttons for subdividing');
  assert.equal(slide('REVIEW: back faces show through the front (normals do not vary smoothly): depth test or culling missing'), 'Now, enable the depth');
  assert.equal(slide('REVIEW: no specular highlight: nothing brighter than the diffuse fit'), 'Update your reflection model');
  assert.equal(slide('REVIEW: not in perspective view (the slide: "Draw a solid sphere in perspective view"): the inside of the far side, whose normals reach 90°'), 'Draw a solid sphere');
  assert.equal(slide('REVIEW: shows the normal colouring of WP04P1, not the lighting: its colours decode to unit normals 2c − 1'), 'Given other parameters k_d,');
  // a highlight's place names the light and the eye: its sentence is ω_o's, not the orbit's
  assert.equal(slide('REVIEW: the highlight sits at the light, not halfway between the light and the viewer: 3° from the light, 25° from the halfway normal: is w_o the direction from the surface to the eye, in the same space as n and w_i?'), 'ω_o is the direction');
  assert.equal(slide('REVIEW: the highlight is 31° from where the model puts it (at the normal halfway between the light, fitted at 0.1, 0.2, 0.9, and the viewer): is w_o the direction from the surface to the eye?'), 'ω_o is the direction');
  // a hole's reason may name the vertex shader, a link page's 'links to': neither is a shader that does not compile
  assert.equal(slide("REVIEW: a hole shows from some side: looked at 25 positions along the orbit (the mesh could not be read from what the page sent (the vertex shader's position attribute was not found))"), 'Draw a solid sphere');
  assert.equal(slide("REVIEW: the page for WP04P5 (uge4/del5/index.html) has no canvas and no script of its own: it links to WP04P4's page"), 'Draw a solid sphere');
  assert.equal(slide('FAIL: program does not link: ERROR: missing main()'), 'Upload parameters (k_d, L_e,');
  assert.equal(slide('FAIL: WGSL does not compile (line 3): expected ;'), 'Upload parameters (k_d, L_e,');
  // a part not graded here (too slow, too heavy) was not judged: no sentence, whatever it was doing
  assert.deepEqual(missedSlides(["not graded here: too slow on this machine: the rubric's bound of 90 s ran out while sampling the orbit; nothing was judged"]), []);
  assert.deepEqual(missedSlides(['a round closed sphere (radius 80 px)']), []); // what passed names nothing
  // a hostile page's reasons are about the page, not the step ('a teacher looks' is no k_s slider)
  assert.deepEqual(missedSlides(["REVIEW: what the page reads back differs from what the browser shows, at the first frame: 56% of the canvas's opaque pixels in view (another canvas or an element laid over it, or a CSS filter on it?); the browser's picture is shown: a teacher looks"]), []);
  assert.deepEqual(missedSlides(["REVIEW: the page replaced or probed what the grader reads it through: toDataURL (a hand-in must not change the browser's own functions or the grader's, nor draw otherwise under a test driver): what it showed may not be what the grader saw, a teacher looks"]), []);
  assert.equal(slide('REVIEW: raising ks showed no highlight'), 'Upload remaining parameters for');
});
