// CSV and TSV, read and written by csv-parse and csv-stringify (RFC 4180: a quoted cell may hold
// the delimiter, doubled quotes and line breaks; a BOM; CRLF or LF). Each file's own conventions
// stay with the module that reads or writes it: Brightspace's "#" before an id (roster.js,
// grade-files.js), the teacher's files as TSV with "#" comment lines (labels.js, overrides.js).
import { parse } from 'csv-parse/sync';
import { stringify } from 'csv-stringify/sync';

/** The delimiter of a table: a tab when its first line has more tabs than commas, else a comma. */
function delimiterOf(text) {
  const first = text.split(/\r?\n/, 1)[0];
  return (first.match(/\t/g) || []).length > (first.match(/,/g) || []).length ? '\t' : ',';
}

/**
 * The rows of CSV or TSV `text`: [{ cells, line }], `line` the line the row starts on (from 1);
 * a BOM before it is left out.
 * `delimiter`: ',' or '\t', or null to take the one the first line has more of. `comments`: a line
 * starting with "#" is a comment (never a "#" inside a line: Brightspace's ids start with one).
 * A quote inside an unquoted cell is kept as typed; blank lines and lines of empty cells are left
 * out. Throws an Error naming `file` and the line csv-parse stopped on (a quote never closed).
 */
export function readRows(text, { delimiter = null, comments = false, file = 'the table' } = {}) {
  let records;
  try {
    records = parse(text, {
      // (each line may end in CRLF, LF or CR: a file added to in another editor mixes them)
      delimiter: delimiter || delimiterOf(text), record_delimiter: ['\r\n', '\n', '\r'],
      bom: true, relax_quotes: true, relax_column_count: true, skip_empty_lines: true, info: true,
      ...(comments ? { comment: '#', comment_no_infix: true } : {}),
    });
  } catch (err) {
    throw new Error(`${file}, line ${err.lines ?? '?'}: ${err.message}`, { cause: err });
  }
  // Each row's line, counted here from where csv-parse says the row ends (info.bytes, in UTF-8,
  // its line break included): its own count of lines takes a CRLF inside a quoted cell for two.
  const breaks = (text) => (text.match(/\r\n|\r|\n/g) || []).length;
  // (TextEncoder and TextDecoder, not Buffer: a page reads class lists and overrides with this too)
  const bytes = new TextEncoder().encode(text), utf8 = new TextDecoder('utf-8', { ignoreBOM: true });
  let at = 0, lineAt = 1;
  const rows = records.map(({ record, info }) => {
    const text = utf8.decode(bytes.subarray(at, info.bytes));
    const own = text.replace(/(?:\r\n|\r|\n)$/, '');
    const end = lineAt + breaks(own);
    [at, lineAt] = [info.bytes, end + (own.length < text.length ? 1 : 0)];
    return { cells: record, line: end - record.reduce((n, c) => n + breaks(c), 0) };
  });
  return rows.filter(({ cells }) => cells.some((c) => c.trim()));
}

/** The rows of CSV or TSV `text` as arrays of cells (readRows without the line numbers). */
export const readTable = (text, options) => readRows(text, options).map((r) => r.cells);

/**
 * CSV text of `rows` (arrays of cells), each line ended by `eol`, the cells parted by `delimiter`:
 * a cell is quoted when it holds the delimiter, a quote (doubled), a line break, or starts or ends
 * with white space, and where `quoted(row, column)` says so; null and undefined are empty, true and
 * false written as words.
 */
export function csvText(rows, { eol = '\n', quoted = () => false, delimiter = ',' } = {}) {
  return stringify(rows, {
    delimiter,
    record_delimiter: eol,
    quoted_match: /[\r\n]|^\s|\s$/,
    cast: {
      boolean: String,
      string: (value, context) =>
        quoted(context.records, context.index) ? { value, quoted: true, quoted_empty: true } : value,
    },
  });
}
