// Puts a call to __checkLoop() (check/frame-watch.js) at the top of every loop body of a part's
// JavaScript, so that a loop which never returns can be stopped: the frame shares the check
// page's thread, and nothing else can interrupt it. Parsed with acorn; code that does not parse
// is served as it is (the browser then reports the syntax error as it would anyway).
// Guarded code never depends on the frame's script having run first: it begins with standIn(seconds),
// which defines a plain __checkLoop where there is none yet (code that ran before the frame's
// script, a worker), so that the call is never a ReferenceError and a loop is still stopped;
// frame-watch.js replaces it, and says that the page ran before the self-check's script.
import { parse } from '../node_modules/acorn/dist/acorn.mjs';
import { MS_PER_SECOND } from '../grader/core/units.js';

const LOOPS = new Set(['WhileStatement', 'DoWhileStatement', 'ForStatement', 'ForInStatement', 'ForOfStatement']);
const CALL = '__checkLoop();';
/**
 * A statement that defines a stand-in __checkLoop (the same rule as frame-watch.js's, on the real
 * clock) where there is none: a loop that runs `seconds` (the rubric's loadSeconds) without returning is stopped.
 */
export const standIn = (seconds) => 'typeof __checkLoop=="function"||Object.defineProperty(globalThis,"__checkLoop",{configurable:true,value:' +
  'function(n,t,now){return function f(){if(f.hung)throw new Error(f.hung);if(++n&1023)return;var s=now();' +
  'if(t<0){t=s;setTimeout(function(){t=-1})}else if(s-t>' + MS_PER_SECOND * seconds + ')' +
  'throw new Error(f.hung="a loop ran for "+Math.round((s-t)/1000)+" s without returning (stopped by the self-check)")}}' +
  '(0,-1,performance.now.bind(performance))});';

/** Every loop's body in an acorn AST (a plain walk: every object-valued property). */
function loopBodies(node, out = []) {
  if (!node || typeof node.type !== 'string') return out;
  if (LOOPS.has(node.type)) out.push(node.body);
  for (const key of Object.keys(node)) {
    const v = node[key];
    if (Array.isArray(v)) for (const c of v) loopBodies(c, out);
    else if (v && typeof v === 'object' && typeof v.type === 'string') loopBodies(v, out);
  }
  return out;
}

/** `source` with the guard in every loop (stopped after `seconds`); unchanged when it has no loop or does not parse. */
export function guardLoops(source, { module = false, seconds }) {
  if (!/\b(for|while|do)\b/.test(source)) return source;
  let ast;
  for (const sourceType of module ? ['module', 'script'] : ['script', 'module']) {
    try {
      ast = parse(source, { ecmaVersion: 'latest', sourceType, allowHashBang: true, allowReturnOutsideFunction: true });
      break;
    } catch {
      ast = null;
    }
  }
  if (!ast) return source;
  // insertions as [position, text], applied from the end so earlier positions stay valid
  const edits = [];
  for (const body of loopBodies(ast)) {
    if (body.type === 'BlockStatement') edits.push([body.start + 1, CALL]);
    else edits.push([body.start, `{${CALL}`], [body.end, '}']);
  }
  if (!edits.length) return source;
  // the stand-in first, after the directives ('use strict' must stay first to count) and a hashbang
  edits.push([ast.body.find((s) => !s.directive).start, standIn(seconds)]);
  edits.sort((a, b) => b[0] - a[0]);
  let out = source;
  for (const [at, text] of edits) out = out.slice(0, at) + text + out.slice(at);
  return out;
}

const SCRIPT = /(<script\b([^>]*)>)([\s\S]*?)(<\/script\s*>)/gi;
const JS_TYPE = /^\s*$|^\s*(module|(text|application)\/(java|ecma)script)\s*$/i;

/** An HTML page with the guard (stopped after `seconds`) in each of its inline JavaScript scripts (shader scripts untouched). */
export function guardInlineScripts(html, seconds) {
  return html.replace(SCRIPT, (all, open, attrs, body, close) => {
    const type = /\btype\s*=\s*["']?([^"'\s>]*)/i.exec(attrs);
    if (/\bsrc\s*=/i.test(attrs) || (type && !JS_TYPE.test(type[1]))) return all;
    return open + guardLoops(body, { module: !!type && /module/i.test(type[1]), seconds }) + close;
  });
}
