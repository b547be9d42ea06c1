// What the page sent to WebGL as geometry, read where the gathering stands (the page interface's
// geometry(): grader/browser/geometry.js records, grader/browser/mesh.js sums up). A measurement,
// never a decision: the audits in core/audits/geometry.js judge it. A page interface without it
// (an older check page) records nothing.
import { clipMatrix } from '../computed/surface.js';
import { MILLIONTHS } from '../units.js';

/** A fit sample is [px, py, pz, cx, cy, cz, cw]: the position, then gl_Position from CLIP_AT on. */
const CLIP_AT = 3, SAMPLE_LENGTH = 7;

/** The last frame's geometry, summed up within the rubric's sample bounds; null where not recorded. */
export async function readGeometry(session) {
  if (!session.page.geometry) return null;
  session.outOfTime();
  return session.page.geometry({
    maxTriangles: session.thresholds.geometrySampleTriangles,
    maxEdgeTriangles: session.thresholds.geometryEdgeTriangles,
  });
}

/** What the page last sent for its shaders ({ key: digest }: grader/browser/sent.js); null where not recorded. */
export async function readSent(session) {
  if (!session.page.sent) return null;
  session.outOfTime();
  return session.page.sent();
}

/**
 * The surface the last frame drew, per pixel (grader/browser/surface.js): facts (names, box, the
 * clip matrix P·V·M) with its two pictures kept as `surface-normals` and `surface-points` (after
 * `prefix`); { why }
 * where it could not be drawn again; null where the page interface cannot.
 */
export async function readSurface(session, prefix = '') {
  if (!session.page.surface) return null;
  session.outOfTime();
  const r = await session.page.surface({ fitSamples: session.thresholds.surfaceFitSamples });
  if (!r || r.why) return { why: r ? r.why : 'the surface was not read' };
  const { normals, points, fit, ...facts } = r;
  // where the page's matrices put its positions: P·V·M, solved from the fit's samples (16 numbers kept, not the samples)
  const clip = clipMatrix(fit.map((f) => ({ p: f.slice(0, CLIP_AT), clip: f.slice(CLIP_AT, SAMPLE_LENGTH) })));
  if (!clip) return { why: `where the page's matrices put its positions could not be solved from ${fit.length} of its pixels` };
  return {
    ...facts,
    clip: clip.map((row) => row.map((v) => Math.round(v * MILLIONTHS) / MILLIONTHS)),
    normals: session.keep(`${prefix}surface-normals`, normals),
    points: session.keep(`${prefix}surface-points`, points),
  };
}
