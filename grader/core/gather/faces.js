// P2, feeding audits/normals.js (front-faces) and its depth-culling audit: the page's own depth,
// culling and winding controls set as the step ends, a frame with culling off, and the depth test and
// culling as the page set them.
import { samples, normalColours, facesViewer } from '../measure.js';
import { freeControlNamed } from './params.js';
import { named, describe } from '../controls.js';
import { readSurface } from './geometry.js';

/**
 * P2: the page may start with the depth test off or culling on the wrong side: its own controls
 * set as the step ends, until the colours face the viewer (facts.facesImage: the picture after;
 * facts.facesSurface: its surface).
 * Then, where the colours are the normals reflected, a frame with culling off (WebGL): the same
 * picture means the nearest faces were showing (facts.noCull; its `draws`, the page's draw calls
 * meanwhile: none, and the picture tells nothing).
 */
export async function probeFaces(session, controls, judged) {
  const { thresholds, facts } = session;
  let { img, an } = judged;
  let nc = normalColours(samples(img, an, thresholds), thresholds);
  if (nc && !facesViewer(nc, thresholds)) {
    for (const [r, want] of [['depth', true], ['cull', true], ['clockwise', false]]) {
      const c = freeControlNamed(session, controls, r);
      if (!c || (c.type === 'checkbox' && c.checked === want)) continue;
      if (!await session.press(c, `the ${r === 'clockwise' ? 'clockwise-front-faces' : r} control`)) continue;
      if (r !== 'clockwise') facts.facesSetBy = { ...facts.facesSetBy, [r]: describe(c) };
      const s = await session.shot();
      if (!s || s.an.blank) break;
      ({ img, an } = s);
      facts.facesImage = session.keep('faces', img);
      nc = normalColours(samples(img, an, thresholds), thresholds);
      if (facesViewer(nc, thresholds)) break;
    }
    // the side seen is read on the surface of the picture the controls gave (the judged view's is before them)
    if (facts.facesImage) facts.facesSurface = await readSurface(session, 'faces-');
  }
  if (nc && nc.det < 0 && nc.residual <= thresholds.facingResidual && facts.api !== 'webgpu') {
    const faces = (await session.page.state()).faces || {};
    facts.noCull = { faces };
    if (faces.depthTest && faces.culling) {
      const before = (await session.page.state()).draws;
      await session.page.setNoCull(true);
      await session.tick(session.thresholds.actionTickMs);
      const s = await session.shot();
      // a page that draws only when a control asks drew nothing here: its picture tells nothing
      facts.noCull.draws = (await session.page.state()).draws - before;
      await session.page.setNoCull(false);
      await session.tick(session.thresholds.actionTickMs);
      if (s) facts.noCull.image = session.keep('no-cull', s.img);
    }
  }
}

/**
 * P2: the depth test and culling as the page set them, its own toggles switched on where they start
 * off, and its own menu of face culling (none, front, back: the slides' WebGPU cullMode) set to back.
 */
export async function probeDepthCulling(session, controls) {
  let faces = (await session.page.state()).faces || {};
  const setBy = {}; // the page's own controls that switched them on: facts.facesSetBy
  for (const [r, on] of [['depth', 'depthTest'], ['cull', 'culling']]) {
    const c = freeControlNamed(session, controls, r);
    if (faces[on] || !c) continue;
    if (await session.press(c, `the ${r} control`)) faces = (await session.page.state()).faces || {};
    if (faces[on]) setBy[r] = describe(c);
  }
  const menu = !faces.culling && controls.find((x) => x.type === 'select' && !session.taken.has(x.index) &&
    named(x, 'cull', session.patterns) && (x.options || []).some((o) => /back/i.test(o)));
  if (menu) {
    const back = menu.options.find((o) => /back/i.test(o));
    await session.set(menu, back);
    session.act(`set the face culling menu ${describe(menu)} to ${back}`);
    await session.tick(session.thresholds.actionTickMs);
    faces = (await session.page.state()).faces || {};
    if (faces.culling) setBy.cull = `${describe(menu)} set to ${back}`;
  }
  session.facts.faces = faces;
  if (Object.keys(setBy).length) session.facts.facesSetBy = { ...session.facts.facesSetBy, ...setBy };
}
