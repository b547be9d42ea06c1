// tools/eslint/code-length.js: a line of code within the bound once its strings, template text,
// regular expressions and comments are taken out; a long sentence in a string passes, a long
// statement holding one short string does not (eslint's max-len with ignoreStrings passed it).
import { describe, it } from 'node:test';
import { RuleTester } from 'eslint';
import codeLength from '../../tools/eslint/code-length.js';

RuleTester.describe = describe;
RuleTester.it = it;
RuleTester.itOnly = it.only;

const tester = new RuleTester({ languageOptions: { ecmaVersion: 'latest', sourceType: 'module' } });
const long = (n) => 'x'.repeat(n);

tester.run('code-length', codeLength, {
  valid: [
    { code: `const a = 1;`, options: [{ code: 20 }] },
    // a long sentence in a string, a template or a comment is not code
    { code: `say('${long(200)}');`, options: [{ code: 20 }] },
    { code: 'say(`' + long(200) + '${a}' + long(100) + '`);', options: [{ code: 20 }] },
    { code: `f(); // ${long(200)}`, options: [{ code: 20 }] },
    { code: `const r = /${long(200)}/;`, options: [{ code: 20 }] },
  ],
  invalid: [
    // a long statement with one short string in it
    { code: `const ${long(30)} = f('a');`, options: [{ code: 20 }], errors: [{ messageId: 'long' }] },
    // a template's expressions are code
    { code: 'say(`a${' + long(30) + '}b`);', options: [{ code: 20 }], errors: [{ messageId: 'long' }] },
  ],
});
