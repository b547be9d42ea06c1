// An eslint rule: a line of code within `code` characters once its strings, template text, regular
// expressions and comments are taken out. eslint's max-len with ignoreStrings passes a whole line
// that holds any string, so a long statement with one short string in it went unseen; the
// sentences a reason says stay whole, the code around them is held to the bound.

/** Characters of `line` (1-based) that `tok` covers, where tok is on one line or spans it. */
function covered(tok, line, lines) {
  const { start, end } = tok.loc;
  if (line < start.line || line > end.line) return 0;
  const from = line === start.line ? start.column : 0;
  const to = line === end.line ? end.column : lines[line - 1].length;
  return Math.max(0, to - from);
}

const TEXT = new Set(['String', 'Template', 'RegularExpression']);

export default {
  meta: {
    type: 'layout',
    docs: { description: 'a line of code within the bound, its strings, template text, regular expressions and comments aside' },
    schema: [{ type: 'object', properties: { code: { type: 'integer', minimum: 1 } }, additionalProperties: false }],
    messages: { long: 'This line has {{length}} characters of code (strings and comments aside). Maximum allowed is {{code}}.' },
  },
  create(context) {
    const code = (context.options[0] && context.options[0].code) || 120;
    const source = context.sourceCode;
    return {
      'Program:exit'() {
        const lines = source.lines;
        const taken = new Array(lines.length + 1).fill(0);
        for (const t of [...source.ast.tokens.filter((x) => TEXT.has(x.type)), ...source.getAllComments()]) {
          for (let l = t.loc.start.line; l <= t.loc.end.line; l++) taken[l] += covered(t, l, lines);
        }
        lines.forEach((text, i) => {
          const length = text.length - taken[i + 1];
          if (length > code) context.report({ loc: { line: i + 1, column: 0 }, messageId: 'long', data: { length, code } });
        });
      },
    };
  },
};
