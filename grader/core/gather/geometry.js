// What the page sent to WebGL as geometry, read where the gathering stands (the page interface's
// geometry(): grader/browser/geometry.js records, grader/browser/mesh.js sums up). A measurement,
// never a decision: the audits in core/audits/geometry.js judge it. A page interface without it
// (an older check page) records nothing.

/** The last frame's geometry, summed up within the rubric's sample bounds; null where not recorded. */
export async function readGeometry(S) {
  if (!S.page.geometry) return null;
  S.outOfTime();
  return S.page.geometry({ maxTriangles: S.T.geometrySampleTriangles, maxEdgeTriangles: S.T.geometryEdgeTriangles });
}

/** What the page last sent for its shaders ({ key: digest }: grader/browser/sent.js); null where not recorded. */
export async function readSent(S) {
  if (!S.page.sent) return null;
  S.outOfTime();
  return S.page.sent();
}

/**
 * The surface the last frame drew, per pixel (grader/browser/surface.js): facts (names, box, the
 * fit's samples) with its two pictures kept as `surface-normals` and `surface-points`; { why } where
 * it could not be drawn again; null where the page interface cannot.
 */
export async function readSurface(S) {
  if (!S.page.surface) return null;
  S.outOfTime();
  const r = await S.page.surface({ fitSamples: S.T.surfaceFitSamples });
  if (!r || r.why) return { why: r ? r.why : 'the surface was not read' };
  const { normals, points, ...facts } = r;
  return { ...facts, normals: S.keep('surface-normals', normals), points: S.keep('surface-points', points) };
}
