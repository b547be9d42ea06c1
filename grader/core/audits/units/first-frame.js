// The audit unit 'first-frame' (The page draws its first frame): Waits for the page's first frame
// (frames run once nothing it awaits is pending) and reads the canvas back.
import { analyse, drawnPixels } from '../../measure.js';
import { SLIDE } from '../slides.js';
import { unit, end } from '../unit.js';

/** The audits this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'first-frame': { title: 'The page draws its first frame', slide: SLIDE.sphere, failureTitle: 'The page draws no visible first frame', description: 'Waits for the page\'s first frame (frames run once nothing it awaits is pending) and reads the canvas back (a page that draws nothing, with no error, is started first by a control named for starting it: a note); a page that draws only lines shows a wireframe, not a solid sphere (a mistake).', reads: ['facts.first', 'images.first', 'facts.errors'] },
  'shaders-compile': { title: 'The shaders compile and link', slide: SLIDE.uniforms, note: 'the shaders must compile first: the error above gives the line', failureTitle: 'A shader does not compile or link', description: 'Reads every shader\'s compile and link status (WebGL) and compilation messages (WebGPU), with the line of the error.', reads: ['facts.first'] },
  'webgpu-adapter': { title: 'WebGPU starts', slide: SLIDE.sphere, note: 'this browser has no WebGPU adapter: try the WebGL view, or a browser with WebGPU', failureTitle: 'WebGPU did not start', description: 'The page asked for a WebGPU adapter and got none.', reads: ['facts.first'] },
};

/** auditFirstFrame's answer where it has said why nothing more is judged, and the part is not broken. */
export const STOP = Symbol('nothing more to judge');

/**
 * Says the shader and adapter failures; returns the reason the part cannot be judged (it fails:
 * the audit 'first-frame''s), STOP, or null.
 */
export function auditFirstFrame({ facts, images, thresholds, sayAs }) {
  const say = sayAs('first-frame');
  const g = facts.first;
  if (!g) return 'the page never finished its first frame';
  if (!images.first) return 'no canvas on the page';
  for (const e of g.shaderErrors) sayAs('shaders-compile')('fail', e);
  if (g.api === 'webgpu' && g.adapter === null) sayAs('webgpu-adapter')('fail', 'no WebGPU adapter: the page could not start WebGPU');
  if (!analyse(images.first, thresholds).blank) {
    if (g.startedBy) say('pass', `note: the page drew nothing until ${g.startedBy} was clicked; the grader clicked it first, as a teacher would, and judged the page from there`);
    if (g.orbitStarted) say('pass', `note: the canvas stayed one colour${g.waited ? ` for ${g.waited} frames more` : ''} (the unlit side toward the camera?); the orbit, started by ${g.orbitStarted}, showed the sphere, and it was judged from there`);
    return null;
  }
  const why = g.shaderErrors[0] || g.gpuErrors[0] || facts.errors.find((e) => /page error|dialog/.test(e));
  if (!g.api) return `drew nothing: the page never got a WebGL or WebGPU context${why ? ` (${why})` : ''}`;
  if (!g.draws) return `drew nothing: the canvas is one colour, no draw call${why ? ` (${why})` : ''}`;
  const waited = g.waited ? ` after ${g.waited} frames more` : '';
  const geo = g.blankGeometry;
  if (wireframe(geo, images.first, thresholds, say, waited)) return STOP;
  // triangles that reach the canvas draw something, even where it cannot be seen: not broken
  if (geo && !geo.why && geo.analysed > 0 && geo.degenerate < 1 && !why) {
    say('mistake', `nothing can be seen: the page draws ${geo.triangles} triangles (${g.draws} draw calls), but the canvas stays one colour${waited} (a sphere the colour of the background, or drawn outside the view?); nothing else was judged`);
    return STOP;
  }
  return `drew nothing visible: the canvas is one colour${waited}${why ? ` (${why})` : ''}`;
}

/**
 * The slide's WP04P1 asks for a solid sphere: a page that draws lines only (gl.LINES, LINE_LOOP,
 * LINE_STRIP; WebGPU's line topologies) shows a wireframe, which is blank to the silhouette (thin
 * lines are opened away) but not one colour. Said as a mistake (true where it is); nothing else is judged.
 */
function wireframe(geo, img, thresholds, say, waited) {
  if (!geo || geo.triangles > 0 || !(geo.lineVertices > 0)) return false;
  const an = analyse(img, thresholds);
  const drawn = drawnPixels(img, an.bg, thresholds.backgroundTolerance);
  if (an.oneColour || drawn.pixels === 0) return false;
  const colour = drawn.spread <= thresholds.oneColourSpread ? ', all in one colour (not 0.5·n + 0.5)' : '';
  say('mistake', `a wireframe, not a solid sphere: the page draws only lines (${geo.lineVertices} vertices in ${geo.draws} draw calls, no gl.TRIANGLES), and the canvas${waited} shows ${drawn.pixels} pixels of them${colour}; nothing else was judged`);
  return true;
}

/** The unit (audits/list.js runs it in its order). */
// a part that drew nothing ends here; where what the grader read is not what a student sees
// (shown-channels), the review stands and nothing is failed on it
export const UNIT = unit(META, 'first-frame', (context, results) => {
  const fail = auditFirstFrame(context);
  if (fail === STOP) return end();
  if (fail) return results['shown-channels'] ? end() : end(fail, 'first-frame');
  return null;
}, { also: ['shaders-compile', 'webgpu-adapter'], uses: ['shown-channels'] });
