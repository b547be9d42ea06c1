// The class page's grid: a row a student, a cell a part, its verdict and its reasons folded under
// it, and there the teacher's last word (a verdict and a note to the student), as overrides.tsv
// gives it to the command: shown as the teacher's, the grader's beside it.
import { PARTS } from '../grader/core/part-names.js';
import { el } from '../check/dom.js';

const VERDICTS = ['pass', 'review', 'fail'];


/** The badge of a verdict (pass, review, fail; anything else, such as not graded here, is grey). */
const badge = (verdict) => el('span', { className: `badge ${VERDICTS.includes(verdict) ? verdict : 'unchecked'}`, textContent: verdict });

/** The pictures a cell shows, as the report shows them: the part's judged picture and our step beside it. */
const PICTURES = [['judged', 'judged'], ['reference', 'our step, same size and light']];

/**
 * The grid of `students` (take-in's submissions): { table, show(row) (a part's row, as graded),
 * teacher(name, part, override or null) (the teacher's verdict shown) }. `onOverride(name, part,
 * { verdict, note } | null)` is called when the teacher sets or clears a verdict in a cell;
 * `pictureOf(href)` gives a row's picture as a data: URL (or null).
 */
export function gridOf(students, onOverride, pictureOf = () => null) {
  const cells = new Map();
  const key = (name, part) => `${name}\n${part}`;
  const body = el('tbody', {}, ...students.map((s) => {
    const tr = el('tr', {}, el('th', { scope: 'row', textContent: s.name }));
    for (const part of PARTS) {
      const td = el('td', { className: 'pending', textContent: s.error ? '' : 'waiting' });
      cells.set(key(s.name, part), { td, row: null, override: null });
      tr.append(td);
    }
    return tr;
  }));
  const table = el('table', { className: 'grid' },
    el('thead', {}, el('tr', {}, el('th', { textContent: 'Student' }), ...PARTS.map((p) => el('th', { textContent: p })))), body);

  const draw = (cell) => {
    const { td, row, override } = cell;
    const verdict = override ? override.verdict : row.verdict;
    td.className = 'verdict';
    td.dataset.verdict = verdict;
    const summary = el('summary', {}, badge(verdict), override ? el('small', { textContent: ` the teacher's (the grader's: ${row.verdict})` }) : null);
    const choice = el('select', { ariaLabel: `${row.name} ${row.part}: the teacher's verdict` },
      el('option', { value: '', textContent: `the grader's (${row.verdict})` }), ...VERDICTS.map((v) => el('option', { value: v, textContent: v })));
    choice.value = override ? override.verdict : '';
    const note = el('input', { type: 'text', value: override ? override.note : '', ariaLabel: `${row.name} ${row.part}: a note to the student` });
    const set = el('button', { type: 'button', textContent: 'Set' });
    const chosen = () => (choice.value ? { verdict: choice.value, note: note.value.trim() } : null);
    set.addEventListener('click', () => onOverride(row.name, row.part, chosen()));
    const figures = PICTURES.filter(([k]) => row.images && pictureOf(row.images[k])).map(([k, caption]) => el('figure', {},
      el('img', { src: pictureOf(row.images[k]), alt: `${row.name} ${row.part}: ${caption}`, width: 120, height: 120 }),
      el('figcaption', { textContent: caption })));
    td.replaceChildren(el('details', {}, summary,
      el('ul', {}, ...row.reasons.map((t) => el('li', { textContent: t }))),
      figures.length ? el('div', { className: 'pictures' }, ...figures) : null,
      el('p', { className: 'override' }, el('label', {}, 'Your verdict ', choice), ' ', el('label', {}, 'note to the student ', note), ' ', set)));
  };
  return {
    table,
    show: (row) => {
      const cell = cells.get(key(row.name, row.part));
      cell.row = row;
      draw(cell);
    },
    teacher: (name, part, override) => {
      const cell = cells.get(key(name, part));
      cell.override = override;
      if (cell.row) draw(cell);
    },
  };
}
