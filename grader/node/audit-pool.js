// Audits of many saved artifacts at once, on worker threads (one a core): the judging of a class
// is pure arithmetic on pictures, so it parallelises as it is. Each result is what
// grade-part.js's judged() gives, without the pictures (plain data, as a worker sends it).
import { readdirSync, statSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { Worker } from 'node:worker_threads';

const WORKER = new URL('./audit-worker.js', import.meta.url);

/**
 * Judges the artifact in each of `dirs` under `rubric`: a Map dir → { fail, checks, numbers, shown,
 * tooSlow, api, canvas, actions, controls, files, errors } (null where there is no artifact).
 * `progress(done, total)` hears each one.
 */
export async function auditDirs(dirs, rubric, { workers = os.availableParallelism(), progress = () => {} } = {}) {
  const results = new Map();
  // the largest artifacts (the most pictures to read and fit) first, so that no worker is left
  // with a long one at the end
  const size = new Map(dirs.map((d) => [d, folderBytes(d)]));
  const queue = [...dirs].sort((a, b) => size.get(b) - size.get(a));
  let done = 0;
  const run = () => new Promise((resolve, reject) => {
    const w = new Worker(WORKER, { workerData: { rubric } });
    const next = () => {
      const dir = queue.shift();
      if (dir === undefined) return w.terminate().then(() => resolve());
      w.once('message', (r) => {
        results.set(dir, r);
        progress(++done, dirs.length);
        next();
      });
      w.postMessage(dir);
    };
    w.once('error', reject);
    next();
  });
  await Promise.all(Array.from({ length: Math.max(1, Math.min(workers, dirs.length)) }, run));
  return results;
}

/** The bytes of the files in `dir` (0 where it is missing). */
function folderBytes(dir) {
  try {
    return readdirSync(dir).reduce((sum, f) => sum + statSync(path.join(dir, f)).size, 0);
  } catch {
    return 0;
  }
}
