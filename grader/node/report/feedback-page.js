// A student's feedback page as the command makes it (grader/class/feedback-page.js), its pictures
// read from the out folder and inlined as data: URLs.
import { existsSync, readFileSync } from 'node:fs';
import { fileOfHref } from '../../files/layout.js';
import { feedbackPage } from '../../class/feedback-page.js';

/** A picture of the report (a path relative to `out`) as a data: URL, or null when it is not there. */
function dataUrl(out, rel) {
  if (!rel) return null;
  const f = fileOfHref(out, rel); // (the report's links are URLs: a name's letters are %-encoded there)
  if (!f || !existsSync(f) || !/\.png$/i.test(f)) return null;
  return `data:image/png;base64,${readFileSync(f).toString('base64')}`;
}

/** The pictures of the report in `out`, as the feedback pages inline them: (href) → a data: URL or null. */
export const picturesIn = (out) => (rel) => dataUrl(out, rel);

/** The feedback page of student `s` ({ name, identity, parts }), its pictures read from `out`. */
export function feedbackHtml(s, out, rubric) {
  return feedbackPage(s, rubric, picturesIn(out));
}
