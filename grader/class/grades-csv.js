// grades.csv: a row a student, a column a part's verdict, then a part's reasons that ask for
// something (its fails and reviews, and why it was not graded) and the ids of the audits that said
// them (grader/core/audits/index.js). The reasons are chosen by their levels and ids, never by
// their words: a sentence reworded moves no reason in or out of the file.
import { csvText } from '../files/csv.js';
import { asking } from '../core/part-result.js';

/** grades.csv's text for `rows` (report.js's: { name, passes, parts: [{ part, verdict, reasons, findings }] }) over `parts`. */
export function gradesCsv(rows, parts) {
  const head = ['name', 'passes', ...parts, ...parts.map((p) => `${p}_reasons`), ...parts.map((p) => `${p}_audits`)];
  const body = rows.map((s) => {
    const of = (p) => s.parts.find((x) => x.part === p);
    return [s.name, s.passes, ...parts.map((p) => of(p).verdict),
      ...parts.map((p) => asking(of(p)).map((f) => f.reason).join('; ')),
      ...parts.map((p) => [...new Set(asking(of(p)).map((f) => f.id).filter(Boolean))].join(' '))];
  });
  return csvText([head, ...body]);
}
