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
