// A teacher's own labels against the grader's verdicts: agreement per part, a confusion table
// (label × verdict) and the disagreements with both sides' reasons. Labels come as a TSV with a
// header (submission, part, label, and optionally api, controls, reasons), the format of
// ../shared/handins/labels.tsv; a label is correct, partial or broken (or the verdict itself:
// pass, review, fail). Plain data in, plain data out: no browser, no files (the command reads the
// labels' file: grader/node/report/labels.js).
import { NOT_GRADED } from '../core/verdict.js';
import { asking } from '../core/part-result.js';
import { readRows } from '../files/csv.js';
import { esc } from '../files/html.js';

/** The verdict a label asks for: correct → pass, partial → review, broken → fail. */
export const VERDICT_OF_LABEL = { correct: 'pass', partial: 'review', broken: 'fail', pass: 'pass', review: 'review', fail: 'fail' };
export const LABELS = ['correct', 'partial', 'broken'];
const VERDICTS = ['pass', 'review', 'fail'];

/**
 * Parses a labels TSV ("#" starts a comment line; a cell may be quoted, as a spreadsheet writes a
 * tab, a quote or a line break in one). Returns [{ submission, part, label, reasons, unsure }];
 * throws an Error naming the line for a row it cannot read.
 */
export function parseLabels(text, file = 'labels') {
  const rows = readRows(text, { delimiter: '\t', comments: true, file });
  if (!rows.length) throw new Error(`${file}: no labels in it`);
  const head = rows[0].cells.map((h) => h.trim().toLowerCase());
  const col = (name) => head.indexOf(name);
  for (const need of ['submission', 'part', 'label']) {
    if (col(need) < 0) throw new Error(`${file}: the first line must name the columns submission, part and label (tab-separated); it has ${head.join(', ')}`);
  }
  return rows.slice(1).map(({ cells, line }) => {
    const get = (name) => (col(name) >= 0 ? (cells[col(name)] || '').trim() : '');
    const label = get('label').toLowerCase();
    const part = get('part').toUpperCase();
    if (!VERDICT_OF_LABEL[label]) throw new Error(`${file}, line ${line}: label "${get('label')}" is none of correct, partial, broken`);
    if (!/^WP04P[1-5]$/.test(part)) throw new Error(`${file}, line ${line}: part "${get('part')}" is none of WP04P1 … WP04P5`);
    const reasons = get('reasons');
    const known = LABELS.includes(label) ? label : LABELS[VERDICTS.indexOf(label)];
    return { submission: get('submission'), part, label: known, reasons, unsure: /\(unsure\)/i.test(reasons) };
  });
}

/**
 * The grader against the labels. `submissions` as in report.json ([{ name, parts: [{ part,
 * verdict, reasons }] }]). Returns { rows, confusion, agree, total, correctPassed, correct,
 * partialPassed, partial, brokenPassed, broken, missing, notGraded }; each row { submission, part,
 * label, want, verdict, agree, labelReasons, reasons, unsure }. A part "not graded here" (WebGPU in
 * a browser without it) is neither an agreement nor a disagreement: it is counted under "not
 * graded", listed in `notGraded`, and left out of the totals.
 */
export function agreement(labels, submissions) {
  const confusion = Object.fromEntries(LABELS.map((l) => [l, Object.fromEntries([...VERDICTS, 'not graded'].map((v) => [v, 0]))]));
  const rows = [];
  const missing = [];
  const notGraded = [];
  for (const l of labels) {
    const s = submissions.find((x) => x.name === l.submission);
    const found = s && s.parts.find((p) => p.part === l.part);
    // (the labels are held to the grader's own verdict, a teacher's override aside: overrides.js)
    const got = found && found.grader ? { ...found, verdict: found.grader.verdict } : found;
    if (!got) {
      missing.push(`${l.submission} ${l.part}`);
      confusion[l.label]['not graded']++;
      continue;
    }
    if (got.verdict === NOT_GRADED) {
      notGraded.push(`${l.submission} ${l.part}`);
      confusion[l.label]['not graded']++;
      continue;
    }
    const want = VERDICT_OF_LABEL[l.label];
    confusion[l.label][got.verdict]++;
    rows.push({
      submission: l.submission,
      part: l.part,
      label: l.label,
      want,
      verdict: got.verdict,
      agree: got.verdict === want,
      labelReasons: l.reasons,
      reasons: got.reasons || [],
      asking: asking(got).map((f) => f.reason),
      unsure: l.unsure,
    });
  }
  const count = (f) => rows.filter(f).length;
  const here = labels.filter((x) => !notGraded.includes(`${x.submission} ${x.part}`));
  const labelled = (l) => here.filter((x) => x.label === l).length;
  return {
    rows, confusion, missing, notGraded,
    agree: count((r) => r.agree), total: here.length,
    correct: labelled('correct'), correctPassed: count((r) => r.label === 'correct' && r.verdict === 'pass'),
    partial: labelled('partial'), partialPassed: count((r) => r.label === 'partial' && r.verdict === 'pass'),
    broken: labelled('broken'), brokenPassed: count((r) => r.label === 'broken' && r.verdict === 'pass'),
  };
}

const pct = (a, b) => (b ? `${((100 * a) / b).toFixed(0)}%` : '–');

/** The agreement as lines of text, for stdout. */
export function agreementText(a) {
  const out = [];
  out.push(`labels: ${a.agree} of ${a.total} labelled parts get their label's verdict (${pct(a.agree, a.total)}); ` +
    `correct parts passed ${a.correctPassed} of ${a.correct}, partial parts passed ${a.partialPassed} of ${a.partial}, broken parts passed ${a.brokenPassed} of ${a.broken}`);
  out.push('labels: label × verdict    pass  review  fail  not graded');
  for (const l of LABELS) {
    const c = a.confusion[l];
    const cells = [[c.pass, 6], [c.review, 8], [c.fail, 6], [c['not graded'], 12]].map(([n, w]) => String(n).padStart(w));
    out.push(`labels: ${l.padEnd(18)}${cells.join('')}`);
  }
  for (const r of a.rows.filter((x) => !x.agree)) {
    out.push(`labels: ${r.submission} ${r.part}: labelled ${r.label}${r.unsure ? ' (unsure)' : ''}, graded ${r.verdict}: ${r.asking.join(' | ') || r.reasons[0] || ''}`);
  }
  for (const m of a.missing) out.push(`labels: ${m}: labelled, but no such part was graded`);
  if (a.notGraded && a.notGraded.length) out.push(`labels: not graded here (WebGPU, which this browser does not have), left out of the counts: ${a.notGraded.join(', ')}`);
  return out;
}

/** The agreement as an HTML section for report.html. */
export function agreementHtml(a, anchor = (r) => `#${r.submission}-${r.part}`) {
  const head = `<th>label \\ verdict</th>${VERDICTS.map((v) => `<th>${v}</th>`).join('')}<th>not graded</th>`;
  const cell = (l, v) => `<td class="num${VERDICT_OF_LABEL[l] === v ? ' agree' : ''}">${a.confusion[l][v]}</td>`;
  const body = LABELS.map((l) => `<tr><th scope="row">${l} (→ ${VERDICT_OF_LABEL[l]})</th>` +
    `${[...VERDICTS, 'not graded'].map((v) => cell(l, v)).join('')}</tr>`).join('');
  const rows = a.rows.filter((r) => !r.agree).map((r) => `<tr><td><a href="${esc(anchor(r))}">${esc(r.submission)} ${r.part}</a></td>` +
    `<td>${esc(r.label)}${r.unsure ? ' (unsure)' : ''}: ${esc(r.labelReasons)}</td>` +
    `<td>${esc(r.verdict)}: ${esc(r.asking.join(' | ') || r.reasons[0] || '')}</td></tr>`).join('');
  return `<section id="labels"><h2>Against the teacher's labels</h2><p>${a.agree} of ${a.total} labelled parts get their label's verdict (${pct(a.agree, a.total)}): ` +
    `correct → pass ${a.correctPassed} of ${a.correct}, partial → review (passed: ${a.partialPassed} of ${a.partial}), broken → fail (passed: ${a.brokenPassed} of ${a.broken}).` +
    `${a.notGraded && a.notGraded.length ? ` Not graded here (WebGPU, which this browser does not have), left out of these counts: ${esc(a.notGraded.join(', '))}.` : ''}</p>` +
    `<table class="confusion"><thead><tr>${head}</tr></thead><tbody>${body}</tbody></table>` +
    (rows ? `<h3>Where the grader and the labels differ</h3><table class="disagree"><thead><tr><th>part</th><th>the label says</th><th>the grader says</th></tr></thead><tbody>${rows}</tbody></table>` : '<p>No disagreements.</p>') +
    '</section>';
}
