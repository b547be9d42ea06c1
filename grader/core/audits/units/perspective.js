// The audit unit 'perspective' (In perspective view (how far the normals reach at the rim)):
// Measures how far the normals the colours show reach at the rim: 90° in an orthographic view,
// less in perspective.
import { samples } from '../../measure.js';
import { rimAngle } from '../../measure/perspective.js';
import { fmt } from '../../format.js';
import { SLIDE } from '../slides.js';
import { unit } from '../unit.js';
import { RIGHT_ANGLE } from '../../units.js';
import { smoothUnitNormals } from '../normals.js';

/** The audit this unit says: id → title, the slide's sentence it checks, the artifacts it reads. */
export const META = {
  perspective: { title: 'In perspective view (how far the normals reach at the rim)', slide: SLIDE.sphere, note: 'an orthographic view shows the normals out to 90° at the rim', failureTitle: 'Not in perspective view', description: 'Measures how far the normals the colours show reach at the rim: 90° in an orthographic view, less in perspective.', reads: ['images.judged'] },
};

/**
 * WP04P1/P2: "Draw a solid sphere in perspective view". Where the colours decode to the normals of
 * one side of the sphere (`seen`: what auditNormals read), the rim's angle tells the projection: an
 * orthographic view shows normals out to 90° from the view direction, a perspective view from a
 * distance d none past acos(1/d). Where front and back faces mix, the picture cannot tell: not said.
 */
export function auditPerspective({ thresholds, must, sayAs, numbers }, seen) {
  const say = sayAs('perspective');
  if (!must.has('perspective') || !seen || !seen.nc) return;
  const { img, an, nc } = seen;
  if (!smoothUnitNormals(nc, thresholds)) return;
  const far = nc.det < 0;
  if (!far && nc.det < thresholds.facingDeterminant) return;
  const rim = rimAngle(samples(img, an, thresholds, { maxRho: thresholds.rimSampleRadius }), far, thresholds);
  if (!rim || rim.rms > thresholds.perspectiveFitDegrees) return;
  numbers.perspective = rim;
  const short = Math.abs(RIGHT_ANGLE - rim.rimDegrees);
  const side = far ? 'the inside of the far side, whose normals' : 'the normals';
  if (short >= RIGHT_ANGLE - thresholds.orthographicRimDegrees) {
    say('pass', `in perspective view: ${side} reach ${fmt(rim.rimDegrees, 0)}° from the view direction at the rim, an eye about ${fmt(rim.distance, 1)} sphere radii from the centre (acos(1/d) = ${fmt(RIGHT_ANGLE - short, 0)}°; an orthographic view reaches 90°)`);
  } else {
    say('mistake', `not in perspective view (the slide: "Draw a solid sphere in perspective view"): ${side} reach ${fmt(rim.rimDegrees, 0)}° from the view direction at the rim, as an orthographic view shows them (90°); a perspective view from a distance d shows none past acos(1/d) (71° at d = 3): an orthographic projection, or an eye so far away that it looks the same?`);
  }
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META, 'perspective', (context, results) => auditPerspective(context, results['normal-colours']), { uses: ['normal-colours'] });
