// The feedback pages on disk (OUT/feedback/<student>.html; each page the report's,
// report/feedback-page.js, handed in by the command) and the feedback zip laid out as the course
// site takes it back: the download's own names, so each file finds its student (where: the site's
// adapter's feedbackPath, grader/node/sites/index.js).
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { zipSync, strToU8 } from 'fflate';
import { safeName } from '../../files/layout.js';
import { siteAdapter } from './index.js';

export const FEEDBACK_FILE = 'feedback.html';

/** Where a student's feedback goes in the zip for the course site `site`. */
export const feedbackZipPath = (s, site) => siteAdapter(site).feedbackPath(s, FEEDBACK_FILE);

/**
 * Writes OUT/feedback/<student>.html for each of `rows` (its page: `pageOf(row)`, the report's
 * feedback page) and OUT/feedback-<site>.zip; returns { pages, zip }.
 */
export function writeFeedback(out, rows, pageOf, site = 'folders') {
  const dir = path.join(out, 'feedback');
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const entries = {};
  const pages = [];
  for (const s of rows) {
    const html = pageOf(s);
    const file = path.join(dir, `${safeName(s.name)}.html`);
    writeFileSync(file, html);
    pages.push(file);
    entries[feedbackZipPath(s, site)] = [strToU8(html), { level: 6 }];
  }
  const zip = path.join(out, `feedback-${site}.zip`);
  writeFileSync(zip, zipSync(entries));
  return { pages, zip };
}
