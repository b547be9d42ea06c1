// The self-check's reading of a dropped hand-in (check/files.js, check/serve.js): the root, what is
// left out, what is refused, the parts found as the grader finds them, and paths asked from a frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CheckInputError, MAX_BYTES, handInFrom, partsOfHandIn } from '../../check/files.js';
import { askedPath, injectFrameScript } from '../../check/serve.js';
import { standIn, guardLoops as guard, guardInlineScripts } from '../../check/guard.js';

// (the rubric's default loadSeconds: a loop that runs so long without returning is stopped)
const SECONDS = 20;
const STAND_IN = standIn(SECONDS);
const guardLoops = (source, o = {}) => guard(source, { ...o, seconds: SECONDS });

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
  assert.equal(guardInlineScripts(html, SECONDS), `<script type="x-shader/x-vertex">for (int i = 0; i < 3; i++) {}</script><script>${STAND_IN}do {__checkLoop(); i++ } while (i < 3)</script>`);
});

test('a review or a fail names the slide sentence its audit checks, found by the audit id', async () => {
  const { missedSlides } = await import('../../check/slides.js');
  const { AUDITS } = await import('../../grader/core/audits/index.js');
  const { SLIDE } = await import('../../grader/core/audits/slides.js');
  const slide = (id, level = 'review') => missedSlides([{ id, level, reason: 'words' }]).map((m) => m.slide.split(' ').slice(0, 4).join(' '))[0];
  const want = {
    'normal-colours': 'Get the normal from', 'per-face': 'Get the normal from', 'orbit-light': 'Add a tick function', 'orbit-toggle': 'Add a tick function',
    'input-event': 'Use the input event', 'per-fragment': 'We implement it by', 'level-controls': 'Insert buttons for subdividing',
    'front-faces': 'Now, enable the depth', 'depth-culling': 'Now, enable the depth', highlight: 'Update your reflection model',
    perspective: 'Draw a solid sphere', 'normals-not-light': 'Given other parameters k_d,', 'all-round': 'Draw a solid sphere',
    // a highlight's place names the light and the eye: its sentence is ω_o's, not the orbit's
    'highlight-place': 'ω_o is the direction', 'linked-page': 'Draw a solid sphere', 'shaders-compile': 'Upload parameters (k_d, L_e,',
    // a sphere that is not round is the sphere's sentence (its words name 'round', which once gave the buttons')
    sphere: 'Draw a solid sphere', growth: 'Recycle the vertex buffer', 'ks-used': 'Upload remaining parameters for', 'point-light': 'L_i = V I',
  };
  for (const [id, words] of Object.entries(want)) assert.equal(slide(id), words, id);
  assert.equal(slide('first-frame', 'fail'), 'Draw a solid sphere');
  assert.match(missedSlides([{ id: 'perspective', level: 'review', reason: '' }])[0].note, /orthographic/);
  // a part not graded here was not judged; what passed names nothing; a hostile page's reasons are about the page, not the step
  assert.deepEqual(missedSlides([{ id: 'too-slow', level: 'not graded here', reason: 'not graded here: too slow' }]), []);
  assert.deepEqual(missedSlides([{ id: 'sphere', level: 'pass', reason: 'a round closed sphere' }]), []);
  assert.deepEqual(missedSlides([{ id: 'shown-channels', level: 'review', reason: 'x' }, { id: 'tamper', level: 'review', reason: 'y' }]), []);
  // one card a sentence, however many reasons miss it
  assert.equal(missedSlides([{ id: 'front-faces', level: 'review', reason: 'a' }, { id: 'depth-culling', level: 'review', reason: 'b' }]).length, 1);
  // a result from before reasons carried ids: levels from FAIL:, REVIEW: and the failed part's first reason; no slide
  const { findingsOfResult } = await import('../../grader/core/part-result.js');
  assert.deepEqual(findingsOfResult({ verdict: 'fail', reasons: ['drew nothing', 'REVIEW: x', 'ok'] }).map((f) => f.level), ['fail', 'review', 'pass']);
  assert.deepEqual(findingsOfResult({ verdict: 'review', reasons: ['REVIEW: x', 'a round closed sphere'] }).map((f) => f.level), ['review', 'pass']);
  assert.deepEqual(missedSlides(findingsOfResult({ verdict: 'fail', reasons: ['drew nothing'] })), []);
  // every audit's sentence is one of the slides' (audits/slides.js), or none
  for (const a of Object.values(AUDITS)) assert.ok(a.slide === null || Object.values(SLIDE).includes(a.slide), a.id);
});
