// The course sites, an adapter each (brightspace.js, canvas.js, moodle.js, folders.js): how its
// download names a hand-in (parseTopName, the files it adds beside them), its grade import file
// (gradeFile: { name, make(rows, points) → { text, left } }) and where a student's feedback goes in
// the zip it takes back (feedbackPath). The intake, the grade files and the feedback zip ask the
// adapter; none of them names a site. A new site is a new adapter and a line here.
import { brightspace } from './brightspace.js';
import { canvas } from './canvas.js';
import { moodle } from './moodle.js';
import { folders } from './folders.js';

/** The sites a download can come from, in the order they are tried; plain folders last. */
export const SITE_ADAPTERS = [brightspace, canvas, moodle, folders];

/** The adapter of the site `id` ('brightspace', 'canvas', 'moodle', 'folders'); plain folders for any other. */
export const siteAdapter = (id) => SITE_ADAPTERS.find((a) => a.id === id) || folders;

/** Each site's words for its download's shape, by id. */
export const SITES = Object.fromEntries(SITE_ADAPTERS.map((a) => [a.id, a.describe]));
