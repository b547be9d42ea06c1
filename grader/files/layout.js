// Where a grading run puts a part's files in its out folder (parts/<safe name>/<part>.json and the
// pictures beside it, artifacts/<safe name>/<part>/), and how report.html links to them. Paths
// are built with `path.join` and links with file: URLs (Node's url module), never by splitting or
// joining on a separator, so that Windows' out folders work as POSIX's; `pathImpl` is Node's path
// of this machine, or the other one's in tests.
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { safeName } from './safe-name.js';

export { safeName };

/** The files of submission `name`'s `part` in `out`: { resultFile, artifactDir }. */
export function partFiles(out, name, part, pathImpl = path) {
  return {
    resultFile: pathImpl.join(out, 'parts', safeName(name), `${part}.json`),
    artifactDir: pathImpl.join(out, 'artifacts', safeName(name), part),
  };
}

/** The link from a page in `out` (report.html) to `file` under `out`, as an <img src>/<a href> takes it. */
export function hrefOf(out, file, pathImpl = path) {
  const windows = pathImpl === path.win32;
  const base = pathToFileURL(pathImpl.join(out, pathImpl.sep), { windows });
  const target = pathToFileURL(pathImpl.resolve(out, file), { windows });
  if (!target.href.startsWith(base.href)) throw new Error(`${file} is not under ${out}`);
  return target.href.slice(base.href.length);
}

/** The file under `out` that a link of hrefOf names (its letters decoded: Thé_Phone, not Th%C3%A9_Phone); null where it leaves `out`. */
export function fileOfHref(out, href, pathImpl = path) {
  const windows = pathImpl === path.win32;
  const base = pathToFileURL(pathImpl.join(out, pathImpl.sep), { windows });
  const target = new URL(href, base);
  if (!target.href.startsWith(base.href)) return null;
  return fileURLToPath(target, { windows });
}
