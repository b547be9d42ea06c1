// A WGSL vertex entry point as the page wrote it, read from its code: its parameters, the inputs
// they carry by @location (directly or as members of a struct they are) and the text of its result
// type. Self-contained (put into graded pages as text by mesh.js and surface-webgpu.js, whose
// scripts define it beside the functions that call it; run by the unit tests in Node).

/**
 * The vertex entry point `entryPoint` (else the first @vertex function) of the WGSL `code`:
 * { src (the code, comments blanked), at (where its `@vertex fn` begins), paramsText, params
 * ([{ attrs, name, type }], null for one that cannot be read), resultType (its result's type, its
 * attributes left out), body (the index of its body's `{`, -1 where there is none),
 * inputs ([{ at (the location), name, path (how the entry point reads it), type }]), structOf(type)
 * (a struct's members, or null) }, or { why } where no such entry point is found.
 */
export function wgslVertexEntry(code, entryPoint) {
  const src = String(code).replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, ' ');
  const entry = [...src.matchAll(/@vertex\s+fn\s+(\w+)\s*\(/g)].find((m) => !entryPoint || m[1] === entryPoint);
  if (!entry) return { why: `the vertex entry point${entryPoint ? ` ${entryPoint}` : ''} was not found in the page's WGSL` };
  // its parameters (balanced parentheses), then its result's type up to the body's brace
  let depth = 1, k = entry.index + entry[0].length;
  const from = k;
  for (; k < src.length && depth > 0; k++) depth += src[k] === '(' ? 1 : src[k] === ')' ? -1 : 0;
  const paramsText = src.slice(from, k - 1);
  const body = src.indexOf('{', k);
  const ATTRS = /(?:@\w+\s*(?:\([^)]*\))?\s*)*/;
  const PARAM = new RegExp(`^(${ATTRS.source})(\\w+)\\s*:\\s*(.+)$`, 's');
  // a list split at its top-level commas
  const split = (text) => {
    const out = [];
    let level = 0, cur = '';
    for (const ch of text) {
      if (ch === '<' || ch === '(') level++;
      if (ch === '>' || ch === ')') level--;
      if (ch === ',' && level === 0) { out.push(cur); cur = ''; } else cur += ch;
    }
    out.push(cur);
    return out.map((p) => p.trim()).filter(Boolean);
  };
  const declared = (text) => {
    const m = PARAM.exec(text);
    return m && { attrs: m[1], name: m[2], type: m[3].trim() };
  };
  const params = split(paramsText).map(declared);
  const structOf = (type) => {
    const m = new RegExp(`struct\\s+${String(type).replace(/\W/g, '')}\\s*\\{([^}]*)\\}`).exec(src);
    return m ? split(m[1].replace(/;/g, ',')).map(declared).filter(Boolean) : null;
  };
  const location = (attrs) => { const m = /@location\s*\(\s*(\d+)\s*\)/.exec(attrs); return m ? Number(m[1]) : null; };
  const inputs = [];
  for (const p of params.filter(Boolean)) {
    if (location(p.attrs) !== null) inputs.push({ at: location(p.attrs), name: p.name, path: p.name, type: p.type });
    else {
      for (const m of structOf(p.type) || []) {
        const at = location(m.attrs);
        if (at !== null) inputs.push({ at, name: m.name, path: `${p.name}.${m.name}`, type: m.type });
      }
    }
  }
  const resultType = body < 0 ? '' : src.slice(k, body).replace(/^\s*->/, '').replace(new RegExp(`^\\s*${ATTRS.source}`), '').trim();
  return { src, at: entry.index, paramsText, params, resultType, body, inputs, structOf };
}
