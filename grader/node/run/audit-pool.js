// Audits of many saved artifacts at once, in child processes (one a core): the judging of a class
// is pure arithmetic on pictures, so it parallelises as it is. Each result is what
// grade-part.js's judged() gives, without the pictures (plain data, as a child sends it). Processes,
// not worker threads: Node 20 can abort the whole process when a worker thread ends while V8 still
// compiles its code in the background (it did once, in npm test's unit tests).
import { fork } from 'node:child_process';
import { readdirSync, statSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const WORKER = fileURLToPath(new URL('./audit-worker.js', import.meta.url));

/**
 * Judges the artifact in each of `dirs` under `rubric`: a Map dir → { fail, checks, numbers, shown,
 * tooSlow, api, canvas, actions, controls, files, errors, stale } (null where there is no artifact;
 * `stale`: the keys its gathering read that `rubric` gives other values, gather/reads.js).
 * `progress(done, total)` hears each one; `strict`: the audit units run strictly (audits/strict.js: a
 * unit that reads a fact it does not name throws), as the tests run them.
 */
export async function auditDirs(dirs, rubric, options = {}) {
  const { workers = os.availableParallelism(), progress = () => {}, strict = false } = options;
  const results = new Map();
  // the largest artifacts (the most pictures to read and fit) first, so that no process is left
  // with a long one at the end
  const size = new Map(dirs.map((d) => [d, folderBytes(d)]));
  const queue = [...dirs].sort((a, b) => size.get(b) - size.get(a));
  let done = 0;
  const run = () => new Promise((resolve, reject) => {
    // (no execArgv: under node --test, the parent's flags would make the child a test run)
    const child = fork(WORKER, [], { execArgv: [], serialization: 'advanced', stdio: ['ignore', 'inherit', 'inherit', 'ipc'] });
    let current = null;
    child.once('error', reject);
    child.once('exit', (code, signal) => {
      if (current !== null) reject(new Error(`an audit process ended (${signal || `exit code ${code}`}) while judging ${current}`));
    });
    const next = () => {
      current = queue.shift() ?? null;
      if (current === null) {
        child.disconnect();
        return resolve();
      }
      child.send({ dir: current });
    };
    child.on('message', ({ result, error }) => {
      if (error !== undefined) {
        child.disconnect();
        const dir = current;
        current = null;
        return reject(new Error(`${dir}: ${error}`));
      }
      results.set(current, result);
      progress(++done, dirs.length);
      next();
    });
    child.send({ rubric, strict });
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
