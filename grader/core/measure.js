// Judging a picture by the properties of the slide's step, not by its pixels against ours:
// students pick their own camera, canvas, background, light and material. An image is
// { width, height, data } (RGBA bytes). Everything here is plain arithmetic, no browser.
// The measurements live in measure/, one concern a module; this file gathers them for importers.
import { analyse as analyseOnce } from './measure/silhouette.js';
import { memo } from './computed/memo.js';

/** A picture's silhouette (measure/silhouette.js), read once a picture and rubric. */
export const analyse = memo(analyseOnce);
export { openMask, fitCircle } from './measure/silhouette.js';
export { samples, perspectiveSamples } from './measure/samples.js';
export { normalColours, facesViewer } from './measure/normals.js';
export { diffuseFit } from './measure/diffuse.js';
export { hueByNormal, tintedByNormal, detintedFit, shadeFit } from './measure/tint.js';
export { addedTintFit, addedClearly } from './measure/tint-added.js';
export { highlightOf, highlightOffset, highlightSeen } from './measure/highlight.js';
export { silhouetteChange, outlineFlips, shadingChange, pictureChange } from './measure/change.js';
export { pointLightFit, pointLightPredict, highlightAbove, nearPointLight, clearlyBetter, clearlyNearFalloff } from './measure/point-light.js';
export { darkSpots } from './measure/dark-spots.js';
export { unnormalisedInputs } from './measure/fragment-normals.js';
export { drawnPixels } from './measure/drawn.js';
