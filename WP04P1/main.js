// WP04P1: a solid sphere in perspective; Subdivide / Coarsen refill one recycled vertex buffer.
import { lookAt, perspective } from '../common/math.js';
import { sphereMesh } from '../common/sphere.js';
import { loadShaders, programFrom, setUniforms } from '../common/shaders.js';
import { BACKGROUND } from '../common/course.js';
import { openStep } from '../common/step.js';
import { STEPS } from '../common/steps.js';
import { run } from '../common/page.js';

async function main() {
  // The page: URL parameters, canvas and context, controls, window.scene (common/step.js; the
  // parameters this step reads: common/steps.js)
  const page = await openStep(STEPS.WP04P1);
  const { gl, canvas, camera } = page;
  const shaders = await loadShaders('shader.vert', 'shader.frag');

  // Camera: a perspective view of the unit sphere from 3 units along the +z axis
  const P = perspective(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = lookAt(camera.eye, camera.at, camera.up);
  const uniforms = { P, V };

  // GL set-up: the program and the one vertex buffer. It runs once; again only if the browser
  // restores a lost context.
  let program;
  function init() {
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(...BACKGROUND);
    program = programFrom(gl, shaders);
    gl.useProgram(program);
    const aPosition = gl.getAttribLocation(program, 'aPosition');
    const vBuffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vBuffer);
    gl.vertexAttribPointer(aPosition, 3, gl.FLOAT, false, 0, 0);
    gl.enableVertexAttribArray(aPosition);
  }

  // A level change refills the one buffer (slide "Replacing an object")
  let numVertices = 0;
  function setLevel(level) {
    const positions = sphereMesh(level);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    numVertices = positions.length / 3;
    return numVertices;
  }

  // ---- set-up ends here; drawing (on demand: nothing moves) ----
  function draw() {
    setUniforms(gl, program, uniforms);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLES, 0, numVertices);
  }
  await page.start({ init, setLevel, draw });
}

run(main);
