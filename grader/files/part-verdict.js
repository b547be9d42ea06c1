// What a part's result file (parts/<student>/<part>.json, written by the run) says the part came to,
// as the progress lines of both browsers' runs say it: read from the out folder, below the command
// and the run alike.
import { readFileSync } from 'node:fs';

/** What a part's result file (item.resultFile) says it came to: its verdict, "not handed in", or '' before one is written. */
export function verdictOfPart(item) {
  try {
    const r = JSON.parse(readFileSync(item.resultFile, 'utf8'));
    return r.status === 'missing' ? 'not handed in' : r.status === 'timeout' ? 'timeout' : r.verdict;
  } catch {
    return '';
  }
}
