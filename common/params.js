// The exercises' parameters, each declared once: its type, the values the URL may give it, its
// default, its label, and for a slider the range it spans. The URL clamp (readParams), the
// controls (common/controls.js) and window.scene (common/step.js) all come from this table.
// Nothing here touches the page, so node's test runner checks it directly.
import { EYE_DISTANCE, FOVY, LIGHT_DEFAULTS } from './course.js';
import { MAX_LEVEL, chooseLevel } from './sphere.js';

/**
 * @typedef {object} Parameter
 * @property {'int'|'number'|'bool'|'enum'} type
 * @property {*} default a value, or a function of the values read before it (`(values, step) => …`)
 * @property {number} [min] least value the URL may give (int, number)
 * @property {number} [max] largest value the URL may give (int, number)
 * @property {Object<string, string>} [options] enum: value → the text the control shows
 * @property {string} [label] the control's visible label (its accessible name)
 * @property {string} [id] the control's element id, where it is not the parameter's name
 * @property {[number, number, number]} [slider] a slider's [least, largest, step]; a value from
 *   the URL outside it widens the slider so that the thumb and the value shown agree
 * @property {string} [follows] an enum parameter whose choice sets this one's default; the control
 *   of that parameter swaps this value for the one last used with the new choice
 */

/** @type {Object<string, Parameter>} */
export const PARAMETERS = {
  api: { type: 'enum', options: { webgl2: 'WebGL 2', webgl: 'WebGL 1', webgpu: 'WebGPU' }, default: 'webgl2' },
  size: { type: 'int', min: 16, max: 2048, default: 512 },
  // multisampling (the slides' msaaCount): 1 (none, as the exact reference renders) or 4
  msaa: { type: 'enum', options: { 1: 'none', 4: '4 samples a pixel' }, default: '1' },
  height: { type: 'int', min: 16, max: 2048, default: (v) => v.size },
  near: { type: 'number', min: 0.01, max: 100, default: 0.1 },
  far: { type: 'number', min: 0.02, max: 1000, default: 10 },
  // Model no more than the scene needs: by default the least level that looks round at this size
  // and, on a lit step, shades within 1/255 of the exact render
  level: { type: 'int', min: 0, max: MAX_LEVEL, default: (v, step) => autoLevel(v, step) },
  depth: { type: 'bool', default: true, label: 'Depth test', id: 'depthTest' },
  cull: { type: 'bool', default: true, label: 'Cull faces', id: 'cullFace' },
  cw: { type: 'bool', default: false, label: 'Clockwise front faces', id: 'frontFaceCW' },
  orbit: { type: 'bool', default: true, label: 'Orbit' },
  angle: { type: 'number', min: -1e6, max: 1e6, default: 0 },
  light: {
    type: 'enum', default: 'directional', label: 'Light',
    options: { directional: 'directional (w = 0): xyz is its direction', point: 'point (w = 1): xyz is its position' },
  },
  lx: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][0], label: 'light x', slider: [-5, 5, 0.1], follows: 'light' },
  ly: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][1], label: 'light y', slider: [-5, 5, 0.1], follows: 'light' },
  lz: { type: 'number', min: -1e6, max: 1e6, default: (v) => LIGHT_DEFAULTS[v.light][2], label: 'light z', slider: [-5, 5, 0.1], follows: 'light' },
  kd: { type: 'number', min: 0, max: 1, default: 0.8, label: 'kd', slider: [0, 1, 0.01] },
  ks: { type: 'number', min: 0, max: 1, default: 0.5, label: 'ks', slider: [0, 1, 0.01] },
  s: { type: 'number', min: 0, max: 10000, default: 40, label: 's', slider: [0, 500, 1] },
  Le: { type: 'number', min: 0, max: 1e12, default: 1, label: 'Le', slider: [0, 5, 0.05] }, // a far point light needs a large intensity
  La: { type: 'number', min: 0, max: 1, default: 0.2, label: 'La', slider: [0, 1, 0.01] },
  model: {
    type: 'enum', default: 'phong', label: 'Specular term',
    options: { phong: 'Phong (w_r · w_o)', 'blinn-phong': 'Blinn-Phong (n · w_h)' },
  },
};

/** The level chooseLevel picks for a step's canvas height (or size), shading and shininess (when read already). */
export function autoLevel(values, step = {}) {
  return chooseLevel(values.height ?? values.size, FOVY, EYE_DISTANCE, { shading: step.shading ?? null, shininess: values.s }).level;
}

const TRUE = new Set(['1', 'true', 'on', 'yes']);
const FALSE = new Set(['0', 'false', 'off', 'no']);

function parseOne(name, raw, rule, fallback) {
  const fix = (why) => ({ value: fallback, notice: `${name}=${raw} ${why}: using ${name}=${fallback}.` });
  if (rule.type === 'enum') {
    const values = Object.keys(rule.options);
    return values.includes(raw) ? { value: raw } : fix(`is not one of ${values.join(', ')}`);
  }
  if (rule.type === 'bool') {
    const v = raw.toLowerCase();
    if (TRUE.has(v)) return { value: true };
    if (FALSE.has(v)) return { value: false };
    return fix('is not on/off (1 or 0)');
  }
  const x = raw.trim() === '' ? NaN : Number(raw);
  if (!Number.isFinite(x)) return fix('is not a number');
  const value = rule.type === 'int' ? Math.round(x) : x;
  if (value < rule.min) {
    return { value: rule.min, notice: `${name}=${raw} is below the least value ${rule.min}: using ${rule.min}.` };
  }
  if (value > rule.max) {
    return { value: rule.max, notice: `${name}=${raw} is above the largest value ${rule.max}: using ${rule.max}.` };
  }
  if (value !== x) return { value, notice: `${name}=${raw} is not a whole number: using ${value}.` };
  return { value };
}

/** The default of parameter `name` given the values read so far. */
export function defaultOf(name, values, step, table = PARAMETERS) {
  const d = table[name].default;
  return typeof d === 'function' ? d(values, step) : d;
}

/**
 * Reads a step's parameters from a query string: every name gets a valid value; what was clamped
 * or ignored is said in `notices`, one sentence each.
 * @param {string[]} names the parameters the step has (keys of `table`)
 * @param {string} search a query string, e.g. location.search
 * @param {object} [step] passed to defaults that are functions (e.g. `{ shading: 'phong' }`)
 * @param {Object<string, Parameter>} [table]
 * @returns {{values: Object, notices: string[]}}
 */
export function readParams(names, search, step = {}, table = PARAMETERS) {
  const values = {};
  const notices = [];
  const given = new URLSearchParams(search);
  for (const name of given.keys()) {
    if (!names.includes(name)) notices.push(`Unknown parameter "${name}" ignored.`);
  }
  // Plain defaults first; a default that is a function of the other values comes after them.
  const ordered = [...names].sort((a, b) =>
    (typeof table[a].default === 'function') - (typeof table[b].default === 'function'));
  for (const name of ordered) {
    const fallback = defaultOf(name, values, step, table);
    values[name] = fallback;
    if (!given.has(name)) continue;
    const { value, notice } = parseOne(name, given.get(name), table[name], fallback);
    values[name] = value;
    if (notice) notices.push(notice);
  }
  // The view's own rules: an angle in [0, 2π), the far plane beyond the near one
  if ('angle' in values) values.angle = wrapAngle(values.angle);
  if ('far' in values) values.far = Math.max(values.far, values.near * 1.01);
  return { values, notices };
}

/** The query string for these values (booleans as 1 and 0), so a copied link reproduces the view. */
export function queryString(values) {
  const query = new URLSearchParams();
  for (const [name, value] of Object.entries(values)) {
    query.set(name, typeof value === 'boolean' ? (value ? '1' : '0') : String(value));
  }
  return query.toString();
}

/** An angle in [0, 2π). */
export function wrapAngle(a) {
  const t = a % (2 * Math.PI);
  return t < 0 ? t + 2 * Math.PI : t;
}
