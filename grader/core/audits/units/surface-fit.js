// The audit unit 'surface-fit' (The lighting on the page's own surface): Fits the slide's model
// and its known misreadings on each pixel's normal and position as the page drew them; a review
// where a misreading of w_o explains the picture better by the rubric's margin, a note for the
// normal colour kept in the material.
import { SLIDE } from '../slides.js';
import { exactLighting } from '../../computed/lighting.js';
import { unit } from '../unit.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  'surface-fit': { title: 'The lighting on the page\'s own surface', slide: SLIDE.eye, failureTitle: 'A known misreading explains the lighting on the page\'s own surface', description: 'Fits the slide\'s model and its known misreadings on each pixel\'s normal and position as the page drew them: a w_o taken otherwise than the slide\'s (fixed, from the world origin, the view matrix applied twice, its sign) that explains the picture better by the rubric\'s margin is a review, the normal colour kept in the material a note, and a w_o misread a little better than the slide\'s but short of the margin a note that the pictures cannot tell them apart; where the surface could not be read, a note that the lighting was judged on the outline and why.', reads: ['facts.surface', 'images.judged'] },
};

/** How many of the fitted variants the numbers keep: what the report shows, not a bound. */
const VARIANTS_KEPT = 8;

const fmt = (x) => x.toFixed(3);

/** Each known misreading of w_o (measure/surface-fit.js's VIEW), in a student's words. */
export const VIEW_WORDS = {
  'fixed at the eye space\'s (0, 0, 1)': 'w_o is one direction for the whole sphere (the eye space\'s (0, 0, 1)), not normalize(e − p) at each point',
  'from the world origin (−p)': 'w_o points from the point to the world\'s origin, not to the eye (normalize(e − p))',
  'with the view matrix applied twice': 'w_o is built with the view matrix applied twice (−normalize(V·(V·p)) in the eye\'s space), not −normalize(V·p)',
  'pointing away from the eye (its sign)': 'w_o points away from the eye, not toward it (normalize(p − e), not normalize(e − p))',
};

/** Does the best fit take w_o otherwise than the slide does? */
export const misread = (best) => !!best.view && best.view !== 'the slide';

/** What a variant means, in a student's words. */
function inWords(best) {
  const out = [];
  if (best.tint === 'added') out.push('the colour carries WP04P1\'s normal colour 0.5·n + 0.5 added to the lighting');
  if (best.tint === 'times') out.push('the lighting is coloured by WP04P1\'s normal colour 0.5·n + 0.5 (the material is the normal colour)');
  if (misread(best)) out.push(VIEW_WORDS[best.view]);
  if (!best.form) out.push('no highlight is needed to explain it');
  return out.join('; ');
}

/**
 * Says which misreading the page's own surface shows, where one explains the picture better than
 * the slide's formula (a w_o misread: a mistake; the normal colour in the material: a note); or that
 * the lighting was judged on the outline, and why.
 */
export function auditSurfaceFit({ sayAs, must = new Set(['highlight']), thresholds = {} }, exact) {
  const say = sayAs('surface-fit');
  if (exact && exact.why) {
    say('pass', `note: the lighting was judged on the outline (a sphere assumed from the silhouette), not on the page's own surface: ${exact.why}`);
    return;
  }
  if (!exact || !exact.slide) return;
  const { best, slide } = exact;
  // where a highlight is asked for and fitted, a w_o misread that explains the picture clearly better
  // than the slide's w_o (surfaceCloserShare of its residual), short of the margin: the pictures
  // cannot tell them apart (said, never judged)
  const closer = must.has('highlight') && best.form && !misread(best) && (exact.variants || [])
    .find((v) => v.view && v.view !== 'the slide' && v.rms <= thresholds.surfaceCloserShare * best.rms);
  if (closer) say('pass', `note: on the page's own surface, a w_o misread explains the picture a little better than the slide's w_o (${VIEW_WORDS[closer.view]}: a residual of ${fmt(closer.rms)}, against ${fmt(best.rms)}), by less than the rubric's margin: the pictures cannot tell them apart`);
  if (best.name === slide.name) return;
  // a misreading of w_o that explains the picture better by the rubric's margin is a mistake; the
  // normal colour kept in the material or added is the page's choice of material: a note
  const said = `on the page's own surface (its normals and positions as it drew them), ${inWords(best)}: that explains the picture with a residual of ${fmt(best.rms)}, the slide's formula with ${fmt(slide.rms)}`;
  if (misread(best)) say('mistake', `${said} (w_o = normalize(e − p), from the point to the eye, in the space of n and w_i)`);
  else say('pass', `note: ${said}`);
}

/**
 * The lighting fitted on the page's own surface (its normals and positions as it drew them):
 * evidence in the numbers, and the note; returns the fit (exactLighting's: null, { why } or the
 * fit) for the units after it.
 */
function auditLightingOnSurface(context, results) {
  const exact = context.litStep ? exactLighting(context.facts, context.images, results['judged-picture'], context.thresholds) : null;
  if (exact) {
    context.numbers.surfaceFit = exact.why
      ? { why: exact.why }
      : {
          samples: exact.samples,
          diffuse: exact.diffuse,
          slide: exact.slide,
          best: exact.best,
          variants: exact.variants.slice(0, VARIANTS_KEPT),
        };
  }
  auditSurfaceFit(context, exact);
  return exact;
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'surface-fit', auditLightingOnSurface, { uses: ['judged-picture'] });
