// What a hand-in's parts are written in, read from disk for the similarity check: per part, the
// page's inline scripts (JavaScript, and GLSL in <script type="x-shader/...">), the script files it
// loads, and the shader files (.vert, .frag, .glsl, .wgsl) its code names or its folder holds.
// Only files inside the hand-in are read; a huge, binary or unreadable file is skipped with a note.
import { readFileSync, realpathSync, statSync, readdirSync } from 'node:fs';
import path from 'node:path';

/** Files larger than this are not code a student wrote by hand (a minified library, a data dump). */
export const MAX_FILE_BYTES = 400 * 1024;
const SHADER_EXT = /\.(vert|frag|glsl|vs|fs|wgsl)$/i;

/** The language a shader's text or file name is in: 'wgsl' or 'glsl'. */
export function shaderFormat(nameOrType, text = '') {
  if (/wgsl/i.test(nameOrType) || /@(vertex|fragment|compute)\b|\bfn\s+\w+\s*\(/.test(text)) return 'wgsl';
  return 'glsl';
}

function formatOfFile(file) {
  if (SHADER_EXT.test(file)) return shaderFormat(file);
  if (/\.m?js$/i.test(file)) return 'javascript';
  return null;
}

/** A file's text, or { skip: reason }: outside the hand-in, missing, huge, binary or unreadable. */
function readText(root, file) {
  let real;
  try {
    real = realpathSync(file);
  } catch {
    return { skip: 'missing' };
  }
  const rootReal = realpathSync(root);
  if (real !== rootReal && !real.startsWith(rootReal + path.sep)) return { skip: 'outside the hand-in' };
  try {
    const st = statSync(real);
    if (!st.isFile()) return { skip: 'not a file' };
    if (st.size > MAX_FILE_BYTES) return { skip: `${Math.round(st.size / 1024)} kB, more than ${MAX_FILE_BYTES / 1024} kB` };
    const buf = readFileSync(real);
    if (buf.includes(0)) return { skip: 'binary' };
    return { text: buf.toString('utf8') };
  } catch (err) {
    return { skip: `unreadable (${err.code || err.message})` };
  }
}

const lineOf = (text, index) => text.slice(0, index).split('\n').length;

/** The <script> elements of an HTML page: { attrs, body, line } (line: where the body starts). */
export function scriptsOf(html) {
  const out = [];
  const re = /<script\b([^>]*)>([\s\S]*?)<\/script\s*>/gi;
  for (let m; (m = re.exec(html));) {
    const bodyStart = m.index + m[0].indexOf('>') + 1;
    out.push({ attrs: m[1], body: m[2], line: lineOf(html, bodyStart) });
  }
  return out;
}

const attr = (attrs, name) => {
  const m = new RegExp(`\\b${name}\\s*=\\s*(?:"([^"]*)"|'([^']*)'|([^\\s>]+))`, 'i').exec(attrs);
  return m ? (m[1] ?? m[2] ?? m[3]) : null;
};

/** The shader files a script names in its strings ('shader.wgsl', "./vs.vert"). */
function namedShaderFiles(text) {
  const names = new Set();
  for (const m of text.matchAll(/["'`]([^"'`\s]+\.(?:vert|frag|glsl|vs|fs|wgsl))["'`]/gi)) names.add(m[1]);
  return [...names];
}

/**
 * The sources of one part: [{ file (relative to the hand-in), line (where the text starts in it),
 * format ('javascript' | 'glsl' | 'wgsl'), text }], and notes on what was skipped.
 */
export function partSources(root, page) {
  const sources = [];
  const notes = [];
  const seen = new Set();
  const pageAbs = path.join(root, page);
  const rel = (abs) => path.relative(root, abs).split(path.sep).join('/');
  const addFile = (abs, format) => {
    const key = path.resolve(abs);
    if (seen.has(key)) return null;
    seen.add(key);
    const r = readText(root, key);
    if (r.skip) {
      notes.push(`${rel(key)}: skipped, ${r.skip}`);
      return null;
    }
    sources.push({ file: rel(key), line: 1, format, text: r.text });
    return r.text;
  };
  const html = readText(root, pageAbs);
  if (html.skip) return { sources, notes: [`${page}: skipped, ${html.skip}`] };
  const pageDir = path.dirname(pageAbs);
  const scriptTexts = [];
  for (const s of scriptsOf(html.text)) {
    const type = attr(s.attrs, 'type') || '';
    const src = attr(s.attrs, 'src');
    if (src) {
      if (/^(https?:)?\/\//i.test(src)) continue;
      const abs = path.resolve(pageDir, decodeURI(src.split(/[?#]/)[0]));
      const text = addFile(abs, formatOfFile(abs) || 'javascript');
      if (text !== null) scriptTexts.push({ text, dir: path.dirname(abs) });
    } else if (/shader|glsl|wgsl/i.test(type) || /shader/i.test(attr(s.attrs, 'id') || '')) {
      const format = shaderFormat(type + (attr(s.attrs, 'id') || ''), s.body);
      sources.push({ file: rel(pageAbs), line: s.line, format, text: s.body });
    } else if (!type || /javascript|module|ecmascript/i.test(type)) {
      sources.push({ file: rel(pageAbs), line: s.line, format: 'javascript', text: s.body });
      scriptTexts.push({ text: s.body, dir: pageDir });
    }
  }
  // shader files: those the code names (fetched relative to the page, or to the script), then
  // those beside a page that has its folder to itself
  for (const { text, dir } of scriptTexts) {
    for (const name of namedShaderFiles(text)) {
      const clean = name.replace(/^\.\//, '');
      const abs = [path.resolve(pageDir, clean), path.resolve(dir, clean)].find((f) =>
        statSync(f, { throwIfNoEntry: false }),
      );
      if (abs) addFile(abs, shaderFormat(abs));
    }
  }
  let siblings = [];
  try {
    siblings = readdirSync(pageDir);
  } catch { /* unreadable folder: nothing beside the page */ }
  if (siblings.filter((n) => /\.html?$/i.test(n)).length === 1) {
    for (const n of siblings.sort()) if (SHADER_EXT.test(n)) addFile(path.join(pageDir, n), shaderFormat(n));
  }
  return { sources, notes };
}
