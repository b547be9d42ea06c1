// The measured table chooseLevel rests on (common/shading-table.js, written by npm run calibrate),
// re-measured entry by entry; and the level hint the lighting steps show beside the level, held to
// what the page really draws.
import { test, expect, open, andDraw, errorAgainstReference } from './fixtures.js';
import { compareShading, measureShading, openBenchPage, SHININESS } from '../../tools/calibrate.js';
import { MAX_LEVEL, SHININESS as TABLE_SHININESS, chooseLevel } from '../../common/sphere.js';
import { SHADING_BY_SIZE } from '../../common/shading-table.js';

// SHADING_TABLE, which chooseLevel reads, is the largest of SHADING_BY_SIZE's sizes, entry by
// entry; the pixels are deterministic here, so every entry measured measures to the digit
// (±0.02/255, its rounding). Every entry at 128 px, the size the browser tests draw the steps at;
// at 256 and 512 px, where an entry costs four and sixteen times as much, every level of
// the diffuse row and of s = 0, 40 and 500 (the slider's least, the steps' default, its greatest):
// a change to a shader moves those too. `npm run calibrate -- --check` measures every entry of
// every size.
const SAMPLED = { 256: [0, 40, 500], 512: [0, 40, 500] };
for (const size of Object.keys(SHADING_BY_SIZE).map(Number)) {
  const shininess = SAMPLED[size] || SHININESS;
  test(`${shininess === SHININESS ? 'every entry' : `the diffuse row and s = ${shininess.join(', ')}`} of the shading table at ${size} px: what the step's shaders measure`, async ({ browser, api, baseURL }) => {
    test.skip(api !== 'webgl2', 'the table holds what the shaders draw; the APIs are held equal elsewhere');
    // a bound against a hang, not a speed test (all sizes took 72 s on the quiet machine, and ran
    // past 180 s while the machine graded a class beside it)
    test.setTimeout(600_000);
    const page = await openBenchPage(browser, baseURL, size);
    const levels = Array.from({ length: MAX_LEVEL + 1 }, (_, l) => l);
    const measured = await measureShading(page, size, shininess, levels);
    await page.close();
    expect(TABLE_SHININESS).toEqual(SHININESS);
    expect(compareShading(measured, SHADING_BY_SIZE[size], { shininess }), 'entries that differ from the measurement').toEqual([]);
  });
}

test.describe('the level hint beside the level', () => {
  test.beforeEach(({ api }) => test.skip(api !== 'webgl2', 'the same hint in every API; once is enough'));

  test('WP04P4 says which level its material needs, and the page shades within 1/255 there and not one level less', async ({ page }) => {
    const shadingError = async () => (await errorAgainstReference(page, { interior: 'both' })).rmse * 255;
    await open(page, '/WP04P4/', { orbit: 0, angle: 0, size: 128, s: 40, level: 7 });
    // at 128 px the silhouette needs level 5; the highlight of s = 40 under Gouraud shading needs 6
    expect(chooseLevel(128, 45, 3, { shading: 'gouraud', shininess: 40 })).toMatchObject({ level: 6, limit: 'shading' });
    await expect(page.locator('#info')).toContainText('level 6 is enough for s = 40 at 128 px');
    await andDraw(page, () => page.getByRole('button', { name: 'Coarsen' }).click());
    await expect(page.locator('#info')).toContainText('the least level that looks round at 128 px and shades within 1/255');
    expect(await shadingError()).toBeLessThanOrEqual(1);
    await andDraw(page, () => page.getByRole('button', { name: 'Coarsen' }).click());
    await expect(page.locator('#info')).toContainText('level 5 · 12,288 vertices (s = 40 needs level 6 at 128 px to shade within 1/255)');
    expect(await shadingError()).toBeGreaterThan(1);
    // a broader highlight: s = 10 needs only level 5; the level itself is left as it is
    expect(chooseLevel(128, 45, 3, { shading: 'gouraud', shininess: 10 })).toMatchObject({ level: 5, limit: 'silhouette' });
    await andDraw(page, () => page.locator('#s').fill('10'));
    await expect(page.locator('#info')).toContainText('level 5 · 12,288 vertices (the least level that looks round at 128 px and shades within 1/255)');
    expect(await shadingError()).toBeLessThanOrEqual(1);
    await andDraw(page, () => page.getByRole('button', { name: 'Coarsen' }).click());
    await expect(page.locator('#info')).toContainText('level 5 is the least that looks round at 128 px');
    // s = 0: a hard edge no level shades within 1/255
    await andDraw(page, () => page.locator('#s').fill('0'));
    await expect(page.locator('#info')).toContainText(`no level shades s = 0 within 1/255 at 128 px: level ${MAX_LEVEL} is`);
  });
});
