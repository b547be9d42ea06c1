// Similar hand-ins across a class: every pair of hand-ins whose own code (not the given code every
// hand-in shares) is more alike than a bound, with a score per part and overall and the matching
// fragments. A pointer for a person to look at, never a verdict.
import { partSources } from './sources.js';
import { tokenStreams } from './tokens.js';
import { markGiven } from './template.js';
import { ownTokens, clonesOf } from './match.js';
import { PARTS } from '../files/parts.js';

export const DEFAULTS = {
  bound: 0.5, // a pair is listed when a part's score or the overall score reaches it
  minTokens: 30, // the shortest run of tokens that counts as a match (and the template rule's run)
  share: 0.3, // a run in this share of the class (and in 3 hand-ins at least) is given code
  minPartTokens: 80, // a part with less own code than this has no score of its own (too little to say)
  maxFragments: 12, // fragments shown per pair
};

/** One hand-in's streams of tokens, each with the file it is in and the parts that load it. */
export function readSubmission({ name, root }, findParts) {
  const byKey = new Map();
  const notes = [];
  const parts = findParts(root);
  for (const part of PARTS) {
    if (!parts[part]) continue;
    const r = partSources(root, parts[part]);
    notes.push(...r.notes);
    for (const source of r.sources) {
      const key = `${source.file}:${source.line}`;
      if (byKey.has(key)) {
        for (const st of byKey.get(key)) st.parts.add(part);
        continue;
      }
      byKey.set(
        key,
        tokenStreams(source)
          .filter((st) => st.tokens.length)
          .map((st) => ({ ...st, file: source.file, source, parts: new Set([part]) })),
      );
    }
  }
  const streams = [...byKey.values()].flat();
  streams.forEach((st, i) => { st.id = `${name}#${i}`; });
  return { name, streams, notes: [...new Set(notes)] };
}

const ownCount = (st) => st.own.origin.filter((o) => o >= 0).length;

/** The scores of a pair from what of each side the other covers: per part and overall. */
function scores(X, Y, covered, minPartTokens) {
  const tally = (s) => {
    const perPart = Object.fromEntries(PARTS.map((p) => [p, { own: 0, covered: 0 }]));
    const all = { own: 0, covered: 0 };
    for (const st of s.streams) {
      const own = ownCount(st);
      const cov = covered.get(st.id)?.size || 0;
      all.own += own;
      all.covered += cov;
      for (const p of st.parts) {
        perPart[p].own += own;
        perPart[p].covered += cov;
      }
    }
    return { perPart, all };
  };
  const x = tally(X);
  const y = tally(Y);
  const ratio = (a, b) => (a.own + b.own ? (a.covered + b.covered) / (a.own + b.own) : 0);
  const parts = {};
  for (const p of PARTS) {
    if (x.perPart[p].own >= minPartTokens && y.perPart[p].own >= minPartTokens) {
      parts[p] = ratio(x.perPart[p], y.perPart[p]);
    }
  }
  // a part copied into one hand-in's other part: its own share covered, whichever part it sits in
  for (const [s, t] of [[x, X], [y, Y]]) {
    for (const p of PARTS) {
      const own = s.perPart[p];
      if (own.own >= minPartTokens && !(p in parts) && t.streams.some((st) => st.parts.has(p))) {
        parts[p] = own.covered / own.own;
      }
    }
  }
  return { overall: ratio(x.all, y.all), parts, ownTokens: [x.all.own, y.all.own] };
}

/** The text of lines [from, to] of a stream's file, numbered. */
function linesOf(st, from, to) {
  const lines = st.source.text.split('\n');
  const out = [];
  for (let l = from; l <= to; l++) out.push({ n: l, text: lines[l - st.source.line] ?? '' });
  return out;
}

function fragmentOf(stX, stY, c) {
  // jscpd's run ends a token past the match, which may be the gap after it
  const line = (st, i) => {
    while (i > 0 && !(st.own.origin[i] >= 0)) i--;
    return st.tokens[st.own.origin[i]]?.line;
  };
  const side = (st, r) => {
    const from = line(st, r.from);
    const to = line(st, r.to - 1);
    return { file: st.file, parts: [...st.parts], from, to, lines: linesOf(st, from, to) };
  };
  return { tokens: c.x.to - c.x.from, a: side(stX, c.x), b: side(stY, c.y) };
}

/** Each side's own tokens inside a run the other side has too: a quick bound on what jscpd can find. */
function sharedRuns(X, Y, keysX, keysY) {
  const covered = new Map();
  for (const [S, keys] of [[X, keysY], [Y, keysX]]) {
    for (const st of S.streams) {
      const k = st.tokens.length - st.keys.length + 1;
      const set = new Set();
      st.keys.forEach((key, i) => {
        if (!st.ownKeys.has(key) || !keys.has(key)) return;
        for (let j = i; j < i + k; j++) set.add(st.own.index[j]);
      });
      if (set.size) covered.set(st.id, set);
    }
  }
  return covered;
}

/** Compares one pair both ways; the covered own tokens of each side, and the fragments seen from X. */
async function comparePair(X, Y, keysX, keysY, o) {
  const sharing = (s, keys) => s.streams.filter((st) => [...st.ownKeys].some((k) => keys.has(k)));
  const sides = new Map([[X, sharing(X, keysY)], [Y, sharing(Y, keysX)]]);
  const covered = new Map();
  const fragments = [];
  const streams = new Map([...X.streams, ...Y.streams].map((st) => [st.id, st]));
  for (const [A, B] of [[X, Y], [Y, X]]) {
    for (const c of await clonesOf(sides.get(A), sides.get(B), o.minTokens)) {
      const st = streams.get(c.x.stream);
      if (!covered.has(st.id)) covered.set(st.id, new Set());
      for (let i = c.x.from; i < c.x.to; i++) if (st.own.origin[i] >= 0) covered.get(st.id).add(i);
      if (A === X) fragments.push(fragmentOf(st, streams.get(c.y.stream), c));
    }
  }
  fragments.sort((a, b) => b.tokens - a.tokens);
  return {
    ...scores(X, Y, covered, o.minPartTokens),
    fragments: fragments.slice(0, o.maxFragments),
    fragmentCount: fragments.length,
  };
}

/** The own k-gram keys of a hand-in: runs of minTokens tokens none of which is given. */
function ownKeys(s) {
  const keys = new Set();
  for (const st of s.streams) {
    st.ownKeys = new Set();
    const k = st.tokens.length - st.keys.length + 1;
    const givenBefore = [0];
    st.given.forEach((g, i) => givenBefore.push(givenBefore[i] + g));
    st.keys.forEach((key, i) => {
      if (givenBefore[i + k] === givenBefore[i]) keys.add(key), st.ownKeys.add(key);
    });
  }
  return keys;
}

/**
 * Compares a class: `submissions` [{ name, root }], `findParts(root)` → { WP04Pn: page }.
 * Returns { options, given, pairs (sorted, highest first, with `listed` when at or over the bound), notes }.
 * `progress(done, total)` is called as pairs are compared.
 */
export async function compareClass(submissions, findParts, options = {}, progress = () => {}) {
  const o = { ...DEFAULTS, ...Object.fromEntries(Object.entries(options).filter(([, v]) => v !== undefined)) };
  const subs = submissions.map((s) => readSubmission(s, findParts));
  const given = markGiven(subs, { k: o.minTokens, share: o.share });
  for (const s of subs) for (const st of s.streams) st.own = ownTokens(st, st.id);
  const keys = subs.map(ownKeys);
  const candidates = [];
  for (let i = 0; i < subs.length; i++) {
    for (let j = i + 1; j < subs.length; j++) {
      const [small, big] = keys[i].size < keys[j].size ? [keys[i], keys[j]] : [keys[j], keys[i]];
      if ([...small].some((k) => big.has(k))) candidates.push([i, j]);
    }
  }
  const pairs = [];
  const best = (r) => Math.max(r.overall, ...Object.values(r.parts));
  let highestUnder = null;
  for (const [n, [i, j]] of candidates.entries()) {
    const [X, Y] = [subs[i], subs[j]];
    // the runs both have bound the score from above: a pair far under the bound is not compared further
    const quick = scores(X, Y, sharedRuns(X, Y, keys[i], keys[j]), o.minPartTokens);
    if (best(quick) < o.bound / 2) {
      if (!highestUnder || best(quick) > highestUnder.score) {
        highestUnder = { a: X.name, b: Y.name, score: best(quick) };
      }
    } else {
      const r = await comparePair(X, Y, keys[i], keys[j], o);
      pairs.push({ a: X.name, b: Y.name, score: best(r), listed: best(r) >= o.bound, ...r });
    }
    progress(n + 1, candidates.length);
  }
  pairs.sort((p, q) => q.score - p.score);
  return {
    options: o,
    classSize: subs.length,
    given,
    compared: pairs.length,
    sharing: candidates.length,
    highestUnder,
    pairs,
    notes: subs.flatMap((s) => s.notes.map((n) => `${s.name}: ${n}`)),
  };
}
