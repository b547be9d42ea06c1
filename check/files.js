// What a student dropped or picked, as the hand-in the grader would see: a Map from relative
// '/'-separated paths to their contents (Blobs, read only when a frame asks). A folder picked with
// <input webkitdirectory> or dropped is the hand-in's root; a .zip is unpacked in the browser
// (fflate) and its one top folder, if it has nothing else, taken as the root. Dot-files,
// node_modules and __MACOSX are left out as the grader leaves them out. Every refusal is a
// CheckInputError whose message says what to do.
import { unzip } from '../node_modules/fflate/esm/browser.js';
import { partsFound, titleOfPage } from '../grader/core/part-names.js';
import { KIB } from '../grader/core/units.js';

/** More than this is not a worksheet (a course folder, videos, node_modules?). */
export const MAX_BYTES = 100 * KIB * KIB;
export const MAX_FILES = 5000;
/** A size under this many MB is said with a decimal. */
const DECIMALS_BELOW_MB = 10;
/** Pages are looked for this many folders deep at most; a page's first TITLE_BYTES are read for its title; a message names PAGES_NAMED pages. */
const PAGE_DEPTH = 7, TITLE_BYTES = 65536, PAGES_NAMED = 5;

export class CheckInputError extends Error {}

const mb = (n) => `${(n / KIB / KIB).toFixed(n < DECIMALS_BELOW_MB * KIB * KIB ? 1 : 0)} MB`;
const skipped = (segments) => segments.some((s) => s.startsWith('.') || s === 'node_modules' || s === '__MACOSX');

/**
 * The hand-in from a list of { path, blob } ('/'-separated paths as dropped: the picked folder's
 * name first, when a folder was picked). Drops the common top folder, leaves out what the grader
 * leaves out, refuses what is too large.
 * @returns {Map<string, Blob>}
 */
export function handInFrom(entries) {
  const kept = entries
    .map((e) => ({ ...e, segments: e.path.split('/').filter(Boolean) }))
    .filter((e) => e.segments.length && !skipped(e.segments));
  const tops = new Set(kept.map((e) => (e.segments.length > 1 ? e.segments[0] : '')));
  const strip = tops.size === 1 && !tops.has('') ? 1 : 0;
  const bytes = kept.reduce((s, e) => s + e.blob.size, 0);
  if (kept.length > MAX_FILES || bytes > MAX_BYTES) {
    throw new CheckInputError(`That is ${kept.length} files, ${mb(bytes)}: more than a worksheet (at most ${MAX_FILES} files, ${mb(MAX_BYTES)} here). ` +
      'Drop the worksheet\'s own folder (the one with Part1 … Part5 in it), not a whole course folder.');
  }
  const files = new Map();
  for (const e of kept) files.set(e.segments.slice(strip).join('/'), e.blob);
  return files;
}

/** Compares two '/'-separated paths as a walk of sorted folders meets them (the grader's order). */
const walkOrder = (a, b) => {
  const x = a.split('/'), y = b.split('/');
  for (let k = 0; k < Math.min(x.length, y.length); k++) if (x[k] !== y[k]) return x[k] < y[k] ? -1 : 1;
  return x.length - y.length;
};

// the pages the grader walks: HTML, six folders deep at most
const pagesOf = (files) => [...files.keys()].filter((p) => /\.html?$/i.test(p) && p.split('/').length <= PAGE_DEPTH).sort(walkOrder);

/** Each page's title and first heading ({ path: words }), read from its first bytes as the grader reads them. */
export async function titlesOfHandIn(files) {
  const titles = {};
  for (const p of pagesOf(files)) titles[p] = titleOfPage(await files.get(p).slice(0, TITLE_BYTES).text());
  return titles;
}

/**
 * The parts of a hand-in, as the grader finds them: { parts: { WP04P1: path | null, ... }, notes:
 * { WP04Pn: how it was found, where its name did not say it }, pages: the HTML pages seen }.
 * `titles` (titlesOfHandIn) name a step where file names do not.
 */
export function partsOfHandIn(files, titles = {}) {
  const pages = pagesOf(files);
  if (!pages.length) {
    throw new CheckInputError(files.size ? `No HTML page in what you dropped (${files.size} files): a part is an HTML page, e.g. Part1/index.html. Drop the worksheet's folder.`
      : 'Nothing to check: the folder is empty.');
  }
  const { parts, notes } = partsFound(pages.map((p) => p.split('/')), (s) => s.join('/'), { titles });
  if (!Object.values(parts).some(Boolean)) {
    throw new CheckInputError(`None of the HTML pages is named for a part of worksheet 4 (${pages.slice(0, PAGES_NAMED).join(', ')}${pages.length > PAGES_NAMED ? ', …' : ''}). ` +
      'Name each part\'s folder or file for it, e.g. WP04P1/, Part1/, w4p1.html, week04p01.html.');
  }
  return { parts, notes, pages };
}

/** A zip's files as { path, blob }, unpacked here in the browser. */
export async function unzipEntries(file) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  const out = await new Promise((resolve, reject) =>
    unzip(bytes, (err, data) => (err ? reject(err) : resolve(data))),
  ).catch((err) => {
    throw new CheckInputError(
      `${file.name} could not be unpacked (${err.message}). Unzip it yourself and drop the folder.`,
    );
  });
  return Object.entries(out).filter(([p]) => !p.endsWith('/')).map(([p, data]) => ({ path: p, blob: new Blob([data]) }));
}

/** A picked folder (<input webkitdirectory>): its files as { path, blob }. One .zip alone is unpacked. */
export async function entriesFromInput(fileList) {
  const list = [...fileList];
  if (list.length === 1 && /\.zip$/i.test(list[0].name)) return unzipEntries(list[0]);
  return list.map((f) => ({ path: f.webkitRelativePath || f.name, blob: f }));
}

/**
 * A drop: folders walked (FileSystemEntry), files taken, one .zip unpacked (with `zip` false, kept
 * as it is); past `most` files the walk stops (the list then holds more than `most`: the caller
 * says it is too much).
 */
export async function entriesFromDrop(dataTransfer, { most = MAX_FILES, zip = true } = {}) {
  const roots = [...dataTransfer.items]
    .filter((i) => i.kind === 'file')
    .map((i) => i.webkitGetAsEntry && i.webkitGetAsEntry())
    .filter(Boolean);
  if (!roots.length) return entriesFromInput(dataTransfer.files);
  if (zip && roots.length === 1 && roots[0].isFile && /\.zip$/i.test(roots[0].name)) return unzipEntries(dataTransfer.files[0]);
  const out = [];
  const fileOf = (entry) => new Promise((resolve, reject) => entry.file(resolve, reject));
  const children = async (dir) => {
    const reader = dir.createReader(), all = [];
    for (;;) {
      const batch = await new Promise((resolve, reject) => reader.readEntries(resolve, reject));
      if (!batch.length) return all;
      all.push(...batch);
    }
  };
  const walk = async (entry, prefix) => {
    if (out.length > most) return;
    const path = prefix ? `${prefix}/${entry.name}` : entry.name;
    if (skipped([entry.name])) return;
    if (entry.isFile) out.push({ path, blob: await fileOf(entry) });
    else for (const c of await children(entry)) await walk(c, path);
  };
  for (const r of roots) await walk(r, '');
  return out;
}
