// s at its least (the Phong term with s = 0 is pow(0, 0) where cos φ ≤ 0: undefined, black on
// many GPUs; a note, since the slides do not ask for s = 0), and WP04P5's shading per fragment,
// seen at a coarse level.
import { analyse, darkSpots, shadingChange, unnormalisedInputs } from '../measure.js';
import { fmt } from '../format.js';
import { SLIDE } from './slides.js';
import { unit } from './unit.js';
import { PERCENT } from '../units.js';

/** This module's audits: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'least-s': { title: 's at its least: pow(0, 0) guarded', slide: SLIDE.guardPow, failureTitle: 's at its least shows pow(0, 0)', description: 'Sets s to its least and looks for the black spots pow(0, 0) leaves on many GPUs; a note (the slides do not ask for s = 0).', reads: ['facts.leastS', 'images.judged'] },
  'per-fragment': { title: 'The Phong model per fragment, its vectors normalised there', slide: SLIDE.phongShading, failureTitle: 'Not the Phong model per fragment', description: 'Compares a coarse level\'s shading with a fine one\'s, and reads the fragment shader for the vectors normalised there.', reads: ['facts.ladder', 'facts.sources', 'images.judged', 'facts.judgedLevel', 'facts.level', 'facts.stopped', 'facts.viewMoved'] },
};

/** The picture at the least s against the judged one (`judged`: { img, an }; the same view). */
export function auditLeastShininess({ facts, images, thresholds, sayAs, numbers, imagesShown }, judged, shading) {
  const say = sayAs('least-s');
  const least = facts.leastS;
  if (!least || !shading || !shading.fit) return;
  const after = images[least.image];
  const { img, an } = judged;
  if (after.width !== img.width || after.height !== img.height) return;
  const fit = shading.judgedFit.tint ? shading.judgedFit.tint.plain : shading.judgedFit; // the picture's own brightness, not a de-tinted one
  const spots = darkSpots(img, an, after, fit, thresholds);
  if (!spots) return;
  numbers.darkSpotsAtLeastS = spots;
  imagesShown.leastS = least.image;
  // the slides do not ask for s = 0: the spots are worth telling the student, as a note
  if (spots.share >= thresholds.darkSpotShare && spots.count >= thresholds.darkSpotCount) {
    say('pass', `note: s = ${least.value} gives black spots inside the sphere (${fmt(PERCENT * spots.share, 1)}% of it darker than diffuse + ambient): pow(0, 0) is undefined (black on many GPUs); guard it (e.g. cos φ > 0 ? pow(cos φ, s) : 0)`);
  } else say('pass', `s = ${least.value} leaves no dark spots inside the sphere (pow(0, 0) guarded)`);
}

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

/** P5: the highlight per fragment: as smooth at a coarse level as at the finest; else pow() in the fragment shader. */
export function auditPerFragment({ facts, images, thresholds, must, sayAs, numbers, imagesShown }, judged, shading) {
  const say = sayAs('per-fragment');
  if (!must.has('per-fragment') || !shading || !shading.fit) return;
  const raw = facts.sources ? unnormalisedInputs(facts.sources) : [];
  if (raw.length) say('mistake', `the fragment shader takes the interpolated ${raw.join(' and ')} into dot() or reflect() without normalising ${raw.length > 1 ? 'them' : 'it'}: interpolated directions are shorter than 1 between the vertices (the slides: "most importantly, we must normalize the direction vectors in the fragment shader")`);
  const j = facts.judgedLevel;
  const coarseAt =
    facts.stopped && !facts.viewMoved
      ? facts.ladder.findIndex((s, k) => k !== j && !s.blank && s.roundness < thresholds.coarseRoundness && s.image)
      : -1;
  const coarse = coarseAt >= 0 ? images[facts.ladder[coarseAt].image] : null;
  if (coarse && coarse.width === judged.img.width) {
    const change = shadingChange(coarse, analyse(coarse, thresholds), judged.img, judged.raw, thresholds);
    numbers.coarseShadingChange = change;
    imagesShown.coarse = facts.ladder[coarseAt].image;
    const r = analyse(coarse, thresholds).roundness;
    if (change !== null && change <= thresholds.phongCoarseChange) say('pass', `the shading at a coarse level (roundness ${fmt(r)}) stays as smooth as at the finest (RMS ${fmt(change, 3)}): per fragment`);
    else say('mistake', `the highlight follows the triangles at a coarse level (RMS ${fmt(change, 3)} from the finest): shading is per vertex, not per fragment (or the normals are not re-normalised in the fragment shader)`);
  } else if (fragmentPow(facts.sources)) say('pass', `no coarse level to compare${facts.level.coarsen ? '' : ' (nothing found that coarsens)'}; the fragment shader evaluates the specular term (pow): per fragment`);
  else say('mistake', 'no coarse level to compare, and no pow() in the fragment shader: the model seems evaluated per vertex');
}

/** This module's audit units (audits/list.js runs them in its order). */
export const UNITS = [
  // s at its least, read in the picture the shading was read in (gather/visible.js)
  unit(META, 'least-s', (context, { 'judged-picture': judged, shading }) => (context.must.has('highlight')
    ? auditLeastShininess(context, { ...judged, img: shading.shadeImg }, shading.shading) : null),
    { uses: ['judged-picture', 'shading'] }),
  unit(META, 'per-fragment', (context, results) => auditPerFragment(context, results['judged-picture'], results.shading.shading), { uses: ['judged-picture', 'shading'] }),
];
