// The fragments two hand-ins share, found by jscpd's clone detector (@jscpd/core: Rabin-Karp over
// runs of minTokens tokens, grown while they match) on the tokens of template.js that are not given.
// Every stream of one hand-in goes into the detector's store first, then every stream of the other,
// so a clone is found whichever parts the two come from (one's P4 against the other's P5).
import { Detector } from '@jscpd/core';
import { TokensMap } from '@jscpd/tokenizer';

// TokensMap hashes every token and every run; 20 characters a hash, as jscpd's own MD5 gives
function fastHash(text) {
  let a = 0x811c9dc5;
  let b = 0x9747b28c;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    a = Math.imul(a ^ c, 0x01000193);
    b = Math.imul(b ^ c, 0x5bd1e995) ^ (b >>> 15);
  }
  const hex = (x) => (x >>> 0).toString(16).padStart(8, '0');
  return (hex(a) + hex(b) + hex(a ^ b)).slice(0, 20);
}

// jscpd's MemoryStore, without an Error (and its stack) made for every token not found
const NOT_FOUND = Promise.reject(new Error('not found'));
NOT_FOUND.catch(() => {});
class QuickStore {
  values = new Map();
  namespace(name) {
    if (!this.values.has(name)) this.values.set(name, new Map());
    this.current = this.values.get(name);
  }
  get(key) {
    const v = this.current.get(key);
    return v === undefined ? NOT_FOUND : Promise.resolve(v);
  }
  set(key, value) {
    this.current.set(key, value);
    return Promise.resolve(value);
  }
  close() {
    this.values.clear();
  }
}

/**
 * A stream's own tokens, as jscpd tokens: given runs are left out and leave a gap no other
 * stream has, so no clone spans them. `origin[i]` is the stream token behind own token i (-1 for a gap), `index[j]` the own token of stream token j (-1 if given).
 */
export function ownTokens(stream, id) {
  const tokens = [];
  const origin = [];
  const index = new Int32Array(stream.tokens.length).fill(-1);
  let gap = false;
  stream.tokens.forEach((t, i) => {
    if (stream.given[i]) {
      gap = true;
      return;
    }
    index[i] = tokens.length + (gap && tokens.length ? 1 : 0);
    if (gap && tokens.length) tokens.push(jscpdToken(`\u0000${id}:${i}`, t.line, tokens.length, stream.format)), origin.push(-1);
    gap = false;
    tokens.push(jscpdToken(t.v, t.line, tokens.length, stream.format));
    origin.push(i);
  });
  return { tokens, origin, index };
}

function jscpdToken(value, line, index, format) {
  const at = { line, column: 1, position: index };
  return { type: 't', value, length: 1, format, range: [index, index + 1], loc: { start: at, end: at } };
}

/**
 * The clones between hand-ins X and Y, seen from X: [{ x: { stream, from, to }, y: { stream, from, to } }]
 * with own-token index ranges (to exclusive). Each side is [{ id, own, format }] of its streams, only
 * those that share a run with the other side (the rest can hold no clone).
 */
export async function clonesOf(X, Y, minTokens) {
  const options = { minTokens, minLines: 1, maxLines: 100000, hashFunction: fastHash };
  const maps = new Map();
  for (const s of [...Y, ...X]) if (s.own.tokens.length > minTokens) maps.set(s.id, s);
  const tokenizer = {
    generateMaps(id) {
      const s = maps.get(id);
      s.map ??= new TokensMap(id, '', s.own.tokens, s.format, options);
      s.map.position = 0;
      return [s.map];
    },
  };
  const detector = new Detector(tokenizer, new QuickStore(), [], options);
  const inX = new Set(X.map((s) => s.id));
  const found = [];
  for (const s of [...Y, ...X]) {
    if (!maps.has(s.id)) continue;
    for (const c of await detector.detect(s.id, '', s.format)) {
      const a = c.duplicationA;
      const b = c.duplicationB;
      if (inX.has(a.sourceId) && !inX.has(b.sourceId)) {
        found.push({
          x: { stream: a.sourceId, from: a.range[0], to: a.range[1] },
          y: { stream: b.sourceId, from: b.range[0], to: b.range[1] },
        });
      }
    }
  }
  return found;
}
