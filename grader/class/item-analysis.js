// Item analysis across a class: for each part, each check the grader made (its reason with the
// student's numbers taken out) with how many students it passed or failed, the most frequent
// first, so a teacher sees what the class missed, and which checks nobody misses. Reads the
// grader's reasons, never the teacher's overrides.

import { findingsOfResult } from '../core/part-result.js';
import { esc } from '../files/html.js';

/**
 * A finding ({ id, level, reason }: findingsOfResult) as a check: { level (pass, review, fail), key
 * (the reason without its numbers), id (its audit) }, or null for a note, a page error, or what a
 * part not graded here showed.
 */
export function findingOf(f) {
  if (!['pass', 'review', 'fail'].includes(f.level)) return null;
  const { level } = f;
  const text = f.reason.replace(/^(FAIL|REVIEW): /, '');
  if (level === 'pass' && /^note:/.test(text)) return null;
  // the reason's first clause (its numbers are in brackets or after a colon), a count it begins
  // with as "#": the same check reads alike for every student; a formula's numbers stay
  const key = text.split(/ \(|: /)[0].replace(/^\d+ /, '# ').trim();
  return { level, key, id: f.id };
}

/**
 * The class's checks, part by part: [{ part, students, passed (the part), checks: [{ key, level,
 * count, example }] }], failed and reviewed checks first, each by how many students it concerns.
 */
export function itemAnalysis(rows, parts) {
  return parts.map((part) => {
    const results = rows.map((s) => s.parts.find((p) => p.part === part)).filter(Boolean);
    const checks = new Map();
    for (const r of results) {
      const seen = new Set();
      for (const finding of findingsOfResult(r)) {
        const f = findingOf(finding);
        if (!f) continue;
        const id = `${f.level}|${f.key}`;
        if (seen.has(id)) continue;
        seen.add(id);
        if (!checks.has(id)) checks.set(id, { ...f, count: 0, example: finding.reason });
        checks.get(id).count++;
      }
    }
    const order = { fail: 0, review: 1, pass: 2 };
    return {
      part,
      students: results.length,
      passed: results.filter((r) => (r.grader ? r.grader.verdict : r.verdict) === 'pass').length,
      checks: [...checks.values()].sort(
        (a, b) => order[a.level] - order[b.level] || b.count - a.count || a.key.localeCompare(b.key),
      ),
    };
  });
}

/** The item analysis as a section of the report. */
export function itemAnalysisHtml(analysis) {
  return `<section id="items"><h2>Item analysis</h2><p>Each part's checks across the class, as the grader made them (the teacher's
overrides aside): how many students each one failed, asked a teacher to review, or passed, the most frequent first.
A count a reason begins with is shown as #; hover for one student's reason in full.</p>` +
    analysis.map((a) => `<h3>${esc(a.part)}: ${a.passed} of ${a.students} pass</h3><table class="items"><thead><tr><th>check</th><th>result</th><th>students</th></tr></thead><tbody>` +
      a.checks.map((c) => `<tr class="${esc(c.level)}"><td title="${esc(c.example)}">${esc(c.key)}</td><td>${esc(c.level)}</td><td class="num">${c.count} of ${a.students}</td></tr>`).join('') +
      '</tbody></table>').join('\n') + '</section>';
}
