// WP04P5: Phong shading. The same Phong reflection model as WP04P4, evaluated per fragment, with
// the direction vectors normalised again in the fragment shader.
import { lookAt, mat3, mat4, normalMatrix, perspective } from '../common/math.js';
import { sphereMesh } from '../common/sphere.js';
import { loadShaders, programFrom, setUniforms } from '../common/shaders.js';
import { BACKGROUND, EYE_DISTANCE } from '../common/course.js';
import { openStep } from '../common/step.js';
import { STEPS } from '../common/steps.js';
import { run } from '../common/page.js';

async function main() {
  // The page: URL parameters, canvas and context, controls, window.scene (common/step.js; the
  // parameters this step reads: common/steps.js)
  const page = await openStep(STEPS.WP04P5);
  const { gl, canvas, state, camera, scene } = page;
  const shaders = await loadShaders('shader.vert', 'shader.frag');

  // Camera: the eye orbits at radius r in the xz-plane; V follows it in every frame
  const P = perspective(camera.fovy, camera.aspect, camera.near, camera.far);
  const V = mat4();
  const N = mat3();
  // The uniforms by their names in the shaders; kd, Le, ks, s, La are the sliders' own values (state).
  // The light in world space: [x, y, z, w] with w = 0 a direction, w = 1 a point.
  const uniforms = { P, V, N, lightPos: scene.light.position, blinnPhong: false };

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
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.CULL_FACE);
  }

  // A level change refills the one buffer (slide "Replacing an object")
  let numVertices = 0;
  function setLevel(level) {
    const positions = sphereMesh(level);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    numVertices = positions.length / 3;
    return numVertices;
  }

  // ---- set-up ends here; drawing: tick() calls draw() in every animation frame while orbiting ----
  function draw() {
    // e = (r sin α, 0, r cos α); V = lookAt(e, at, up)
    camera.eye[0] = EYE_DISTANCE * Math.sin(state.angle);
    camera.eye[2] = EYE_DISTANCE * Math.cos(state.angle);
    lookAt(camera.eye, camera.at, camera.up, V);
    normalMatrix(V, N); // N = ((V M)^T)^-1 with M = identity
    uniforms.blinnPhong = state.model === 'blinn-phong';
    setUniforms(gl, program, uniforms, state);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.drawArrays(gl.TRIANGLES, 0, numVertices);
  }
  await page.start({ init, setLevel, draw });
}

run(main);
