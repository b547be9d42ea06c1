// Phong shading (WP04P5): "Most importantly, we must normalize the direction vectors in the
// fragment shader." Interpolated unit vectors are shorter than one between the vertices, so a
// fragment shader that takes an interpolated normal (or light or view direction) into dot() as it
// comes gets a darker, smaller highlight inside each triangle. Read from the fragment shader's own
// code: its interpolated vec3/vec4 inputs that enter dot() or reflect() and are never normalised there.

const NORMALISERS = /^(normalize|length|inversesqrt)$/;
const USES = /^(dot|reflect|faceforward)$/;
// a colour or a texture coordinate is not a direction
const NOT_A_DIRECTION = /col|rgb|albedo|tex|uv|kd|ks/i;

const stripComments = (s) => s.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');
const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** Every call `name(args)` in `code`: [{ name, args, from, to }], `args` its arguments' text (balanced parentheses), [from, to) the call's. */
function calls(code) {
  const out = [];
  for (const m of code.matchAll(/\b([A-Za-z_]\w*)\s*\(/g)) {
    let depth = 1;
    let k = m.index + m[0].length;
    for (; k < code.length && depth > 0; k++) depth += code[k] === '(' ? 1 : code[k] === ')' ? -1 : 0;
    out.push({ name: m[1], args: code.slice(m.index + m[0].length, k - 1), from: m.index, to: k });
  }
  return out;
}

/** `code` with every normalising call blanked: what is left is used as it comes. */
function withoutNormalisers(code) {
  let out = code;
  for (const c of calls(code)) {
    if (NORMALISERS.test(c.name)) {
      out = out.slice(0, c.from) + ' '.repeat(c.to - c.from) + out.slice(c.to);
    }
  }
  return out;
}

/** The GLSL fragment shader's interpolated vectors: `varying vec3 N, L;` or `in highp vec4 v;`. */
function glslInputs(fs) {
  const names = [];
  for (const m of fs.matchAll(/\b(?:varying|in)\s+(?:(?:lowp|mediump|highp|flat|smooth|noperspective)\s+)*vec[34]\s+([^;]+);/g)) {
    for (const n of m[1].split(',')) names.push(n.trim().replace(/\[.*$/, ''));
  }
  return names.filter(Boolean).map((n) => ({ name: n, token: new RegExp(`\\b${escape(n)}\\b`) }));
}

/** WGSL: the @fragment function's code and its @location vec3/vec4 inputs (parameters, or fields of a struct parameter). */
function wgslInputs(src) {
  const at = src.search(/@fragment/);
  if (at < 0) return null;
  const code = src.slice(at);
  const fn = code.match(/fn\s+[A-Za-z_]\w*\s*\(/);
  const params = fn ? (calls(code.slice(fn.index + 2))[0] || { args: '' }).args : '';
  const inputs = [];
  const vec = /^vec[34](f|h|<\s*f(32|16)\s*>)$/;
  for (const p of params.split(',').map((s) => s.trim()).filter(Boolean)) {
    const m = p.match(/([A-Za-z_]\w*)\s*:\s*([\w<>\s]+)$/);
    if (!m) continue;
    const [, name, type] = m;
    if (/@location/.test(p) && vec.test(type.replace(/\s/g, ''))) inputs.push({ name, token: new RegExp(`\\b${escape(name)}\\b(?!\\s*:)`) });
    const struct = src.match(new RegExp(`struct\\s+${escape(type.trim())}\\s*\\{([^}]*)\\}`));
    if (!struct) continue;
    for (const f of struct[1].split(',')) {
      const fm = f.match(/@location\s*\(\s*\d+\s*\)[^:]*?([A-Za-z_]\w*)\s*:\s*([\w<>\s]+)$/);
      if (fm && vec.test(fm[2].replace(/\s/g, ''))) {
        inputs.push({
          name: `${name}.${fm[1]}`,
          token: new RegExp(`\\b${escape(name)}\\s*\\.\\s*${escape(fm[1])}\\b`),
        });
      }
    }
  }
  return { code, inputs };
}

/** Is `text` the input itself (`v`, `-v`, `v.xyz`, `in.n`)? */
const isItself = (text, token) => {
  const t = text.trim().replace(/^-\s*/, '').replace(/\.[xyzwrgba]{1,4}$/, '');
  const m = t.match(token);
  return !!m && m.index === 0 && m[0].length === t.length;
};

/**
 * The inputs normalised in `code`: the argument of normalize(), length() or inversesqrt(), or
 * dot(v, v), or assigned as they are to a name that is (`vec3 n = v; ... n = normalize(n);`).
 */
function normalisedIn(code, inputs) {
  const all = calls(code);
  const normalising = all.filter((c) => NORMALISERS.test(c.name)).map((c) => c.args);
  for (const c of all) {
    const [x, y, more] = c.name === 'dot' ? c.args.split(',') : [];
    if (x !== undefined && y !== undefined && more === undefined && x.trim() === y.trim()) normalising.push(x);
  }
  const assignments = [...code.matchAll(/\b([A-Za-z_]\w*)\s*(?::\s*[\w<>]+\s*)?=(?!=)([^;]*);/g)].map((m) => ({ lhs: m[1], rhs: m[2] }));
  const isNormalised = (token, seen) => normalising.some((a) => isItself(a, token))
    || assignments.some(({ lhs, rhs }) => !seen.has(lhs) && isItself(rhs, token)
      && isNormalised(new RegExp(`\\b${escape(lhs)}\\b`), new Set([...seen, lhs])));
  return new Set(inputs.filter((i) => isNormalised(i.token, new Set())).map((i) => i.name));
}

/**
 * The fragment shaders' interpolated vectors that enter dot() or reflect() and are never normalised
 * in the fragment shader: [name, ...] (empty when every one is, or no fragment shader computes with them).
 */
export function unnormalisedInputs(sources) {
  const stages = [];
  for (const s of sources.glsl || []) {
    const fs = stripComments(s);
    if (/gl_FragColor|out\s+(?:(?:lowp|mediump|highp)\s+)?vec4/.test(fs) && !/gl_Position/.test(fs)) stages.push({ code: fs, inputs: glslInputs(fs) });
  }
  for (const s of sources.wgsl || []) {
    const stage = wgslInputs(stripComments(s));
    if (stage) stages.push(stage);
  }
  const found = [];
  for (const { code, inputs } of stages) {
    const directions = inputs.filter((i) => !NOT_A_DIRECTION.test(i.name));
    const normalised = normalisedIn(code, directions);
    const used = calls(code).filter((c) => USES.test(c.name)).map((c) => withoutNormalisers(c.args));
    for (const i of directions) {
      if (!normalised.has(i.name) && used.some((a) => i.token.test(a)) && !found.includes(i.name)) {
        found.push(i.name);
      }
    }
  }
  return found;
}
