// Finding a page's controls as a teacher does: by what they do to the picture. A control's
// names (id, name, label, the words beside it) only order the trials, break ties (which
// material slider is kd) and name it in the report. Plain data: the gatherers (core/gather/) drive
// the page and take the trials' pictures; these functions read them.
import { silhouetteChange, pictureChange, outlineFlips } from './measure/change.js';

/** The characters of a control's words kept to name it in the report. */
const WORDS_KEPT = 60;

const re = (s) => new RegExp(s, 'i');
/** An id or name read as words too: kdSlider → kd Slider, slider_kd → slider kd. */
const words = (s) => s && s.replace(/([a-z])([A-Z])/g, '$1 $2').replace(/[_-]+/g, ' ');
/** What a control carries to be read by: id, name, visible text and labels. */
export function labelsOf(c) {
  return [c.id, words(c.id), c.name, words(c.name), c.text].filter(Boolean);
}
/** How a control is named in the report: its type and the words it carries. */
export function describe(c) {
  const said = [c.text, c.id && `#${c.id}`, c.name && c.name !== c.id && `name=${c.name}`].filter(Boolean).join(' ').slice(0, WORDS_KEPT);
  return `${c.type} "${said}"`;
}

export const CLICKABLE = ['button', 'submit', 'a', 'div', 'span', 'image'];
export const isClickable = (c) => CLICKABLE.includes(c.type) || c.type === 'checkbox';
export const isValued = (c) => ['range', 'number', 'select'].includes(c.type);

/** Does the control's name say `role` (a rubric pattern key)? */
export function named(c, role, patterns) {
  return namedIn(labelsOf(c), role, patterns);
}

/** Does one of `labels` (texts) name `role` (the rubric's pattern for it)? */
export function namedIn(labels, role, patterns) {
  return labels.some((t) => re(patterns[role]).test(t));
}

/** Do `labels` name `role` and not `other` (words beside a thing name it too, so one named for both is neither)? */
export const namedOnlyIn = (labels, role, other, patterns) =>
  namedIn(labels, role, patterns) && !namedIn(labels, other, patterns);

/** Does the control's name say `role` and not `other`? */
export const namedOnly = (c, role, other, patterns) => namedOnlyIn(labelsOf(c), role, other, patterns);

/**
 * The role a control's names suggest, or null: the clickables' (coarsen, subdivide, orbit,
 * depth, cull, clockwise), the value controls' (levelSlider, kd, ks, s, Le, La). "Decrement
 * subdivision" names the level it lowers: coarsen is read before subdivide.
 */
export function nameRole(c, patterns) {
  const is = (role) => named(c, role, patterns);
  if (isClickable(c) && c.type !== 'checkbox') {
    for (const role of ['coarsen', 'subdivide', 'orbit', 'depth', 'cull', 'clockwise']) if (is(role)) return role;
  } else if (c.type === 'checkbox') {
    for (const role of ['orbit', 'depth', 'clockwise', 'cull']) if (is(role)) return role;
  } else if (isValued(c)) {
    for (const role of ['levelSlider', 'kd', 'ks', 's', 'Le', 'La']) if (is(role)) return role;
  }
  return null;
}

/**
 * The effect of one action on the picture, from the picture before, just after, and a moment
 * later (analyses from judge.analyse): 'finer' or 'coarser' (the silhouette gets rounder or
 * coarser: the level), 'starts' or 'stops' (the picture starts or stops moving: the orbit),
 * 'shading' (the picture changes inside an unchanged silhouette: material, light or the faces
 * drawn), 'blank' (nothing drawn after it), 'none'.
 */
export function effectOf({ before, after, later, wasMoving }, thresholds) {
  const moving = pictureChange(after.img, later.img, thresholds) > thresholds.pictureMoves;
  if (!wasMoving && moving) return 'starts';
  if (wasMoving && !moving) return 'stops';
  if (wasMoving) return 'none'; // whatever else it did cannot be told while the picture moves
  if (after.an.blank && !before.an.blank) return 'blank';
  if (before.an.blank || after.an.blank) return 'none';
  const sil = silhouetteChange(before.an, after.an);
  if (sil > thresholds.silhouetteSettled) {
    // a finer mesh inscribed in the sphere covers more of its disc, and its outline is rounder
    const rounder = before.an.roundness - after.an.roundness,
      larger = (after.an.area - before.an.area) / before.an.area;
    if (Math.abs(larger) > thresholds.levelAreaChange) return larger > 0 ? 'finer' : 'coarser';
    return rounder > 0 ? 'finer' : 'coarser';
  }
  // at a high level: a few outline pixels flip, all of them at the outline, and the area moves with them
  const f = outlineFlips(before.an, after.an, thresholds);
  if (
    f &&
    f.flips >= thresholds.outlineFlips &&
    f.atOutline >= thresholds.outlineFlipsAtEdge * f.flips &&
    Math.abs(f.area) >= Math.max(thresholds.outlineAreaLeast, thresholds.outlineAreaPerFlip * f.flips)
  ) {
    return f.area > 0 ? 'finer' : 'coarser';
  }
  return pictureChange(before.img, after.img, thresholds) > thresholds.pictureChanged ? 'shading' : 'none';
}

/**
 * The order a teacher tries controls in for a role: those named for it first, then those named
 * for nothing, then the rest (a name can be wrong: "makeSquare" coarsens a sphere).
 */
export function trialOrder(controls, role, patterns, taken = new Set()) {
  const free = controls.filter((c) => !taken.has(c.index));
  const rank = (c) => (named(c, role, patterns) ? 0 : nameRole(c, patterns) === null ? 1 : 2);
  return free.map((c, k) => [rank(c), k, c]).sort((a, b) => a[0] - b[0] || a[1] - b[1]).map((x) => x[2]);
}

// ---- the sliders of one parameter ----
const FAMILIES = [['r', 'g', 'b'], ['red', 'green', 'blue'], ['x', 'y', 'z'], ['0', '1', '2']];
const CHANNEL = new Map(FAMILIES.flatMap((f, k) => f.map((ch) => [ch, k])));

/**
 * A name split into the parameter it names and a colour or vector channel: "ksR", "ks_r", "kd-red",
 * "lightX", "ks0", "k_s (g)", "Specular B:" → { stem, channel, family }; null where it names none.
 */
export function channelOf(s) {
  if (!s) return null;
  const t = String(s).trim();
  const m = /^(.*?[a-z0-9])(R|G|B|Red|Green|Blue|X|Y|Z)$/.exec(t) || // camelCase: ksR, lightPosX
    /^(.*?\S)[\s_\-.:([]+(r|g|b|red|green|blue|x|y|z|0|1|2)\]?\)?[\s:=]*$/i.exec(t) || // ks_r, k_s (g), Specular B:
    /^(.*?[a-z_])(\d)$/i.exec(t); // ks0 (and s1..s5, a numbering: see parameterGroups)
  if (!m) return null;
  const stem = m[1].replace(/[\s_\-.:([]+$/, '').toLowerCase();
  const channel = m[2].toLowerCase();
  return stem && { stem, channel, family: CHANNEL.has(channel) ? CHANNEL.get(channel) : -1 };
}

/**
 * A channel from a slider's handler: a function called with 0, 1 or 2 (or r/g/b, x/y/z) first, as
 * changeKs(0, this.value) → { stem: 'ks', channel: '0', family }; null where none is.
 */
export function handlerChannelOf(handler) {
  const m = /\b([A-Za-z_$][\w$]*)\s*\(\s*['"]?([012]|[rgbxyz])['"]?\s*,/.exec(String(handler || ''));
  if (!m || /^(function|if|for|while|switch|return|parseFloat|parseInt|Number|setTimeout|setInterval|requestAnimationFrame)$/.test(m[1])) return null;
  const stem = m[1].replace(/^(change|set|update|handle|on)_?/i, '').toLowerCase();
  const channel = m[2].toLowerCase();
  return stem ? { stem, channel, family: CHANNEL.get(channel) } : null;
}

const isSetting = (c) => (isValued(c) && c.type !== 'select') || c.type === 'color';

/**
 * The page's sliders as the parameters they set (WP04P4: "sliders for the different parameters"):
 * three sliders of one name stem with r/g/b (red/green/blue), x/y/z or 0/1/2, one a channel, are
 * one parameter and move together; a colour picker (`<input type=color>`) is one parameter; every
 * other slider is its own. Names are read from the id, then the name, then the words beside it; a
 * stem numbered past 2 (s1 … s5) is a numbering, not channels. [{ controls, stem, channels, role }]
 * in the page's order.
 */
export function parameterGroups(controls, patterns) {
  const settable = controls.filter(isSetting);
  const grouped = new Map(); // control index → group
  // (a handler's channel counts where its stem names the parameter, or the three carry the same words)
  const sameWords = (xs) =>
    new Set(
      xs.map((x) =>
        String(x.c.text || '')
          .replace(/[([]?\b([012]|[rgbxyz])\b[)\]]?/gi, '')
          .replace(/[\s\d.:=]+/g, ' ')
          .trim()
          .toLowerCase(),
      ),
    ).size === 1;
  const handlerOk = (stem, xs) => !!nameRole({ index: -1, type: 'range', id: stem, text: stem }, patterns) || sameWords(xs);
  // where a channel is read: the id, the name, the text (each by channelOf), the handler (handlerChannelOf)
  const readers = [
    [(c) => c.id, channelOf], [(c) => c.name, channelOf], [(c) => c.text, channelOf],
    [(c) => c.handler, handlerChannelOf, handlerOk],
  ];
  for (const [source, parse, ok] of readers) {
    const byStem = new Map();
    for (const c of settable) {
      if (grouped.has(c.index) || c.type === 'color') continue;
      const ch = parse(source(c));
      if (!ch) continue;
      if (!byStem.has(ch.stem)) byStem.set(ch.stem, []);
      byStem.get(ch.stem).push({ c, ...ch });
    }
    for (const [stem, xs] of byStem) {
      const fam = xs[0].family;
      const channels = new Set(xs.map((x) => x.channel));
      if (
        fam < 0 ||
        xs.length !== 3 ||
        channels.size !== 3 ||
        xs.some((x) => x.family !== fam) ||
        (ok && !ok(stem, xs))
      ) {
        continue;
      }
      const g = { controls: xs.map((x) => x.c), stem, channels: FAMILIES[fam].join(', ') };
      for (const x of xs) grouped.set(x.c.index, g);
    }
  }
  const out = [];
  for (const c of settable) {
    const g = grouped.get(c.index);
    if (g && g.controls[0] !== c) continue;
    const group = g || { controls: [c], stem: null, channels: null };
    const asSlider = (x) => ({ ...x, type: 'range' });
    group.role =
      (g ? [{ index: -1, type: 'range', id: g.stem, text: g.stem }, ...g.controls] : [c])
        .map((x) => nameRole(asSlider(x), patterns))
        .find(Boolean) || null;
    out.push(group);
  }
  return out;
}

/** How a group of sliders is named in the report: its one control, or its stem and channels. */
export function describeGroup(g) {
  return g.controls.length === 1
    ? describe(g.controls[0])
    : `the ${g.controls.length} "${g.stem}" sliders (${g.channels}: ${g.controls.map((c) => (c.id ? `#${c.id}` : describe(c))).join(', ')}) together`;
}

/**
 * The keys of what the page sends for its shaders (grader/browser/sent.js: uniforms, constant
 * attributes, vertex buffers) whose digest differs between two reads, leaving out `animated` (the
 * keys that change with no control touched: an orbit's view matrix) and keys new in the second read
 * (a buffer made anew each frame says nothing). null where nothing was recorded.
 */
export function sentChanges(before, after, animated = []) {
  if (!before || !after) return null;
  const skip = new Set(animated);
  return Object.keys(after).filter((k) => !skip.has(k) && k in before && before[k] !== after[k]).sort();
}
