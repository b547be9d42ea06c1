// Code as tokens that survive a disguise: JavaScript, GLSL and WGSL are split into tokens by
// jscpd's tokenizer (@jscpd/tokenizer, Prism grammars), then names, strings and comments are left
// out of what is compared: every identifier is "ID" and every string "S", so renaming variables,
// reflowing lines or rewriting comments changes nothing. Keywords, operators, punctuation and
// numbers are kept. A shader held in a JavaScript string is tokenised as a shader of its own.
import { tokenize } from '@jscpd/tokenizer';
import { shaderFormat } from './sources.js';

const DROPPED = new Set(['empty', 'new_line', 'comment', 'block-comment', 'ignore']);
const NAMES = new Set(['default', 'function', 'functions', 'function-calls', 'function-variable', 'class-name',
  'constant', 'property', 'parameter', 'variable', 'builtin', 'attributes', 'known-class-name', 'maybe-class-name',
  'property-access', 'method', 'literal-property', 'imports', 'exports', 'attr-name', 'tag', 'namespace']);
const STRINGS = new Set(['string', 'template-string', 'template-punctuation', 'char', 'url', 'attr-value']);
const DECLARATIONS = new Set(['var', 'let', 'const']);
// a string long enough to be a shader, and words only shaders have
const SHADER_IN_STRING = /gl_Position|gl_FragColor|void\s+main\s*\(|@vertex|@fragment|@builtin\s*\(|precision\s+(high|medium|low)p/;

/** The comparable form of one Prism token, or null to leave it out. */
export function normalToken(type, value) {
  if (DROPPED.has(type)) return null;
  if (NAMES.has(type)) return 'ID';
  if (STRINGS.has(type)) return 'S';
  if (type === 'regex') return 'R';
  if (type === 'keyword' && DECLARATIONS.has(value)) return 'decl';
  if (type === 'number' || /literal$/.test(type)) return String(Number(value.replace(/[fuih]$/i, '')) || value);
  if (type === 'keyword' || type === 'punctuation' || type === 'operator' || type === 'boolean') return value;
  // anything else Prism names (an interpolation, a GLSL directive, ...): its kind, not its words
  return /^[\s\w]*$/.test(value) ? type : value.trim() || null;
}

/**
 * A source's streams of comparable tokens: [{ format, line, tokens: [{ v, line }] }], where line is
 * the line in the source's file; a shader held in a string is a stream of its own after the first.
 */
export function tokenStreams(source) {
  const main = { format: source.format, line: source.line, tokens: [] };
  const streams = [main];
  let raw;
  try {
    raw = tokenize(source.text, source.format);
  } catch {
    return streams;
  }
  for (const t of raw) {
    const line = source.line + (t.loc?.start?.line ?? 1) - 1;
    if (source.format === 'javascript' && STRINGS.has(t.type) && t.value.length > 60 && SHADER_IN_STRING.test(t.value)) {
      const body = t.value.slice(1, -1);
      streams.push(...tokenStreams({ format: shaderFormat('', body), line, text: body }).filter((s) => s.tokens.length));
      main.tokens.push({ v: 'S', line });
      continue;
    }
    const v = normalToken(t.type, t.value);
    if (v !== null) main.tokens.push({ v, line });
  }
  return streams;
}
