// A student's feedback page: one self-contained HTML file (pictures inlined as data: URLs, styles
// inline, no script, nothing fetched), that names this student and no other. Per part: the
// verdict in words (the teacher's where the teacher set it, and said so), what to fix first and
// plainly, the slide's sentence it misses, the student's own pictures beside our reference, the
// controls the grader found and what it did with them, and how to check again before handing in.
// The pictures come from the caller (`pictureOf(href)`: a data: URL or null; the command reads
// them from the out folder: grader/node/report/feedback-page.js).
import { missedSlides } from '../core/audits/missed-slides.js';
import { findingsOfResult, asks } from '../core/part-result.js';
import { NOT_GRADED } from '../core/verdict.js';
import { esc } from '../files/html.js';

const IN_WORDS = {
  pass: 'Passed: it does what the step asks.',
  review: 'Partly: it draws the sphere but misses a point of the step (below).',
  fail: 'Not passed: it does not work yet (below).',
  [NOT_GRADED]: 'Not graded here: the grader could not run it on this machine (below); it is not counted against you.',
};
// the pictures a part may show, in the order a student reads them (the first two are the student's own)
const PICTURES = [
  ['judged', 'your page, as judged'], ['reference', 'our reference, at your canvas size and light'], ['first', 'your page, first frame'],
  ['coarse', 'your page at a coarse level'], ['highlightPlace', 'your highlight, the light away from the viewer'], ['leastS', 'your page with s at its least'],
  ['unclipped', 'your page, its own sliders lowered'], ['brightened', 'your page, its own light raised'],
  ['allRoundGap', 'your page from another side along the orbit: a hole'],
  ['shownFirst', 'your page as the browser shows it, first frame'], ['shownLast', 'your page as the browser shows it, at the end'],
];

/** A reason as a student reads it: no FAIL:/REVIEW: prefix, the first letter up. */
const plain = (r) => {
  const t = r.replace(/^(FAIL|REVIEW): /, '');
  return t.charAt(0).toUpperCase() + t.slice(1);
};

function partHtml(r, pictureOf, rubric) {
  const cfg = rubric.parts[r.part] || {};
  const site = (rubric.feedback && rubric.feedback.courseSite || '').replace(/\/?$/, '/');
  // what to fix: the fails and reviews, and why a part was not graded here (by their levels, not their words)
  const findings = findingsOfResult(r);
  const problems = findings.filter(asks).map((f) => f.reason);
  const works = findings.filter((f) => !asks(f)).map((f) => f.reason);
  const slides = missedSlides(findings);
  const href = (k) => r.images && r.images[k];
  const pictures = PICTURES.map(([k, caption]) => [href(k) ? pictureOf(href(k)) : null, caption])
    .filter(([src]) => src);
  const controls = Object.entries(r.controls || {});
  const list = (items) => `<ul>${items.map((x) => `<li>${x}</li>`).join('')}</ul>`;
  const step = site !== '/' ? `<a href="${esc(`${site}${r.part}/`)}">our ${esc(r.part)}</a>` : `our ${esc(r.part)} on the course site`;
  return `<section class="part ${esc(r.verdict === NOT_GRADED ? 'not-graded' : r.verdict)}" id="${esc(r.part)}" data-part="${esc(r.part)}" data-verdict="${esc(r.verdict)}">
<h2>${esc(r.part)}${cfg.title ? `: ${esc(cfg.title)}` : ''}</h2>
<p class="verdict"><strong>${esc(r.verdict)}</strong> · ${esc(IN_WORDS[r.verdict] || r.verdict)}</p>
${r.teacher ? `<p class="teacher">Your teacher set this verdict (the grader said ${esc(r.grader.verdict)}).${r.teacher.note ? ` ${esc(r.teacher.note)}` : ''}</p>` : ''}
${problems.length ? `<h3>${r.teacher && r.verdict === 'pass' ? 'What the grader noted (your teacher passed this part)' : 'What to fix'}</h3>${list(problems.map((x) => esc(plain(x))))}` : ''}
${slides.length ? `<h3>What the slides ask</h3>${list(slides.map((x) => `“${esc(x.slide)}”${x.note ? ` (${esc(x.note)})` : ''}`))}<p>${step} does it.</p>` : ''}
${pictures.length ? `<div class="pictures">${pictures.map(([src, caption]) => `<figure><img src="${src}" alt="${esc(`${r.part}: ${caption}`)}"><figcaption>${esc(caption)}</figcaption></figure>`).join('')}</div>` : ''}
${works.length ? `<h3>What works</h3>${list(works.map((x) => esc(plain(x))))}` : ''}
${controls.length ? `<h3>The controls the grader found</h3>${list(controls.map(([k, v]) => `${esc(k)}: ${esc(v)}`))}` : ''}
${r.actions && r.actions.length ? `<details><summary>What the grader did on your page</summary>${list(r.actions.map(esc))}</details>` : ''}
${r.errors && r.errors.length ? `<h3>Errors your page printed</h3>${list(r.errors.map(esc))}` : ''}
</section>`;
}

/**
 * The feedback page of student `s` ({ name, identity, parts }), each picture (its href in the part's
 * images) as `pictureOf(href)` gives it (a data: URL, or null where it is not there).
 */
export function feedbackPage(s, rubric, pictureOf) {
  const site = (rubric.feedback && rubric.feedback.courseSite || '').replace(/\/?$/, '/');
  const check = site !== '/' ? `<a href="${esc(`${site}check/`)}">the check page</a>` : 'the check page (check/ on the course site)';
  const who = (s.identity && (s.identity.rosterName || s.identity.name)) || s.name;
  const passes = s.parts.filter((p) => p.verdict === 'pass').length;
  const when = s.identity && s.identity.time ? ` handed in ${esc(s.identity.time.replace('T', ' '))}${s.identity.late ? ' (late)' : ''}` : '';
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data:; style-src 'unsafe-inline'">
<title>Feedback on worksheet 4: ${esc(who)}</title>
<style>body{font-family:system-ui,sans-serif;max-width:60rem;margin:1rem auto;padding:0 1rem;color:#1d2330;line-height:1.45}
.part{border-top:2px solid #ccd;margin-top:1.2rem}.verdict strong{display:inline-block;padding:0 .5rem;border-radius:.6rem;color:#fff;background:#b3261e}
.pass .verdict strong{background:#2a7d2a}.review .verdict strong{background:#8a5a00}.not-graded .verdict strong{background:#556}
.teacher{border-left:4px solid #1d2330;padding-left:.6rem}.pictures{display:flex;flex-wrap:wrap;gap:.8rem}figure{margin:0}
img{width:256px;height:auto;border:1px solid #99a;image-rendering:pixelated}figcaption{font-size:.85rem;color:#445}</style></head><body>
<header><h1>Feedback on worksheet 4</h1><p>For ${esc(who)}${when}: ${passes} of ${s.parts.length} parts pass.
A part passes when it does what its step in the slides asks; a part marked review draws its sphere but misses a point of the step;
a fail does not work yet. The grader opened each of your pages, found your controls by what they do and judged the pictures.</p>
<p>Check again before you hand in: drop your worksheet folder or its zip on ${check} and it gives these same verdicts, in your browser.</p></header>
<main>${s.parts.map((r) => partHtml(r, pictureOf, rubric)).join('\n')}</main></body></html>\n`;
}
