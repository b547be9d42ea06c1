#!/usr/bin/env node
// npm run publish-site -- --out DIR: the site as static files, to serve from any web server or path
// (GitHub Pages: push DIR to a gh-pages branch, or let a Pages workflow upload it): the steps, the
// lab, the check page, the class page, the grader's modules they run, and the few files of npm
// packages they load (by the same relative paths as from the repository, under node_modules/),
// with .nojekyll so that GitHub Pages serves node_modules/ as it is.
import { cpSync, existsSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { UsageError, isMainScript, parseOptions, runCommand } from './cli.js';

const repo = path.dirname(path.dirname(fileURLToPath(import.meta.url)));

/** The site's own folders and files (what its pages load, and what those load). */
export const SITE = ['index.html', 'WP04P1', 'WP04P2', 'WP04P3', 'WP04P4', 'WP04P5', 'common', 'check', 'grade', 'lab',
  'grader/core', 'grader/class', 'grader/browser', 'grader/files', 'grader/similarity'];
/** The packages' files the pages load (check/files.js, check/guard.js, grade/index.html's import map, lab/index.html). */
export const VENDOR = ['fflate/esm/browser.js', 'acorn/dist/acorn.mjs', 'pixelmatch/index.js', 'csv-parse/dist/esm/sync.js',
  'csv-stringify/dist/esm/sync.js', 'chart.js/dist/chart.umd.min.js'];

const HELP = `usage: npm run publish-site -- --out DIR
Writes the site as static files into DIR (made anew): ${SITE.join(', ')}, and from node_modules/
${VENDOR.join(', ')}; and .nojekyll (GitHub Pages then serves node_modules/ too). Serve DIR from any
path of any web server: the check page and the class page work from there (over https, or
http://localhost). For GitHub Pages: publish DIR as the Pages site (a gh-pages branch holding it, or
a workflow's upload-pages-artifact), then open <the Pages URL>/grade/.
exit codes: 0 written, 1 a file missing (run npm ci first), 2 bad usage`;

/** Writes the site into `out`; returns how many files and folders were copied. */
export function publish(out, { log = () => {} } = {}) {
  const missing = VENDOR.filter((f) => !existsSync(path.join(repo, 'node_modules', f)));
  if (missing.length) throw new Error(`not installed: node_modules/${missing.join(', node_modules/')} (run npm ci first)`);
  rmSync(out, { recursive: true, force: true });
  mkdirSync(out, { recursive: true });
  for (const [k, p] of SITE.entries()) {
    log(`copying ${p} (${k + 1} of ${SITE.length})`);
    cpSync(path.join(repo, p), path.join(out, p), { recursive: true });
  }
  for (const f of VENDOR) cpSync(path.join(repo, 'node_modules', f), path.join(out, 'node_modules', f));
  writeFileSync(path.join(out, '.nojekyll'), '');
  return SITE.length + VENDOR.length;
}

if (isMainScript(import.meta.url)) {
  runCommand({
    name: 'publish',
    help: HELP,
    readOptions: (argv) => {
      const o = parseOptions(argv, { out: { type: 'string' } });
      if (!o.help && !o.out) throw new UsageError('give --out DIR');
      return o;
    },
    run: (o) => {
      const out = path.resolve(o.out);
      const tty = process.stdout.isTTY;
      const n = publish(out, { log: (line) => tty && process.stdout.write(`\rpublish: ${line}\x1b[K`) });
      console.log(`${tty ? '\r' : ''}publish: the site in ${out} (${n} folders and files copied)${tty ? '\x1b[K' : ''}`);
      return 0;
    },
  });
}
