// The surface a WebGL page drew, per pixel, from what it sent: the last frame's draws of separate
// triangles drawn again in a context of the grader's own (an OffscreenCanvas; the page's context
// is only read), with the page's own vertex shader, its uniforms' values as they are now and the
// bytes it uploaded for its attributes. The vertex shader is kept whole; a main() of ours calls
// the page's and hands on, per vertex, the position attribute (the model's space), the normal
// attribute (where the shader has one named for a normal; else the position: n = p) and
// gl_Position; a fragment shader of ours writes them out in float, one pass each, with whether the
// face seen is a front face. So each pixel's position and normal are exactly the page's own,
// rasterised as the page rasterised them. Drawn with the browser's own functions
// (grader/browser/natives.js): nothing is counted, recorded or seen as the page's.
// Self-contained parts, put into graded pages as text (surfaceReaderScript, by grader/browser/geometry.js).

/**
 * The reader, from its parts: (G, infoOf) → rec.surface({ fitSamples }): { width, height, position,
 * normal (the attributes' names; normal null: n = p), box ([lo, hi] of the positions), covered
 * (pixels), fit ([[px, py, pz, cx, cy, cz, cw]]: up to fitSamples positions with their gl_Position),
 * normals, points (RGBA bytes, rows from the top: 0.5·n + 0.5 and the position within its box;
 * alpha 255 front face, 128 back face, 0 none) }, or { why } where it cannot be drawn again.
 */
function surfaceReaderOf(calls, shaders, copyUniforms, copyAttributes, drawPass, pictures) {
  return ({ rec, bytesOf, TRIANGLES }, infoOf) => ({ fitSamples }) => {
    const N = window.__glNative;
    if (!N || !N.offscreenGetContext || !N.WebGL2RenderingContext) return { why: 'this browser has no WebGL 2 OffscreenCanvas for the grader to draw the page\'s geometry again' };
    const frame = rec.cur && rec.cur.draws.length ? rec.cur : rec.last;
    const draws = frame
      ? frame.draws.filter((d) => !d.resolve && d.mode === TRIANGLES && d.count >= 3 && d.program)
      : [];
    if (!draws.length) return { why: frame && frame.draws.some((d) => d.resolve) ? 'a WebGPU page whose pipelines the grader did not see made' : 'no separate triangles (gl.TRIANGLES) were drawn in the last frame' };
    const pg = draws[0].gl, width = pg.drawingBufferWidth, height = pg.drawingBufferHeight;
    const { gl, page } = calls(N, pg, new OffscreenCanvas(width, height));
    if (!gl) return { why: 'the grader could not make a WebGL 2 context of its own' };
    try {
      if (!gl.getExtension('EXT_color_buffer_float')) return { why: 'this browser cannot draw into a float texture (EXT_color_buffer_float)' };
      const tex = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, null);
      const depth = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
      gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
      if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) return { why: 'the grader\'s float framebuffer is not complete' };
      const viewport = page('getParameter', pg.VIEWPORT);
      gl.viewport(viewport[0], viewport[1], viewport[2], viewport[3]);
      const depthTest = window.__grade && window.__grade.faces ? window.__grade.faces.depthTest : true;
      const made = { programs: new Map(), buffers: new Map(), position: null, normal: null };
      const ours = (program) => {
        let p = made.programs.get(program);
        if (!p) made.programs.set(program, p = shaders(gl, page, infoOf(pg, program), program));
        made.position = made.position || p.info.position;
        made.normal = made.normal || (p.normal && p.normal.name);
        return p;
      };
      const passes = [0, 1, 2].map((what) =>
        drawPass(
          gl,
          { draws, what, depthTest, ours, TRIANGLES, width, height },
          (d, prog) => copyUniforms(gl, page, d.program, prog),
          (d, prog) => copyAttributes(gl, page, d, prog, made.buffers, bytesOf, TRIANGLES),
        ),
      );
      const pics = pictures(passes, width, height, fitSamples);
      return pics.why ? pics : { width, height, position: made.position, normal: made.normal, ...pics };
    } catch (err) {
      return { why: `the page's geometry could not be drawn again: ${String(err && err.message).slice(0, 240)}` };
    } finally {
      const lose = gl.getExtension('WEBGL_lose_context');
      if (lose) lose.loseContext();
    }
  };
}

/** { gl: our context's functions (the browser's own, never the page's or the grader's wrappers), page(name, ...args): a read of the page's context }. */
function calls(N, pg, canvas) {
  const ctx = N.offscreenGetContext.call(canvas, 'webgl2', { antialias: false, preserveDrawingBuffer: true });
  const own = N.WebGL2RenderingContext;
  const pageFns = N[pg instanceof WebGL2RenderingContext ? 'WebGL2RenderingContext' : 'WebGLRenderingContext'];
  const gl = ctx && new Proxy(ctx, { get: (c, k) => (typeof own[k] === 'function' ? (...a) => own[k].apply(c, a) : c[k]) });
  return { gl, page: (name, ...a) => pageFns[name].apply(pg, a) };
}

/** Our program for the page's `program` (info: its attributes, infoOf): { prog, info, normal }; throws with the reason. */
function shaders(gl, page, info, program) {
  const VERTEX = 0x8B31, FRAGMENT = 0x8B30;
  const vs = (page('getAttachedShaders', program) || []).find((s) => page('getShaderParameter', s, gl.SHADER_TYPE) === VERTEX);
  const src = vs ? page('getShaderSource', vs) || '' : '';
  const es3 = /^\s*#version\s+300\s+es/.test(src);
  const main = /\bvoid\s+main\s*\(\s*(?:void)?\s*\)/;
  const pos = info.attributes.find((a) => a.name === info.position);
  const as4 = (a) => (a.type === 'vec4' ? a.name : a.type === 'vec3' ? `vec4(${a.name}, 1.0)` : a.type === 'vec2' ? `vec4(${a.name}, 0.0, 1.0)` : null);
  const p = pos && as4(pos);
  if (!p || !main.test(src)) throw new Error('the vertex shader\'s main() or position attribute was not found');
  const normal = info.attributes.find((a) => a.name !== info.position && /norm/i.test(a.name) && /^vec[34]$/.test(a.type)) || null;
  const n = normal ? `vec4(${normal.name}.xyz, 0.0)` : `vec4(${p}.xyz, 0.0)`;
  const io = (dir) => `${dir} highp vec4 _grP; ${dir} highp vec4 _grN; ${dir} highp vec4 _grC;\n`;
  // the page's main() renamed; ours calls it, then hands on the position, the normal and gl_Position
  const vsrc = `${src.replace(main, `${io(es3 ? 'out' : 'varying')}void _grMain()`)}\nvoid main() { _grMain(); _grP = ${p}; _grN = ${n}; _grC = gl_Position; }\n`;
  const body = 'highp vec4 o = _grWhat == 0 ? vec4(_grP.xyz / _grP.w, gl_FrontFacing ? 1.0 : 2.0) : _grWhat == 1 ? vec4(_grN.xyz, 1.0) : _grC;';
  const fsrc = es3 ? `#version 300 es\nprecision highp float;\n${io('in')}uniform int _grWhat;\nout highp vec4 _grOut;\nvoid main() { ${body} _grOut = o; }\n`
    : `precision highp float;\n${io('varying')}uniform int _grWhat;\nvoid main() { ${body} gl_FragColor = o; }\n`;
  const compile = (type, source) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
      throw new Error(`${type === VERTEX ? 'vertex' : 'fragment'} shader: ${(gl.getShaderInfoLog(s) || '').trim().slice(0, 200)}`);
    }
    return s;
  };
  const prog = gl.createProgram();
  gl.attachShader(prog, compile(VERTEX, vsrc));
  gl.attachShader(prog, compile(FRAGMENT, fsrc));
  gl.linkProgram(prog);
  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
    throw new Error(`link: ${(gl.getProgramInfoLog(prog) || '').trim().slice(0, 200)}`);
  }
  return { prog, info, normal };
}

/** The page program's uniforms' values now, set on ours (samplers left out: no texture is drawn). */
function copyUniforms(gl, page, program, prog) {
  const count = gl.getProgramParameter(prog, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; i++) {
    const u = gl.getActiveUniform(prog, i);
    if (!u || u.name.startsWith('_gr')) continue;
    const base = u.name.replace(/\[0\]$/, '');
    for (let k = 0; k < u.size; k++) {
      const name = u.size > 1 ? `${base}[${k}]` : u.name;
      const from = page('getUniformLocation', program, name), to = gl.getUniformLocation(prog, name);
      if (!from || !to) continue;
      const v = page('getUniform', program, from), t = u.type;
      if (t === 0x1406) gl.uniform1f(to, v);
      else if (t >= 0x8B50 && t <= 0x8B52) gl[`uniform${t - 0x8B50 + 2}fv`](to, v);
      else if (t >= 0x8B5A && t <= 0x8B5C) gl[`uniformMatrix${t - 0x8B5A + 2}fv`](to, false, v);
      else if (t === 0x1404 || t === 0x8B56) gl.uniform1i(to, Number(v));
      else if (t >= 0x8B53 && t <= 0x8B55) gl[`uniform${t - 0x8B53 + 2}iv`](to, v);
      else if (t >= 0x8B57 && t <= 0x8B59) gl[`uniform${t - 0x8B57 + 2}iv`](to, Array.from(v, Number));
      else if (t === 0x1405) gl.uniform1ui(to, v);
    }
  }
}

/** The draw's attributes (a matrix's column by column, each with the page's divisor) and indices on buffers of ours, from the bytes the page uploaded (or its constant values). */
function copyAttributes(gl, page, d, prog, buffers, bytesOf, TRIANGLES) {
  const upload = (target, src) => {
    const bytes = src && bytesOf.get(src);
    if (!bytes) return null;
    let b = buffers.get(src);
    if (!b) {
      buffers.set(src, b = gl.createBuffer());
      gl.bindBuffer(target, b);
      gl.bufferData(target, bytes, gl.STATIC_DRAW);
    }
    gl.bindBuffer(target, b);
    return b;
  };
  // a matrix attribute takes a location a column (mat2, mat3, mat4: FLOAT_MAT2 … FLOAT_MAT4)
  const columns = (type) => (type >= 0x8B5A && type <= 0x8B5C ? type - 0x8B5A + 2 : 1);
  const count = gl.getProgramParameter(prog, gl.ACTIVE_ATTRIBUTES);
  for (let i = 0; i < count; i++) {
    const a = gl.getActiveAttrib(prog, i);
    const first = gl.getAttribLocation(prog, a.name), pageFirst = page('getAttribLocation', d.program, a.name);
    if (first < 0) continue;
    for (let k = 0; k < columns(a.type); k++) {
      const to = first + k, from = pageFirst >= 0 ? pageFirst + k : -1;
      const at = from >= 0 ? d.attribs[from] : null;
      if (!at || !at.enabled || !at.buffer) {
        gl.disableVertexAttribArray(to);
        if (from >= 0) gl.vertexAttrib4fv(to, page('getVertexAttrib', from, gl.CURRENT_VERTEX_ATTRIB));
        continue;
      }
      if (!upload(gl.ARRAY_BUFFER, at.buffer)) throw new Error(`the data of ${a.name}'s buffer was not seen`);
      gl.enableVertexAttribArray(to);
      gl.vertexAttribPointer(to, at.size, at.type, at.normalized, at.stride, at.offset);
      gl.vertexAttribDivisor(to, at.divisor || 0);
    }
  }
  if (d.indexed && !upload(gl.ELEMENT_ARRAY_BUFFER, d.elements)) throw new Error('the index buffer\'s data was not seen');
  return TRIANGLES;
}

/** One pass over the draws (what: 0 the position and the face, 1 the normal, 2 gl_Position), read back in float. */
function drawPass(gl, { draws, what, depthTest, ours, TRIANGLES, width, height }, uniforms, attributes) {
  gl.clearColor(0, 0, 0, 0);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  if (depthTest) gl.enable(gl.DEPTH_TEST);
  else gl.disable(gl.DEPTH_TEST);
  for (const d of draws) {
    const p = ours(d.program);
    gl.useProgram(p.prog);
    uniforms(d, p.prog);
    gl.uniform1i(gl.getUniformLocation(p.prog, '_grWhat'), what);
    attributes(d, p.prog);
    const [mode, front] = (d.cull || 'off').split('/');
    if (mode === 'off') gl.disable(gl.CULL_FACE);
    else {
      gl.enable(gl.CULL_FACE);
      gl.cullFace(mode === 'front' ? gl.FRONT : mode === 'both' ? gl.FRONT_AND_BACK : gl.BACK);
      gl.frontFace(front === 'cw' ? gl.CW : gl.CCW);
    }
    if (d.instances !== undefined) {
      if (d.indexed) gl.drawElementsInstanced(TRIANGLES, d.count, d.type, d.offset, d.instances);
      else gl.drawArraysInstanced(TRIANGLES, d.first, d.count, d.instances);
    } else if (d.indexed) gl.drawElements(TRIANGLES, d.count, d.type, d.offset);
    else gl.drawArrays(TRIANGLES, d.first, d.count);
  }
  const px = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, px);
  return px;
}

/**
 * The passes as two pictures of the canvas's size (the normal as 0.5·n + 0.5; the position within
 * its box; alpha 255 on a front face, 128 on a back face, 0 where nothing was drawn) and up to
 * fitSamples positions with their gl_Position.
 */
function pictures([P, Nn, C], width, height, fitSamples) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  let covered = 0;
  for (let i = 0; i < P.length; i += 4) {
    if (!P[i + 3]) continue;
    covered++;
    for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], P[i + k]); hi[k] = Math.max(hi[k], P[i + k]); }
  }
  if (!covered) return { why: 'the page\'s triangles cover no pixel when drawn again' };
  const normals = new Uint8Array(width * height * 4), points = new Uint8Array(width * height * 4);
  const byte = (x) => Math.max(0, Math.min(255, Math.round(x * 255)));
  const fit = [], every = Math.max(1, Math.floor(covered / fitSamples));
  let k = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * ((height - 1 - y) * width + x), o = 4 * (y * width + x); // (read back from the bottom row up)
      if (!P[i + 3]) continue;
      const l = Math.hypot(Nn[i], Nn[i + 1], Nn[i + 2]) || 1;
      for (let c = 0; c < 3; c++) {
        normals[o + c] = byte(0.5 * (Nn[i + c] / l) + 0.5);
        points[o + c] = byte(hi[c] > lo[c] ? (P[i + c] - lo[c]) / (hi[c] - lo[c]) : 0.5);
      }
      normals[o + 3] = points[o + 3] = P[i + 3] === 1 ? 255 : 128;
      if (k++ % every === 0 && fit.length < fitSamples) {
        fit.push([P[i], P[i + 1], P[i + 2], C[i], C[i + 1], C[i + 2], C[i + 3]].map((v) => Math.round(v * 1e6) / 1e6));
      }
    }
  }
  return { box: [lo, hi], covered, fit, normals, points };
}

const PARTS = [calls, shaders, copyUniforms, copyAttributes, drawPass, pictures];

/** The reader's maker as an expression for a page's script: (G, infoOf) → rec.surface. */
export const surfaceReaderScript = `(${surfaceReaderOf})(${PARTS.join(', ')})`;

/** pictures() as text, for the WebGPU reader (grader/browser/surface-webgpu.js), which makes the same pictures. */
export const picturesScript = `${pictures}`;
