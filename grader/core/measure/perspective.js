// WP04P1 "Draw a solid sphere in perspective view", read from the normals its colours show. An
// orthographic view shows normals all the way to 90° from the view direction at the rim; a
// perspective view from a distance d (in sphere radii) shows none past acos(1/d), and the normals
// inside are drawn nearer the view direction in proportion. One number, the rim's angle, fitted to
// every decoded normal, not read off the few pixels at the edge.
import { HALF_TURN, RIGHT_ANGLE } from '../units.js';

/** A guard against dividing by (nearly) zero. */
const GUARD = 1e-9;
/** The rim angles searched: 0° to RIM_DEGREES from the view direction (the mechanics of a search). */
const RIM_DEGREES = 45;

const DEG = HALF_TURN / Math.PI;

/**
 * The angle from the view axis of the normal seen at screen radius `rho` (a share of the
 * silhouette's radius), for a unit sphere whose rim is seen `a` radians off the axis (the eye at
 * d = 1/sin a; a = 0 is orthographic). `far`: the inside of the far side shows (culled front faces,
 * the slide's clockwise experiment), its angle taken from the axis pointing away from the eye.
 */
export function normalAngle(rho, a, far = false) {
  const r = Math.min(1, Math.max(0, rho));
  if (a <= 0) return Math.asin(r);
  const d = 1 / Math.sin(a);
  const t = Math.atan(r * Math.tan(a)); // the pixel's ray, off the axis
  const root = Math.sqrt(Math.max(0, 1 - (d * Math.sin(t)) ** 2));
  const k = d * Math.cos(t) + (far ? root : -root); // where the ray meets the sphere
  const lateral = k * Math.sin(t), along = d - k * Math.cos(t);
  return Math.atan2(lateral, far ? -along : along);
}

/**
 * How far the decoded normals reach at the rim: `pts` are samples ({ c, n }: the colour and the
 * orthographic normal's screen position n[0], n[1]) whose colours are 0.5·n + 0.5. The view axis is
 * their mean direction; the rim's angle a is the one (in 0.5° steps up to 45°) whose perspective
 * explains the normals' angles from it best. { rimDegrees (90 − a, or 90 + a on the far side),
 * distance (1/sin a, Infinity when orthographic), rms (degrees), count }, or null with too few.
 */
export function rimAngle(pts, far, thresholds) {
  if (pts.length < thresholds.minFitSamples) return null;
  const axis = [0, 0, 0];
  const dirs = pts.map((s) => {
    const d = s.c.map((v) => 2 * v - 1), len = Math.hypot(...d) || 1;
    const u = d.map((v) => v / len);
    for (let k = 0; k < 3; k++) axis[k] += u[k];
    return u;
  });
  const len = Math.hypot(...axis);
  if (len < GUARD) return null;
  const v = axis.map((x) => x / len);
  const seen = pts.map((s, i) => ({
    rho: Math.hypot(s.n[0], s.n[1]),
    angle: Math.acos(Math.max(-1, Math.min(1, dirs[i][0] * v[0] + dirs[i][1] * v[1] + dirs[i][2] * v[2]))),
  }));
  let best = null;
  for (let deg = 0; deg <= RIM_DEGREES; deg += 0.5) {
    const a = deg / DEG;
    let e = 0;
    for (const s of seen) e += (s.angle - normalAngle(s.rho, a, far)) ** 2;
    if (!best || e < best.e) best = { deg, e };
  }
  return {
    rimDegrees: far ? RIGHT_ANGLE + best.deg : RIGHT_ANGLE - best.deg,
    distance: best.deg > 0 ? 1 / Math.sin(best.deg / DEG) : Infinity,
    rms: DEG * Math.sqrt(best.e / seen.length),
    count: seen.length,
  };
}
