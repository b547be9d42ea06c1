// The given code of a class, found from the class itself (as MOSS's base files and Dolos's
// fingerprint-count limit do, without the teacher listing them): a run of K tokens that occurs in
// a large share of the hand-ins is the textbook's helpers, the slides' code or an idiom everyone
// writes, whatever its file is called and wherever it sits, and it counts for no pair.

/** A 32-bit hash of each token's text (FNV-1a), so that k-grams hash in one pass. */
function tokenHashes(tokens) {
  return tokens.map(({ v }) => {
    let h = 0x811c9dc5;
    for (let i = 0; i < v.length; i++) h = Math.imul(h ^ v.charCodeAt(i), 0x01000193);
    return h >>> 0;
  });
}

/** The keys of every K-token run of a stream (two 32-bit polynomial hashes), at each start. */
export function kgramKeys(tokens, k) {
  const h = tokenHashes(tokens);
  const keys = [];
  for (let i = 0; i + k <= h.length; i++) {
    let a = 0;
    let b = 7;
    for (let j = i; j < i + k; j++) {
      a = (Math.imul(a, 31) + h[j]) >>> 0;
      b = (Math.imul(b, 1000003) ^ h[j]) >>> 0;
    }
    keys.push(`${a.toString(36)}.${b.toString(36)}`);
  }
  return keys;
}

/** How many hand-ins a run must be in to be given: `share` of the class, and never fewer than 3. */
export function givenCount(classSize, share) {
  return Math.max(3, Math.ceil(share * classSize));
}

/**
 * Marks the given tokens of every stream of a class: `submissions` is [{ streams: [{ tokens }] }];
 * each stream gets `given` (a Uint8Array, 1 where the token is inside a run of k tokens found in
 * at least givenCount(class size, share) hand-ins) and `keys` (its k-gram keys). Returns the number
 * of runs taken as given.
 */
export function markGiven(submissions, { k, share }) {
  const counts = new Map();
  for (const s of submissions) {
    const mine = new Set();
    for (const st of s.streams) {
      st.keys = kgramKeys(st.tokens, k);
      for (const key of st.keys) mine.add(key);
    }
    for (const key of mine) counts.set(key, (counts.get(key) || 0) + 1);
  }
  const bound = givenCount(submissions.length, share);
  let given = 0;
  for (const [, n] of counts) if (n >= bound) given++;
  for (const s of submissions) {
    for (const st of s.streams) {
      st.given = new Uint8Array(st.tokens.length);
      st.keys.forEach((key, i) => {
        if (counts.get(key) >= bound) st.given.fill(1, i, i + k);
      });
    }
  }
  return given;
}
