// What the audits of the page's own geometry share (units/closed.js, per-face.js, winding.js):
// the geometry judged, read from what the page sent (gather/geometry.js records it).

/** The geometry judged: the judged level's, else the first level's (where the page went blank later). */
export const judgedGeometry = (facts) =>
  [facts.geometry, facts.geometryAtFirst].find((g) => g && !g.why && g.analysed > 0) || null;
