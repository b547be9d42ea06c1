// The audit unit 'least-s' (s at its least: pow(0, 0) guarded): Sets s to its least and looks for
// the black spots pow(0, 0) leaves on many GPUs; a note (the slides do not ask for s = 0).
import { darkSpots } from '../../measure.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { PERCENT } from '../../units.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'least-s': { title: 's at its least: pow(0, 0) guarded', slide: SLIDE.guardPow, failureTitle: 's at its least shows pow(0, 0)', description: 'Sets s to its least and looks for the black spots pow(0, 0) leaves on many GPUs; a note (the slides do not ask for s = 0).', reads: ['facts.leastS', 'images.judged'] },
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

/** The unit (audits/list.js runs it in its order). */
// s at its least, read in the picture the shading was read in (gather/visible.js)
export const UNIT = unit(META, 'least-s', (context, { 'judged-picture': judged, shading }) => (context.must.has('highlight')
  ? auditLeastShininess(context, { ...judged, img: shading.shadeImg }, shading.shading) : null),
  { uses: ['judged-picture', 'shading'] });
