// The feedback pages (feedback/<student>.html; each page the report's, handed in by the caller)
// and the feedback zip laid out as the course site takes it back: the download's own names, so each
// file finds its student (where: the site's adapter's feedbackPath, grader/class/adapters/index.js).
// Rows in, files out: the command writes them (grader/node/report/report.js's writeClass).
import { zipSync, strToU8 } from 'fflate';
import { safeName } from '../files/safe-name.js';
import { siteAdapter } from './adapters/index.js';

export const FEEDBACK_FILE = 'feedback.html';

/** Where a student's feedback goes in the zip for the course site `site`. */
export const feedbackZipPath = (s, site) => siteAdapter(site).feedbackPath(s, FEEDBACK_FILE);

/**
 * Each of `rows`' page (`pageOf(row)`, the report's feedback page) as feedback/<student>.html, and
 * feedback-<site>.zip: { pages: { 'feedback/<student>.html': html }, zip: { 'feedback-<site>.zip': bytes } }.
 */
export function feedbackFiles(rows, pageOf, site = 'folders') {
  const pages = {}, entries = {};
  for (const s of rows) {
    const html = pageOf(s);
    pages[`feedback/${safeName(s.name)}.html`] = html;
    entries[feedbackZipPath(s, site)] = [strToU8(html), { level: 6 }];
  }
  return { pages, zip: { [`feedback-${site}.zip`]: zipSync(entries) } };
}
