// The geometry a page drew, summed up from the bytes it sent (grader/browser/geometry.js records
// them): how many triangles, which way they are wound seen from outside, whether the mesh is closed,
// and which attributes are constant over each triangle (a face's colour or normal, not a vertex's).
// Self-contained functions (put into graded pages as text, meshAnalysisScript, and called by the
// unit tests in Node, meshAnalysis), giving { vertexShader, vertexInputs, summary }; a WGSL entry
// point's inputs are read by wgsl-vertex.js, which the script defines beside them.
import { wgslVertexEntry } from './wgsl-vertex.js';

/**
 * The analysis, from its parts (each self-contained: the page gets them as text, meshAnalysisScript):
 * { vertexShader, vertexInputs, summary(draws, opts) }.
 */
function analysis(vertexShader, vertexInputs, reader, indexer, meshesOf, walker, tally) {
  // (the triangles read at most where no limit is given: the mesh's, and the edges' walk)
  const MAX_TRIANGLES = 60000, MAX_EDGES = 65536;
  const summary = (draws, { FLOAT, TRIANGLES, maxTriangles = MAX_TRIANGLES, maxEdgeTriangles = MAX_EDGES }) => {
    const tris = draws.filter((d) => d.mode === TRIANGLES && d.count >= 3);
    const triangles = tris.reduce((n, d) => n + Math.floor(d.count / 3), 0);
    const out = {
      draws: draws.length,
      triangles,
      otherVertices: draws.filter((d) => d.mode !== TRIANGLES).reduce((n, d) => n + d.count, 0),
      // drawn as lines (LINES, LINE_LOOP, LINE_STRIP: modes 1 to 3): a wireframe, not a surface
      lineVertices: draws.filter((d) => d.mode >= 1 && d.mode <= 3).reduce((n, d) => n + d.count, 0),
    };
    if (!tris.length) return { ...out, why: 'no separate triangles (gl.TRIANGLES) were drawn' };
    const largest = tris.reduce((a, b) => (b.count > a.count ? b : a));
    out.cull = largest.cull;
    const found = meshesOf(tris, FLOAT, reader, indexer);
    if (found.why) return { ...out, ...(found.position ? { position: found.position } : {}), why: found.why };
    out.position = found.position;
    const step = Math.max(1, Math.ceil(triangles / maxTriangles));
    const each = walker(found.meshes, step);
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    each((m, j, v) => {
      if (v) {
        for (const q of v) {
          for (let k = 0; k < 3; k++) {
            lo[k] = Math.min(lo[k], q[k]);
            hi[k] = Math.max(hi[k], q[k]);
          }
        }
      }
    });
    const centre = lo.map((x, k) => (x + hi[k]) / 2);
    const diag = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    if (!(diag > 0)) return { ...out, why: 'the positions are all one point, or none could be read' };
    return { ...out, ...tally(each, centre, diag, step === 1 && triangles <= maxEdgeTriangles) };
  };
  return { vertexShader, vertexInputs, summary };
}

/**
 * A vertex shader's attributes ({ name, type }) and the one gl_Position is computed from
 * (`position`): traced back through the assignments before it; else the one named for a
 * position, else the only vec3/vec4 one.
 */
function vertexShader(source) {
  const ATTRIBUTE = /(?:^|[;\s)])(?:attribute|in)\s+(?:(?:highp|mediump|lowp)\s+)?(float|vec[234]|mat[234]|ivec[234]|int)\s+([A-Za-z_]\w*)/g;
  const ASSIGN = /([A-Za-z_]\w*)(?:\.[xyzwrgba]+)?\s*[-+*/]?=(?!=)\s*([^;]+);/g;
  const IDENT = /[A-Za-z_]\w*/g;
  const code = String(source).replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, ' ');
  const attributes = [];
  for (const m of code.matchAll(ATTRIBUTE)) {
    if (!attributes.some((a) => a.name === m[2])) {
      attributes.push({ type: m[1], name: m[2] });
    }
  }
  const assigned = new Map();
  for (const m of code.matchAll(ASSIGN)) {
    if (!assigned.has(m[1])) assigned.set(m[1], []);
    assigned.get(m[1]).push(m[2]);
  }
  const names = new Set(attributes.map((a) => a.name));
  const reached = [], seen = new Set(), todo = ['gl_Position'];
  while (todo.length && seen.size < 500) {
    const id = todo.shift();
    if (seen.has(id)) continue;
    seen.add(id);
    if (names.has(id)) { reached.push(id); continue; }
    for (const expr of assigned.get(id) || []) for (const m of expr.matchAll(IDENT)) todo.push(m[0]);
  }
  const vector = (a) => a.type === 'vec3' || a.type === 'vec4';
  const named = (a) => /pos|vert|coord/i.test(a.name);
  const candidates = attributes.filter((a) => vector(a) && reached.includes(a.name));
  const pick = candidates.find(named) || candidates[0] || attributes.find((a) => vector(a) && /pos/i.test(a.name))
    || (attributes.filter(vector).length === 1 ? attributes.find(vector) : null);
  return { attributes, position: pick ? pick.name : null };
}


/**
 * A WGSL vertex entry point's inputs (`entryPoint`, else the first @vertex function): byLocation
 * ({ N: { name, type } }, from its parameters and the structs they are) and the location of the
 * position (named for one, else location 0).
 */
function vertexInputs(source, entryPoint) {
  const byLocation = {};
  for (const i of wgslVertexEntry(source, entryPoint).inputs || []) byLocation[i.at] = { name: i.name, type: i.type };
  const vector = (t) => /vec[34]/.test(t.type);
  const named = Object.entries(byLocation).find(([, t]) => vector(t) && /pos|vert/i.test(t.name));
  const position = named ? Number(named[0]) : byLocation[0] ? 0 : null;
  return { byLocation, position };
}


/** A reader of one attribute's vertices: (i, out) → true when vertex i was inside the buffer. */
function reader(data, FLOAT) {
  if (!data || !data.bytes || data.type !== FLOAT) return null;
  const view = new DataView(data.bytes.buffer, data.bytes.byteOffset, data.bytes.byteLength);
  const size = data.size, stride = data.stride || 4 * size, offset = data.offset || 0;
  return (i, out) => {
    const at = offset + i * stride;
    if (i < 0 || at + 4 * size > view.byteLength) return false;
    for (let k = 0; k < size; k++) out[k] = view.getFloat32(at + 4 * k, true);
    return true;
  };
}

/** A draw's k-th vertex's index (its element, or first + k), or null where the index buffer's data was not seen. */
function indexer(d) {
  if (!d.indexed) return (k) => d.first + k;
  if (!d.indices) return null;
  const view = new DataView(d.indices.buffer, d.indices.byteOffset, d.indices.byteLength);
  const bytes = d.type === 0x1401 ? 1 : d.type === 0x1403 ? 2 : 4;
  return (k) => {
    const at = d.offset + k * bytes;
    if (at + bytes > view.byteLength) return -1;
    return (
      (d.base || 0) +
      (bytes === 1 ? view.getUint8(at) : bytes === 2 ? view.getUint16(at, true) : view.getUint32(at, true))
    );
  };
}


/**
 * The draws' meshes: { meshes: [{ d, n (triangles), index, read (positions), size, others (vec3/4
 * attributes read alike) }], position (the position attribute's name) }, or { why, position? }
 * where the positions cannot be read.
 */
function meshesOf(tris, FLOAT, reader, indexer) {
  const meshes = [];
  let position;
  for (const d of tris) {
    const pos = d.attributes.find((a) => a.position);
    const why = !pos ? 'the vertex shader\'s position attribute was not found'
      : !pos.data ? `the position attribute ${pos.name} is not on an enabled buffer`
        : !pos.data.bytes ? `the data of ${pos.name}'s buffer was not seen`
          : pos.data.type !== FLOAT ? `${pos.name} is not made of floats` : !indexer(d) ? 'the index buffer\'s data was not seen' : null;
    if (why) return { why, position };
    position = pos.name;
    const others = d.attributes
      .filter((a) => !a.position && /^vec[34]$/.test(a.type) && a.data && a.data.size >= 3 && reader(a.data, FLOAT))
      .map((a) => ({ name: a.name, read: reader(a.data, FLOAT), size: a.data.size }));
    meshes.push({
      d,
      n: Math.floor(d.count / 3),
      index: indexer(d),
      read: reader(pos.data, FLOAT),
      size: pos.data.size,
      others,
    });
  }
  return { meshes, position };
}

/** each(fn): every `step`-th triangle over all the meshes, in order, as fn(mesh, j, [a, b, c] or null where a corner is past its buffer). */
function walker(meshes, step) {
  const p = [0, 0, 0, 1];
  const vertex = (m, k, into) => {
    const i = m.index(k);
    if (!m.read(i, p)) return false;
    const w = m.size === 4 && p[3] !== 0 ? p[3] : 1;
    into[0] = p[0] / w; into[1] = p[1] / w; into[2] = p[2] / w;
    return true;
  };
  // (t counts over all draws)
  return (fn) => {
    let t = 0;
    const a = [0, 0, 0], b = [0, 0, 0], c = [0, 0, 0];
    for (const m of meshes) {
      for (let j = (step - (t % step)) % step; j < m.n; j += step) {
        const ok = vertex(m, 3 * j, a) && vertex(m, 3 * j + 1, b) && vertex(m, 3 * j + 2, c);
        fn(m, j, ok ? [a, b, c] : null);
      }
      t += m.n;
    }
  };
}

/**
 * The triangles walked (`each`) around the mesh's centre (`diag` its size): { analysed, cw (the
 * share wound clockwise seen from outside), degenerate, outside (past the buffer's end), closed ({
 * edges, open, over } where `edgesWanted`, else null), perFace ([{ name, share, distinct }]) }.
 */
function tally(each, centre, diag, edgesWanted) {
  let analysed = 0, cw = 0, degenerate = 0, outside = 0;
  const faces = new Map(); // attribute name → { same, all, distinct }
  const ids = new Map(), edges = new Map(), q = diag * 1e-5;
  const idOf = (v) => {
    const key = `${Math.round(v[0] / q)},${Math.round(v[1] / q)},${Math.round(v[2] / q)}`;
    let id = ids.get(key);
    if (id === undefined) ids.set(key, id = ids.size);
    return id;
  };
  const va = [0, 0, 0, 0], vb = [0, 0, 0, 0], vc = [0, 0, 0, 0];
  each((m, j, v) => {
    if (!v) { outside++; return; }
    analysed++;
    const [a, b, c] = v;
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]], w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const mid = [0, 1, 2].map((k) => (a[k] + b[k] + c[k]) / 3 - centre[k]);
    const dot = n[0] * mid[0] + n[1] * mid[1] + n[2] * mid[2];
    if (Math.hypot(...n) < 1e-12 * diag * diag || Math.abs(dot) < 1e-9 * diag * diag * diag) degenerate++;
    else if (dot < 0) cw++;
    if (edgesWanted) {
      const i = [idOf(a), idOf(b), idOf(c)];
      for (let k = 0; k < 3; k++) {
        const x = i[k], y = i[(k + 1) % 3];
        if (x === y) continue;
        const key = Math.min(x, y) * 2 ** 24 + Math.max(x, y);
        edges.set(key, (edges.get(key) || 0) + 1);
      }
    }
    for (const o of m.others) {
      const f = faces.get(o.name) || faces.set(o.name, { same: 0, all: 0, distinct: new Set() }).get(o.name);
      const i0 = m.index(3 * j), i1 = m.index(3 * j + 1), i2 = m.index(3 * j + 2);
      if (!o.read(i0, va) || !o.read(i1, vb) || !o.read(i2, vc)) continue;
      f.all++;
      let same = true;
      for (let k = 0; k < o.size && k < 4; k++) {
        if (Math.abs(va[k] - vb[k]) > 1e-6 || Math.abs(va[k] - vc[k]) > 1e-6) {
          same = false;
        }
      }
      if (same) f.same++;
      if (f.distinct.size < 64) f.distinct.add(va.slice(0, Math.min(o.size, 3)).map((x) => x.toFixed(4)).join(','));
    }
  });
  const share = (x, of) => (of ? Math.round((x / of) * 1e4) / 1e4 : 0);
  const solid = analysed - degenerate;
  let closed = null;
  if (edgesWanted) {
    let open = 0, over = 0;
    for (const count of edges.values()) { if (count === 1) open++; else if (count > 2) over++; }
    closed = { edges: edges.size, open, over };
  }
  return { analysed, cw: share(cw, solid), degenerate: share(degenerate, analysed), outside, closed,
    perFace: [...faces].map(([name, f]) => ({ name, share: share(f.same, f.all), distinct: f.distinct.size })) };
}

const PARTS = [vertexShader, vertexInputs, reader, indexer, meshesOf, walker, tally];

/** The analysis as an expression for a page's script: its parts as text. */
export const meshAnalysisScript = `((wgslVertexEntry) => (${analysis})(${PARTS.join(', ')}))(${wgslVertexEntry})`;

/** The analysis here (the unit tests run it in Node, as a page runs meshAnalysisScript). */
export const meshAnalysis = () => analysis(...PARTS);
