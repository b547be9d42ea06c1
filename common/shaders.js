// Shader programs from .vert/.frag files: fetched together (Promise.all), compiled and linked.
// A failure throws an Error that names the file and the line, with the source listed around it,
// so the page can show the student exactly where the GLSL is wrong.

/** Error from a shader that failed to load, compile or link; `details` is the marked listing. */
class ShaderError extends Error {
  constructor(message, details = '') {
    super(message);
    this.name = 'ShaderError';
    this.details = details;
  }
}

async function fetchText(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (err) {
    throw new ShaderError(`Could not load the shader ${url}: ${err.message}`);
  }
  if (!response.ok) {
    throw new ShaderError(`Could not load the shader ${url}: the server answered ${response.status} ${response.statusText}`);
  }
  return response.text();
}

/** The source with line numbers, the failing line marked with ">>". */
export function listing(source, badLine) {
  const lines = source.split('\n');
  const width = String(lines.length).length;
  return lines
    .map((text, i) => `${i + 1 === badLine ? '>>' : '  '} ${String(i + 1).padStart(width)}  ${text}`)
    .join('\n');
}

/**
 * Compiles one shader; on failure throws a ShaderError naming `name` and the first bad line.
 * @param {WebGLRenderingContext|WebGL2RenderingContext} gl
 * @param {number} type gl.VERTEX_SHADER or gl.FRAGMENT_SHADER
 * @param {string} source GLSL
 * @param {string} name the file name shown in messages
 */
function compileShader(gl, type, source, name) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (gl.getShaderParameter(shader, gl.COMPILE_STATUS) || gl.isContextLost()) return shader;
  const log = (gl.getShaderInfoLog(shader) || 'no log').trim();
  gl.deleteShader(shader);
  // Logs read like "ERROR: 0:12: 'foo' : undeclared identifier"
  const match = /ERROR:\s*\d+:(\d+):\s*(.*)/.exec(log);
  const line = match ? Number(match[1]) : 0;
  const where = line ? `${name}, line ${line}` : name;
  throw new ShaderError(`Shader error in ${where}: ${match ? match[2] : log}`, `${log}\n\n${listing(source, line)}`);
}

/** Links two compiled shaders into a program, or throws a ShaderError with the link log. */
function linkProgram(gl, vertexShader, fragmentShader, name = 'program') {
  const program = gl.createProgram();
  gl.attachShader(program, vertexShader);
  gl.attachShader(program, fragmentShader);
  gl.linkProgram(program);
  if (gl.getProgramParameter(program, gl.LINK_STATUS) || gl.isContextLost()) return program;
  const log = (gl.getProgramInfoLog(program) || 'no log').trim();
  gl.deleteProgram(program);
  throw new ShaderError(`Could not link ${name}: ${log}`);
}

/**
 * Fetches a vertex and a fragment shader by URL (relative to the page), together.
 * @returns {Promise<{vertex: string, fragment: string, vertexName: string, fragmentName: string}>}
 */
export async function loadShaders(vertexUrl, fragmentUrl) {
  const [vertex, fragment] = await Promise.all([fetchText(vertexUrl), fetchText(fragmentUrl)]);
  return { vertex, fragment, vertexName: vertexUrl, fragmentName: fragmentUrl };
}

/** Compiles and links shaders as loadShaders gives them: a new program for this context. */
export function programFrom(gl, shaders) {
  return createProgram(gl, shaders.vertex, shaders.fragment, shaders.vertexName, shaders.fragmentName);
}

/** Compiles and links GLSL sources given as strings (names are for messages). */
function createProgram(gl, vertexSource, fragmentSource, vertexName = 'vertex shader', fragmentName = 'fragment shader') {
  const vs = compileShader(gl, gl.VERTEX_SHADER, vertexSource, vertexName);
  const fs = compileShader(gl, gl.FRAGMENT_SHADER, fragmentSource, fragmentName);
  const program = linkProgram(gl, vs, fs, `${vertexName} + ${fragmentName}`);
  // The program keeps what it needs; the shader objects can go.
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  return program;
}

/**
 * Uploads a program's uniforms by name: each active uniform takes `uniforms[name]`, or else
 * `values[name]` (a step's parameters: kd, ks, s, Le, La are the slides' names and the shaders').
 * A number given for a vecN fills every component. Locations are looked up once per program.
 * @param {WebGLRenderingContext|WebGL2RenderingContext} gl
 * @param {WebGLProgram} program the program in use
 * @param {Object<string, number|boolean|ArrayLike<number>>} uniforms
 * @param {Object<string, *>} [values]
 */
export function setUniforms(gl, program, uniforms, values = {}) {
  let setters = settersOf.get(program);
  if (!setters) settersOf.set(program, (setters = makeSetters(gl, program)));
  for (let i = 0; i < setters.length; i++) {
    const { name, set } = setters[i];
    const value = name in uniforms ? uniforms[name] : values[name];
    if (value === undefined) throw new Error(`setUniforms: the shaders' uniform ${name} has no value`);
    set(value);
  }
}

const settersOf = new WeakMap();

function makeSetters(gl, program) {
  const setters = [];
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; i++) {
    const { name, type } = gl.getActiveUniform(program, i);
    const at = gl.getUniformLocation(program, name);
    const vector = (n, upload) => {
      const splat = new Float32Array(n); // filled when a number is given for the vector
      return (v) => upload.call(gl, at, typeof v === 'number' ? splat.fill(v) : v);
    };
    const set = {
      [gl.FLOAT]: (v) => gl.uniform1f(at, v),
      [gl.FLOAT_VEC2]: vector(2, gl.uniform2fv),
      [gl.FLOAT_VEC3]: vector(3, gl.uniform3fv),
      [gl.FLOAT_VEC4]: vector(4, gl.uniform4fv),
      [gl.FLOAT_MAT3]: (v) => gl.uniformMatrix3fv(at, false, v),
      [gl.FLOAT_MAT4]: (v) => gl.uniformMatrix4fv(at, false, v),
      [gl.INT]: (v) => gl.uniform1i(at, v),
      [gl.BOOL]: (v) => gl.uniform1i(at, v ? 1 : 0),
    }[type];
    if (!set) throw new Error(`setUniforms: the type of uniform ${name} (0x${type.toString(16)}) is not handled`);
    setters.push({ name, set });
  }
  return setters;
}

/**
 * Fetches a vertex and a fragment shader by URL (relative to the page), compiles and links them.
 * @returns {Promise<{program: WebGLProgram}>}
 */
export async function loadProgram(gl, vertexUrl, fragmentUrl) {
  return { program: programFrom(gl, await loadShaders(vertexUrl, fragmentUrl)) };
}
