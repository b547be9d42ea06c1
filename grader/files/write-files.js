// The files a class's outputs are made of (grader/class/: { 'a/b.html': text or bytes }), written
// into an out folder: each under its relative path, its folders made.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';

/** Writes each of `files` ({ relative path with '/': string or Uint8Array }) under `out`; returns the paths written. */
export function writeFiles(out, files) {
  return Object.entries(files).map(([rel, data]) => {
    const file = path.join(out, ...rel.split('/'));
    mkdirSync(path.dirname(file), { recursive: true });
    writeFileSync(file, data);
    return file;
  });
}
