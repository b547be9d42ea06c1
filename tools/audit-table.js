#!/usr/bin/env node
// The grader README's table of audit units, made from the list the grader runs
// (grader/core/audits/list.js): one row a unit, in the order they run, with the ids it says, the
// facts it reads and the units whose results it uses; then what each audit checks, with its title
// and the title a part that misses it gets. The README holds it between two markers;
// `npm test` holds the README to the list.
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { AUDIT_LIST } from '../grader/core/audits/list.js';
import { AUDITS } from '../grader/core/audits/index.js';
import { requiredFacts } from '../grader/core/audits/unit.js';
import { isMainScript, parseOptions, runCommand } from './cli.js';

export const README = path.join(path.dirname(fileURLToPath(import.meta.url)), '../grader/README.md');
export const BEGIN = '<!-- audit units: made by tools/audit-table.js -->';
export const END = '<!-- end of audit units -->';

const HELP = `usage: node tools/audit-table.js [--check]
Writes the table of audit units (grader/core/audits/list.js: the order they run, the ids each says,
the facts each reads, the units whose results each uses) into grader/README.md, between its markers.
  --check  write nothing: say whether the README's table is the list's
exit codes: 0 written (or, with --check, up to date), 1 out of date or no markers, 2 bad usage`;

const code = (xs) => (xs.length ? xs.map((x) => `\`${x}\``).join(', ') : '—');

/** The table of `units` (AUDIT_LIST's shape), as markdown lines. */
export function auditTable(units) {
  const rows = units.map((u, k) => {
    const says = Object.entries(u.meta).map(([id, m]) => `\`${id}\`: ${m.title}`).join('; ') || '(a reading others use)';
    return `| ${k + 1} | \`${u.id}\` | ${says} | ${code(requiredFacts(u))} | ${code(u.uses)} |`;
  });
  // what each audit checks: every id the grader says (those said around the units, such as
  // page-missing, too), with the title a part that misses it gets
  const audits = new Map(Object.entries(AUDITS));
  for (const u of units) for (const [id, m] of Object.entries(u.meta)) audits.set(id, m);
  const words = [...audits].map(([id, m]) => `- \`${id}\`: **${m.title}**; missed: *${m.failureTitle}*. ${m.description}`);
  return ['| # | unit | says (id: title) | reads (facts.) | uses |', '| - | - | - | - | - |', ...rows, '', 'What each audit checks:', '', ...words].join('\n');
}

/** `text` (the README) with its table made from `units`; throws where the markers are missing. */
export function withTable(text, units) {
  const a = text.indexOf(BEGIN), b = text.indexOf(END);
  if (a < 0 || b < a) throw new Error(`the README has no markers ${BEGIN} … ${END}`);
  return `${text.slice(0, a + BEGIN.length)}\n${auditTable(units)}\n${text.slice(b)}`;
}

function run({ check }) {
  const text = readFileSync(README, 'utf8');
  const made = withTable(text, AUDIT_LIST);
  if (check) {
    console.log(made === text ? 'audit-table: the README\'s table is the list\'s' : 'audit-table: the README\'s table is out of date: run node tools/audit-table.js');
    return made === text ? 0 : 1;
  }
  if (made !== text) writeFileSync(README, made);
  console.log(`audit-table: ${AUDIT_LIST.length} units in ${path.relative(process.cwd(), README)}${made === text ? ' (unchanged)' : ''}`);
  return 0;
}

if (isMainScript(import.meta.url)) {
  runCommand({ name: 'audit-table', help: HELP, readOptions: (argv) => parseOptions(argv, { check: { type: 'boolean' } }), run });
}
