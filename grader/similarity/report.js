// The similarity check in the grader's report: report.json's `similarity`, similar.csv, and a
// section of report.html that the class grid links to (a badge on both hand-ins' rows).
import { PARTS } from '../core/part-names.js';
import { csvText } from '../files/csv.js';
import { esc } from '../files/html.js';

const pct = (x) => `${Math.round(100 * x)}%`;
export const pairId = (p) => `similar-${`${p.a}--${p.b}`.replace(/[^A-Za-z0-9._-]+/g, '_')}`;
export const POINTER = 'A pointer for a person to look at, never a verdict: a pair listed here may have worked together as ' +
  'allowed, started from the same code, or be a coincidence. Code that many hand-ins share (the textbook\'s helpers, ' +
  'the slides\' code) is left out before comparing.';

/** The listed pairs, as report.json keeps them. */
export function similarityJson(r) {
  const listed = r.pairs.filter((p) => p.listed);
  return {
    note: POINTER,
    bound: r.options.bound,
    classSize: r.classSize,
    givenRuns: r.given,
    pairsSharingCode: r.sharing,
    highest: r.pairs[0] ? { a: r.pairs[0].a, b: r.pairs[0].b, score: r.pairs[0].score } : r.highestUnder,
    pairs: listed.map(({ a, b, score, overall, parts, samePictures, fragmentCount, fragments }) => ({
      a,
      b,
      score,
      overall,
      parts,
      samePictures: samePictures || [],
      fragmentCount,
      fragments: fragments.map((f) => ({
        tokens: f.tokens,
        a: { file: f.a.file, parts: f.a.parts, from: f.a.from, to: f.a.to },
        b: { file: f.b.file, parts: f.b.parts, from: f.b.from, to: f.b.to },
      })),
    })),
    notes: r.notes,
  };
}

/** similar.csv: one listed pair a row, its scores per part and overall; the names and the pictures' list always quoted. */
export function similarCsv(r) {
  const head = ['a', 'b', 'score', 'overall', ...PARTS, 'same_pictures', 'fragments'];
  const named = new Set([0, 1, head.indexOf('same_pictures')]);
  return csvText(
    [
      head,
      ...r.pairs
        .filter((p) => p.listed)
        .map((p) => [
          p.a,
          p.b,
          p.score.toFixed(3),
          p.overall.toFixed(3),
          ...PARTS.map((k) => (k in p.parts ? p.parts[k].toFixed(3) : '')),
          (p.samePictures || []).join(' '),
          p.fragmentCount,
        ]),
    ],
    { quoted: (row, column) => row > 0 && named.has(column) },
  );
}

/** The badge on a hand-in's row of the class grid: a link to each listed pair it is in. */
export function similarityBadges(r, name) {
  return r.pairs.filter((p) => p.listed && (p.a === name || p.b === name)).map((p) =>
    ` <a class="similar-badge" href="#${pairId(p)}" title="similar to ${esc(p.a === name ? p.b : p.a)}: ${pct(p.score)}">similar: ${esc(p.a === name ? p.b : p.a)}</a>`).join('');
}

const side = (s) => `<figure class="side"><figcaption>${esc(s.file)} · lines ${s.from}–${s.to} · ${esc(s.parts.join(', '))}</figcaption>` +
  `<pre>${s.lines.map((l) => `<span class="ln">${l.n}</span>${esc(l.text)}`).join('\n')}</pre></figure>`;

function pairHtml(p, link) {
  const parts = PARTS.filter((k) => k in p.parts).map((k) => `${k} ${pct(p.parts[k])}`).join(' · ') || 'no part with enough code of its own';
  return `<section class="pair" id="${pairId(p)}"><h3>${link(p.a)} and ${link(p.b)}: ${pct(p.score)}</h3>` +
    `<p>Overall ${pct(p.overall)} of the code they wrote themselves; per part (compared across parts): ${parts}.</p>` +
    (p.samePictures?.length ? `<p class="same-pictures">The grader's judged pictures are pixel-identical, where the rest of the class differs: ${esc(p.samePictures.join(', '))}.</p>` : '') +
    (p.fragments.length ? `<p>The ${p.fragments.length} longest of ${p.fragmentCount} matching fragments, ${esc(p.a)} on the left:</p>` +
      p.fragments.map((f) => `<div class="fragment">${side(f.a)}${side(f.b)}</div>`).join('') : '') + '</section>';
}

export const SIMILARITY_CSS = `.similar-badge{display:inline-block;margin-left:.3rem;padding:0 .35rem;border-radius:.5rem;background:#5b3fa6;color:#fff;font-size:.72rem;text-decoration:none}
.fragment{display:flex;gap:.6rem;margin:.4rem 0}.fragment .side{flex:1;min-width:0;margin:0}.fragment pre{margin:0;padding:.3rem;background:#f6f6fa;border:1px solid #dde;overflow:auto;font-size:.75rem;max-height:20rem}
.fragment figcaption{font-family:monospace;color:#556;font-size:.75rem}.ln{display:inline-block;width:3em;color:#889;user-select:none}.pointer{background:#eef;padding:.4rem .6rem;border-left:4px solid #5b3fa6}`;

/**
 * The report's section: `link(name)` is the HTML that names a hand-in (a link to its own section).
 */
export function similarityHtml(r, link = esc) {
  const listed = r.pairs.filter((p) => p.listed);
  const highest = r.pairs[0] || r.highestUnder;
  return `<section id="similarity"><h2>Similar hand-ins</h2><p class="pointer">${esc(POINTER)}</p>` +
    `<p>${r.classSize} hand-ins; ${r.sharing} pairs share a run of ${r.options.minTokens} tokens of their own; listed: the pairs at or over ` +
    `${pct(r.options.bound)} in a part or overall, or whose judged pictures are identical. ` +
    `${highest ? `Highest: ${esc(highest.a)} and ${esc(highest.b)}, ${pct(highest.score)}.` : ''}</p>` +
    (listed.length ? `<table class="similar-pairs"><thead><tr><th>pair</th><th>score</th><th>overall</th>${PARTS.map((k) => `<th>${k}</th>`).join('')}<th>same pictures</th></tr></thead><tbody>` +
      listed.map((p) => `<tr><td><a href="#${pairId(p)}">${esc(p.a)} · ${esc(p.b)}</a></td><td class="num">${pct(p.score)}</td><td class="num">${pct(p.overall)}</td>` +
        PARTS.map((k) => `<td class="num">${k in p.parts ? pct(p.parts[k]) : ''}</td>`).join('') + `<td>${esc((p.samePictures || []).join(', '))}</td></tr>`).join('') +
      '</tbody></table>' + listed.map((p) => pairHtml(p, link)).join('') : '<p>No pair is listed.</p>') +
    (r.notes.length ? `<details><summary>Files left out</summary><ul>${r.notes.map((n) => `<li>${esc(n)}</li>`).join('')}</ul></details>` : '') + '</section>';
}

/** A report.html of its own when nothing was graded (--similarity-only): a grid of names, then the section. */
export function similarityPage(r, names) {
  const rows = names.map((n) => `<tr data-name="${esc(n)}"><th scope="row">${esc(n)}${similarityBadges(r, n)}</th></tr>`).join('\n');
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Similar hand-ins</title><style>body{font-family:system-ui,sans-serif;margin:1rem 2rem;color:#1d2330}
table{border-collapse:collapse}td,th{border:1px solid #ccd;padding:.2rem .4rem;text-align:left}.num{text-align:right}${SIMILARITY_CSS}</style></head><body>
<h1>Similar hand-ins</h1><p>Nothing was graded in this folder (--similarity-only): the class, then the pairs.</p>
<table id="grid"><thead><tr><th>submission</th></tr></thead><tbody>
${rows}
</tbody></table>
${similarityHtml(r)}</body></html>`;
}
