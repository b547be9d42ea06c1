// The audit unit 'per-fragment' (The Phong model per fragment, its vectors normalised there):
// Reads a coarse level on the page's own surface, else compares a coarse level's shading with a
// fine one's on the pictures, and reads the fragment shader for the vectors normalised there.
import { analyse, shadingChange, unnormalisedInputs } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { coarseReading } from '../../computed/coarse-reading.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'per-fragment': { title: 'The Phong model per fragment, its vectors normalised there', slide: SLIDE.phongShading, failureTitle: 'Not the Phong model per fragment', description: 'Reads a coarse level on the page\'s own surface (the judged picture\'s model evaluated at each pixel: what the level adds to its residual), else compares a coarse level\'s shading with a fine one\'s on the pictures, and reads the fragment shader for the vectors normalised there; a page whose own checkbox or radio button for per-fragment shading starts unticked has it set first (a note); a page that shows the sphere in several canvases of one size is judged on the one named for per-fragment shading, or the one not named for Gouraud shading beside one that is (a note).', reads: ['facts.ladder', 'facts.sources', 'images.judged', 'facts.judgedLevel', 'facts.level', 'facts.stopped', 'facts.viewMoved', 'facts.perFragmentSet', 'facts.canvases', 'facts.coarseSurface', 'facts.surface'] },
};

/** The fragment shader's own code (GLSL writing a colour, or WGSL's @fragment and what it calls): does it call pow()? */
export function fragmentPow(sources) {
  const fs = sources.glsl.filter((s) => /gl_FragColor|out\s+vec4/.test(s) && !/gl_Position/.test(s));
  const wg = sources.wgsl.map((s) => {
    const body = s.split(/@fragment/)[1] || '';
    const called = [...body.matchAll(/([A-Za-z_]\w*)\s*\(/g)].map((m) => m[1]);
    return body + called.map((name) => (s.split(new RegExp(`fn\\s+${name}\\s*\\(`))[1] || '').split(/\n}\s*\n/)[0]).join('\n');
  });
  return [...fs, ...wg].some((s) => /pow\s*\(/.test(s));
}

/**
 * Per fragment, from the coarse level's reading on the page's own surface (computed/coarse-reading.js):
 * { added, perFragment }. What the coarse level adds to the judged picture's residual, in quadrature
 * (the model's own misfit is in both): per fragment where it stays under a visible residual
 * (surfaceResidual); per vertex, the colour interpolated between the vertices is not the model at
 * the pixel, most of all at the highlight.
 */
export function perFragmentOnSurface(reading, thresholds) {
  const added = Math.sqrt(Math.max(0, reading.rms ** 2 - reading.judgedRms ** 2));
  return { added, perFragment: added <= thresholds.surfaceResidual };
}

/**
 * P5: the highlight per fragment: the coarse level read on the page's own surface, else as smooth
 * at a coarse level as at the finest on the pictures; else pow() in the fragment shader.
 */
export function auditPerFragment(context, judged, shading, exact) {
  const { facts, images, thresholds, must, sayAs, numbers, imagesShown } = context;
  const say = sayAs('per-fragment');
  if (!must.has('per-fragment') || !shading || !shading.fit) return;
  if (facts.canvases) say('pass', `note: the page shows the sphere in ${facts.canvases.largest} canvases of one size; the grader judged ${facts.canvases.judged}, ${facts.canvases.why}`);
  if (facts.perFragmentSet) say('pass', `note: the page starts without per-fragment shading; its own control for it (${facts.perFragmentSet}) was set first, as the step asks, and the part judged from there`);
  const raw = facts.sources ? unnormalisedInputs(facts.sources) : [];
  if (raw.length) say('mistake', `the fragment shader takes the interpolated ${raw.join(' and ')} into dot() or reflect() without normalising ${raw.length > 1 ? 'them' : 'it'}: interpolated directions are shorter than 1 between the vertices (the slides: "most importantly, we must normalize the direction vectors in the fragment shader")`);
  const j = facts.judgedLevel;
  const coarseAt =
    facts.stopped && !facts.viewMoved
      ? facts.ladder.findIndex((s, k) => k !== j && !s.blank && s.roundness < thresholds.coarseRoundness && s.image)
      : -1;
  const coarse = coarseAt >= 0 ? images[facts.ladder[coarseAt].image] : null;
  const onSurface = coarseReading({ facts, images, thresholds }, { exact, judged: judged.img }, coarseAt, coarse);
  if (onSurface) numbers.coarseSurface = onSurface;
  if (onSurface && !onSurface.why) {
    imagesShown.coarse = facts.ladder[coarseAt].image;
    const d = perFragmentOnSurface(onSurface, thresholds), r = analyse(coarse, thresholds).roundness;
    const read = `the slide's model evaluated at each pixel, with the judged picture's light and material on the page's own normals and positions, leaves a residual of ${fmt(onSurface.rms, 3)} on the picture at a coarse level (roundness ${fmt(r)}), ${fmt(onSurface.judgedRms, 3)} at the finest: the level adds ${fmt(d.added, 3)}`;
    if (d.perFragment) say('pass', `${read}, less than a visible ${thresholds.surfaceResidual}: per fragment, read on the page's own surface`);
    else say('mistake', `${read}, past a visible ${thresholds.surfaceResidual}: the highlight follows the triangles at a coarse level; shading is per vertex, not per fragment (or the normals are not re-normalised in the fragment shader), read on the page's own surface`);
  } else if (coarse && coarse.width === judged.img.width) {
    const change = shadingChange(coarse, analyse(coarse, thresholds), judged.img, judged.raw, thresholds);
    numbers.coarseShadingChange = change;
    imagesShown.coarse = facts.ladder[coarseAt].image;
    const r = analyse(coarse, thresholds).roundness;
    const where = onSurface ? ` (on the pictures: the page's own surface at that level cannot say: ${onSurface.why})` : '';
    if (change !== null && change <= thresholds.phongCoarseChange) say('pass', `the shading at a coarse level (roundness ${fmt(r)}) stays as smooth as at the finest (RMS ${fmt(change, 3)}): per fragment${where}`);
    else say('mistake', `the highlight follows the triangles at a coarse level (RMS ${fmt(change, 3)} from the finest): shading is per vertex, not per fragment (or the normals are not re-normalised in the fragment shader)${where}`);
  } else if (fragmentPow(facts.sources)) say('pass', `no coarse level to compare${facts.level.coarsen ? '' : ' (nothing found that coarsens)'}; the fragment shader evaluates the specular term (pow): per fragment`);
  else say('mistake', 'no coarse level to compare, and no pow() in the fragment shader: the model seems evaluated per vertex');
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'per-fragment',
  (context, results) => auditPerFragment(context, results['judged-picture'], results.shading.shading, results['surface-fit']),
  { uses: ['judged-picture', 'shading', 'surface-fit'] });
