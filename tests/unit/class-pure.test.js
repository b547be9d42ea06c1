// grader/class/ makes a class's outputs (the report, the grade files, the feedback pages and zip)
// from rows, in Node and in a page alike: nothing it imports, all the way down, is a Node module.
// Lint holds each file in grader/class/; this follows the imports out of it (grader/core/,
// grader/files/, grader/similarity/ ...), where lint allows Node.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { builtinModules } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const CLASS = path.join(path.dirname(fileURLToPath(import.meta.url)), '../../grader/class');
// the packages the outputs are made with (each usable in a page; pixelmatch compares a part with ours): a new one is a choice made here
const PACKAGES = ['fflate', 'csv-parse/sync', 'csv-stringify/sync', 'pixelmatch'];
const SPECIFIER = /(?:^|[\s;])(?:import|export)\s[^'"]*?from\s*['"]([^'"]+)['"]|import\(\s*['"]([^'"]+)['"]\s*\)/g;

const filesUnder = (dir) => readdirSync(dir).flatMap((f) => {
  const p = path.join(dir, f);
  return statSync(p).isDirectory() ? filesUnder(p) : f.endsWith('.js') ? [p] : [];
});

/** A module's code, its comments left out. */
const codeOf = (file) => readFileSync(file, 'utf8').replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
// Node's own globals, which a page does not have (a page's module that touches one throws)
const NODE_GLOBALS = /\b(Buffer|process|require|__dirname|__filename|global)\b(?!\s*:)/;

/** Every module reached from `roots` by their imports: { modules (files), outside (bare specifiers, with who imports them) }. */
function reached(roots) {
  const seen = new Set(), outside = [];
  const visit = (file) => {
    if (seen.has(file)) return;
    seen.add(file);
    const code = codeOf(file);
    for (const m of code.matchAll(SPECIFIER)) {
      const spec = m[1] || m[2];
      if (spec.startsWith('.')) visit(path.resolve(path.dirname(file), spec));
      else outside.push({ spec, from: path.relative(CLASS, file) });
    }
  };
  roots.forEach(visit);
  return { modules: [...seen], outside };
}

test('nothing grader/class/ imports, all the way down, is a Node module; its packages are the ones named', () => {
  const { modules, outside } = reached(filesUnder(CLASS));
  assert.ok(modules.length > 20, `${modules.length} modules reached`);
  const node = outside.filter(({ spec }) => spec.startsWith('node:') || builtinModules.includes(spec.split('/')[0]));
  assert.deepEqual(node, []);
  assert.deepEqual(outside.filter(({ spec }) => !PACKAGES.includes(spec)), []);
  // nor a global only Node has (Buffer, process, require, ...): strings aside, where a sentence may name one
  const strings = /(['"`])(?:\\.|(?!\1)[^\\\n])*\1/g;
  const uses = modules.filter((f) => NODE_GLOBALS.test(codeOf(f).replace(strings, '""'))).map((f) => path.relative(CLASS, f));
  assert.deepEqual(uses, []);
});

test('the walk sees an import of Node where there is one (the command\'s report writer)', () => {
  const writer = path.join(CLASS, '../node/report/report.js');
  const { outside } = reached([writer]);
  assert.ok(outside.some(({ spec }) => spec.startsWith('node:')), JSON.stringify(outside));
});
