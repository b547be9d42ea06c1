// What the audits of the normal colours share (units/perspective.js, normals-not-light.js):
// whether the colours decode (2c − 1) to the unit normals of one side of a sphere.

/** The colours decode to unit normals (2c − 1) that vary over the picture as one side of a sphere's do. */
export const smoothUnitNormals = (nc, thresholds) =>
  !!nc &&
  !(
    nc.spread < thresholds.normalsSpread ||
    nc.unitError > thresholds.normalsUnitError ||
    nc.residual > thresholds.facingResidual
  );
