// The second signal, from the grader's own pictures: two hand-ins whose judged frames of a part
// are pixel-identical where the rest of the class differs. Reads the pictures a grading run left
// in its out folder; judgedPicture() is the one place that knows where they are.
import { createHash } from 'node:crypto';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { partFiles } from '../files/layout.js';

/** The judged picture of a hand-in's part in a grading out folder (its artifact: grader/node/run/artifacts.js), or null. */
export function judgedPicture(out, name, part) {
  const dir = partFiles(out, name, part).artifactDir;
  try {
    const facts = JSON.parse(readFileSync(path.join(dir, 'facts.json'), 'utf8'));
    const file = facts.files && facts.files[facts.facesImage || facts.judged];
    return file && existsSync(path.join(dir, file)) ? path.join(dir, file) : null;
  } catch {
    return null;
  }
}

/** A hash of a PNG's pixels and size (not its bytes: two encoders may write the same pixels apart). */
function pixelHash(file) {
  try {
    const png = PNG.sync.read(readFileSync(file));
    return createHash('sha1').update(`${png.width}x${png.height}:`).update(png.data).digest('hex');
  } catch {
    return null;
  }
}

/**
 * The pairs of hand-ins with the same judged picture of a part, where at least `others` more
 * hand-ins have a picture of that part and no third shares it: Map 'a\u0000b' → [part, ...].
 */
export function samePictures(out, names, parts, others = 1) {
  const pairs = new Map();
  for (const part of parts) {
    const groups = new Map();
    let pictures = 0;
    for (const name of names) {
      const file = out && judgedPicture(out, name, part);
      const h = file && pixelHash(file);
      if (!h) continue;
      pictures++;
      if (!groups.has(h)) groups.set(h, []);
      groups.get(h).push(name);
    }
    for (const group of groups.values()) {
      if (group.length !== 2 || pictures < 2 + others) continue;
      const key = [...group].sort().join('\u0000');
      pairs.set(key, [...(pairs.get(key) || []), part]);
    }
  }
  return pairs;
}
