// The grader's reference is the exact render of the scene our page shows for a query
// (grader/core/reference-state.js, referenceScene): here each of our steps is opened with such
// queries and its own window.scene, as it published it after drawing, must be the scene the grader
// builds, field for field (the frame and the vertex count aside: the grader draws no mesh).
import { test, expect } from '@playwright/test';
import { referenceQuery, referenceScene } from '../../grader/core/reference-state.js';
import { STEPS } from '../../common/steps.js';

const T = { nearPointDistance: 0 }; // (no point light fitted here: referenceLight reads the fit alone)

// the queries the grader asks: a canvas (square or not), a fitted light (or none), the rubric's extras
const QUERIES = [
  { size: { width: 96, height: 96 }, numbers: {}, extra: {} },
  { size: { width: 120, height: 80 }, numbers: { fit: { light: [0.3, 0.5, 0.81] } }, extra: {} },
  { size: { width: 64, height: 100 }, numbers: { fit: { light: [-0.6, 0, 0.8] } }, extra: { model: 'blinn-phong', s: 12, angle: 0.7 } },
  { size: { width: 80, height: 80 }, numbers: {}, extra: { light: 'point', lx: 0.5, ly: 1, lz: 2.5, Le: 4 } },
];

for (const part of Object.keys(STEPS)) {
  test(`${part}: its window.scene is the scene the grader renders as our reference`, async ({ page }) => {
    for (const q of QUERIES) {
      const query = referenceQuery(q.size, q.numbers, T, q.extra);
      await page.goto(`/${part}/index.html?${query}`);
      await page.waitForFunction(() => window.scene && window.scene.frame >= 1);
      const published = await page.evaluate(() => {
        const { frame, vertices, ...rest } = window.scene; // eslint-disable-line no-unused-vars -- left out
        return JSON.parse(JSON.stringify(rest));
      });
      const built = referenceScene(part, query);
      expect(JSON.parse(JSON.stringify(built.scene)), `${part}?${query}`).toEqual(published);
      expect([built.width, built.height], 'the canvas it draws').toEqual(await page.evaluate(() => {
        const c = document.getElementById('gl-canvas');
        return [c.width, c.height];
      }));
    }
  });
}
