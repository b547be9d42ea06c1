// ESLint (flat config): the recommended rules on every JS file; browser globals for the site,
// Node globals for tools, tests and configs.
import js from '@eslint/js';
import globals from 'globals';
import codeLength from './tools/eslint/code-length.js';

// the grader owns what it runs (its browser launchers included): nothing in grader/ or check/ comes from tools/
// the grader's core runs in Node and in the browser alike: its own modules only
const CORE_ONLY = { regex: '^(node:|[a-z@])', message: 'the grader\'s core imports only its own modules (no Node, no packages)' };
const NOT_TOOLS = { regex: '(^|/)tools/', message: 'the check page and the grader import the grader from grader/, never from tools/' };
const NOT_CHECK = { regex: '(^|/)check/', message: 'the grader takes what it shares with the check page from grader/core/, never from check/' };

export default [
  { ignores: ['node_modules/', 'out/', 'test-results/', 'playwright-report/', 'tests/fixtures/handins/', 'tests/fixtures/student/', 'tests/fixtures/similar/', 'tests/fixtures/artifacts/', 'tests/fixtures/check/', 'tests/fixtures/firefox/', 'tests/fixtures/heavy/'] },
  js.configs.recommended,
  {
    languageOptions: { ecmaVersion: 2023, sourceType: 'module' },
    rules: { 'no-unused-vars': ['error', { argsIgnorePattern: '^_' }] },
  },
  { ignores: ['grader/core/**'], languageOptions: { globals: { ...globals.browser } } },
  {
    files: ['tools/**', 'tests/**', '*.config.js'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
  { files: ['common/boot.js'], languageOptions: { sourceType: 'script' } },
  {
    files: ['grader/node/**', 'grader/files/**', 'grader/similarity/**'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
  {
    files: ['grader/class/**'],
    languageOptions: { globals: { ...globals.browser } },
  },
  // the check page is a site page, and the grader owns what it runs (its browser launchers
  // included): both take the grader from grader/, never from the command-line tools
  {
    files: ['check/**', 'grader/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS] }] },
  },
  // no arrow sideways or up: the command (grader/node/) and the similarity report
  // (grader/similarity/) share what lies below both (grader/files/: parts on disk, the out folder's
  // layout, CSV; grader/core/), never each other's modules one way (similarity never imports node/);
  // the check page and the grader share only core/
  {
    files: ['grader/files/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, { regex: '(^|/)(node|similarity|check)/', message: 'grader/files/ lies below the command and the similarity report: it imports only grader/core/ and packages' }] }] },
  },
  {
    files: ['grader/similarity/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, { regex: '(^|/)(node|check)/', message: 'the similarity report takes what it shares with the command from grader/files/ or grader/core/, never from grader/node/' }] }] },
  },
  {
    files: ['grader/node/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, NOT_CHECK] }] },
  },
  // a class's outputs (grader/class/: the report, the grade files, the feedback pages and zip, the
  // course sites' adapters) take rows and give files, in Node and in a page alike: no Node module,
  // nothing of the command's (tests/unit/class-pure.test.js follows their imports all the way down)
  {
    files: ['grader/class/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, NOT_CHECK, { regex: '^node:|(^|/)node/', message: 'grader/class/ takes rows and gives files, in Node and in a page alike: no Node module, nothing from grader/node/' }] }] },
  },
  // grader/node/ in rooms: cli/ (the command: options, help, progress, the teacher's loop) above
  // run/ (the browsers, the workers, serving a hand-in), sites/ (the course sites' downloads and
  // import files) and report/ (the report, the feedback pages, the item analysis), which never
  // import each other or the command: what two of them share lives below them (grader/files/)
  ...['run', 'sites', 'report'].map((room) => ({
    files: [`grader/node/${room}/**`],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, NOT_CHECK, { regex: `(^|/)(${['cli', 'run', 'sites', 'report'].filter((r) => r !== room).join('|')})/`,
      message: `grader/node/${room}/ imports neither the command (cli/) nor another room: put what they share below them, in grader/files/ or grader/core/` }] }] },
  })),
  {
    files: ['check/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, { regex: '(^|/)grader/(node|similarity|files)/', message: 'the check page takes the grader from grader/core/ only' }] }] },
  },
  // the class page grades in the browser with the check page's runner and the grader's modules
  // that need no Node (grader/core/, grader/class/)
  {
    files: ['grade/**'],
    rules: { 'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, { regex: '^node:|(^|/)grader/(node|similarity)/', message: 'the class page runs in a browser: grader/core/, grader/class/ and check/, no Node' }] }] },
  },
  // the grader's core runs in Node (npm run grade) and in the browser (the check page) alike: no
  // Node module, no DOM; only the language and the timers both have
  {
    files: ['grader/core/**'],
    languageOptions: { globals: { ...globals.es2021, URL: 'readonly', URLSearchParams: 'readonly', setTimeout: 'readonly', clearTimeout: 'readonly', queueMicrotask: 'readonly' } },
    rules: {
      'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, CORE_ONLY] }],
    },
  },
  // a line of code read without scrolling (the sentences a reason says, in strings, aside); a
  // statement broken over lines keeps its branches in braces
  {
    files: ['grader/**', 'check/**', 'grade/**'],
    rules: {
      'max-len': ['error', { code: 120, ignoreStrings: true, ignoreTemplateLiterals: true, ignoreRegExpLiterals: true, ignoreComments: true, ignoreUrls: true }],
      curly: ['error', 'multi-line'],
    },
  },
  // in the grader and the check page, every line of code within 120 characters, however short a
  // string it holds (max-len's ignoreStrings passes the whole line): tools/eslint/code-length.js
  {
    files: ['grader/**', 'check/**', 'grade/**'],
    plugins: { local: { rules: { 'code-length': codeLength } } },
    rules: { 'local/code-length': ['error', { code: 120 }] },
  },
  // a module a maintainer reads in one sitting, a function on one screen; the functions
  // still to split say so where they are (eslint-disable-next-line, with why)
  {
    files: ['grader/**', 'check/**', 'grade/**'],
    rules: {
      'max-lines': ['error', { max: 300, skipBlankLines: true, skipComments: true }],
      'max-lines-per-function': ['error', { max: 80, skipBlankLines: true, skipComments: true }],
    },
  },
  // gather, then audit (Lighthouse): an audit is a pure function of the artifact and never reaches
  // into a gatherer; what both need lives in measure/ (or the modules beside audit.js)
  {
    files: ['grader/core/audits/**'],
    rules: {
      'no-restricted-imports': ['error', { patterns: [NOT_TOOLS, CORE_ONLY, { regex: '(^|/)gather/', message: 'an audit imports nothing from core/gather/: put what both need in measure/ or beside audit.js' }] }],
    },
  },
];
