// A part's artifact on disk (Lighthouse's latest-run/): `facts.json` (what the page showed, as
// plain data) and its pictures as PNG files beside it (png.js: the browser's own bytes where it
// handed the picture over as a PNG), a picture shown twice stored once
// (facts.json's `files` maps each picture's name to its file; its `schema` numbers its shape).
// Read back, it audits as it did when gathered: `npm run grade -- --audit-only OUT` re-judges a
// class with no browser.
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { decodePng, pngBytes } from './png.js';
import { ARTIFACT_SCHEMA, currentFacts } from '../../core/artifact-schema.js';

/** Writes `artifact` ({ facts, images }) into `dir` (emptied first); returns the files by picture name. */
export function writeArtifact(dir, { facts, images }) {
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const files = {};
  const byHash = new Map();
  for (const [name, img] of Object.entries(images)) {
    const hash = createHash('sha1').update(`${img.width}x${img.height}:`).update(img.data).digest('hex');
    if (!byHash.has(hash)) {
      const file = `${name}.png`;
      writeFileSync(path.join(dir, file), pngBytes(img));
      byHash.set(hash, file);
    }
    files[name] = byHash.get(hash);
  }
  writeFileSync(path.join(dir, 'facts.json'), `${JSON.stringify({ schema: ARTIFACT_SCHEMA, ...facts, files }, null, 1)}\n`);
  return files;
}

/**
 * The artifact in `dir`: { facts, images, files }, its facts in today's shape (an older one brought
 * up to it by core/artifact-schema.js), each of its pictures read from its file when first asked
 * for; null when there is none.
 */
export function readArtifact(dir) {
  const f = path.join(dir, 'facts.json');
  if (!existsSync(f)) return null;
  const { files = {}, ...facts } = currentFacts(JSON.parse(readFileSync(f, 'utf8')));
  // each picture decoded when first read (an audit reads a few of a part's many), once a file
  const images = {};
  const read = new Map();
  const decoded = (file) => {
    if (!read.has(file)) read.set(file, decodePng(readFileSync(path.join(dir, file))));
    return read.get(file);
  };
  for (const [name, file] of Object.entries(files)) {
    Object.defineProperty(images, name, { get: () => decoded(file), enumerable: true });
  }
  return { facts, images, files };
}

/** Every artifact under `root` (root/<submission>/<part>/facts.json): [{ submission, part, dir }]. */
export function listArtifacts(root) {
  if (!existsSync(root)) return [];
  const out = [];
  for (const s of readdirSync(root, { withFileTypes: true }).filter((e) => e.isDirectory()).map((e) => e.name).sort()) {
    const sd = path.join(root, s);
    for (const p of readdirSync(sd).sort()) {
      if (existsSync(path.join(sd, p, 'facts.json'))) out.push({ submission: s, part: p, dir: path.join(sd, p) });
    }
  }
  return out;
}
