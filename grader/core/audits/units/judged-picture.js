// The audit unit 'judged-picture': the picture judged at the judged level (the sphere's picture
// for the audits after it); a part whose picture went blank after the controls were used ends
// here, said as 'sphere' (units/sphere.js).
import { sphereView } from '../../computed/evidence.js';
import { analyse } from '../../measure.js';
import { unit, end } from '../unit.js';
import { META as META_SPHERE } from './sphere.js';

/**
 * The judged picture (the level judged, as facts.judged names it) and its sphere's outline ({ img,
 * an, raw, circleArc }, for the units that use it), or the end of the judging where it is blank.
 */
function judgedPicture({ facts, images, thresholds, imagesShown }) {
  imagesShown.judged = facts.facesImage || facts.judged;
  const img = images[facts.judged];
  const raw = analyse(img, thresholds);
  if (raw.blank) return end('the picture went blank after the controls were used', 'sphere');
  const { an, circleArc } = sphereView(img, thresholds);
  return { img, an, raw, circleArc };
}

/** The unit (audits/list.js runs it in its order). */
export const UNIT = unit(META_SPHERE, 'judged-picture', judgedPicture,
  { says: ['sphere'], reads: ['facts.judged', 'facts.facesImage'] });
