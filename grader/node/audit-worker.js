// One audit worker (audit-pool.js): an artifact's folder in, its judging out.
import { parentPort, workerData } from 'node:worker_threads';
import { readArtifact } from './artifacts.js';
import { judged } from '../core/grade-part.js';

parentPort.on('message', (dir) => {
  const artifact = readArtifact(dir);
  if (!artifact) return parentPort.postMessage(null);
  const j = judged(artifact, workerData.rubric);
  delete j.images; // (pictures stay here: the artifact's files name them)
  delete j.artifact;
  parentPort.postMessage({ ...j, files: artifact.files, errors: artifact.facts.errors || [] });
});
