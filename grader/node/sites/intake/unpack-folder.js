// One student's hand-in written out to a folder of its own (the unpacking, its bounds and its
// names: grader/class/intake/unpack.js). Nothing is written outside the folder, over a file or
// through a link.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { IntakeError } from '../../../class/intake/zip.js';

/**
 * The `put` of unpack.js's unpackFiles that writes a hand-in into `root` (an empty or missing
 * folder, made here); it throws an IntakeError with a message for the teacher for a file it cannot write.
 */
export function handinWriter(root) {
  mkdirSync(root, { recursive: true });
  return (real, data, shown) => {
    const target = path.join(root, ...real);
    const rel = path.relative(root, target);
    if (!rel || rel.startsWith('..') || path.isAbsolute(rel)) throw new IntakeError(`"${shown}" would be written outside the hand-in`);
    try {
      mkdirSync(path.dirname(target), { recursive: true });
      // (wx: never over a file, never through a link; the folder is new and only this code writes it)
      writeFileSync(target, data, { flag: 'wx' });
    } catch (err) {
      // a path too long or too deep for this file system, a name it refuses: this hand-in's message
      const short = shown.length > 120 ? `${shown.slice(0, 60)}…${shown.slice(-60)}` : shown;
      throw new IntakeError(`"${short}" could not be written here (${err.code || err.message}); nothing of it was graded`, { cause: err });
    }
  };
}
