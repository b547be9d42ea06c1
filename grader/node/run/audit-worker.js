// One audit process (audit-pool.js): the rubric (and whether the units run strictly, as the tests
// run them: audits/strict.js), then an artifact's folder at a time in, its judging out. It ends when the pool lets go of it (the IPC channel closes).
import { readArtifact } from './artifacts.js';
import { judged } from '../../core/grade-part.js';
import { staleKeys } from '../../core/gather/reads.js';
import { AUDIT_LIST } from '../../core/audits/list.js';
import { strictly } from '../../core/audits/strict.js';

let rubric = null, audits = AUDIT_LIST;
process.on('message', (m) => {
  if (m.rubric) {
    rubric = m.rubric;
    if (m.strict) audits = strictly(AUDIT_LIST);
    return;
  }
  try {
    const artifact = readArtifact(m.dir);
    if (!artifact) return process.send({ result: null });
    const j = judged(artifact, rubric, { audits });
    delete j.images; // (pictures stay here: the artifact's files name them)
    delete j.artifact;
    // the keys the gathering read that this rubric gives other values: gathering again would differ
    const stale = staleKeys(artifact.facts.gatheredWith, rubric);
    process.send({ result: { ...j, files: artifact.files, errors: artifact.facts.errors || [], stale } });
  } catch (err) {
    process.send({ error: err.message });
  }
});
