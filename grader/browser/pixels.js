// The grader's read-back of the canvas, as an init script after instrument.js: window.__grade.pixels.
// It calls the browser's own functions as they were before the page's first script ran (a page
// that replaces toDataURL, drawImage or getImageData afterwards changes what it reads itself, not
// what the grader reads), and it cannot be replaced (grader/browser/tamper.js says who tried).
export function pixelsScript() {
  const g = window.__grade;
  if (!g || g.pixels) return;
  const C = HTMLCanvasElement.prototype,
    X = CanvasRenderingContext2D.prototype,
    D = Document.prototype,
    E = Element.prototype;
  const property = (proto, name) => Object.getOwnPropertyDescriptor(proto, name);
  const N = {
    querySelectorAll: D.querySelectorAll, createElement: D.createElement,
    getClientRects: E.getClientRects, getAttribute: E.getAttribute,
    getContext: C.getContext, toDataURL: C.toDataURL, width: property(C, 'width'), height: property(C, 'height'),
    fillStyle: property(X, 'fillStyle'), fillRect: X.fillRect, clearRect: X.clearRect, drawImage: X.drawImage,
    getImageData: X.getImageData,
    getBoundingClientRect: E.getBoundingClientRect, innerWidth: property(window, 'innerWidth'), innerHeight: property(window, 'innerHeight'),
    clientLeft: property(E, 'clientLeft'), clientTop: property(E, 'clientTop'), clientWidth: property(E, 'clientWidth'), clientHeight: property(E, 'clientHeight'),
  };
  const size = (c) => ({ width: N.width.get.call(c), height: N.height.get.call(c) });

  /** The canvas the grader reads: the largest visible one (the one chosen among equals: canvases.js), or null. */
  const target = () => {
    const shown = (c) => size(c).width > 0 && size(c).height > 0 && N.getClientRects.call(c).length;
    const area = (c) => size(c).width * size(c).height;
    const all = [...N.querySelectorAll.call(document, 'canvas')].filter(shown);
    if (!all.length) return null;
    const largest = all.reduce((a, b) => (area(b) > area(a) ? b : a));
    const chosen = g.chosenCanvas ? g.chosenCanvas() : null;
    return chosen && all.includes(chosen) && area(chosen) === area(largest) ? chosen : largest;
  };

  // the one 2D canvas the reads draw on, kept from read to read (out of the page's reach): a new one
  // a read cost the page 10-20 ms more (its pixels made and cleared again), some 500 reads a class
  let copy = null, c2 = null;

  /** The kept 2D canvas at `canvas`'s size with `canvas` drawn on it, over `background` if one is given, else over nothing (as a new canvas): { copy, c2, width, height }. */
  const copyOf = (canvas, background) => {
    const { width, height } = size(canvas);
    if (!copy) {
      copy = N.createElement.call(document, 'canvas');
      c2 = N.getContext.call(copy, '2d', { willReadFrequently: true });
    }
    if (N.width.get.call(copy) !== width || N.height.get.call(copy) !== height) {
      N.width.set.call(copy, width);
      N.height.set.call(copy, height);
    }
    if (background) {
      N.fillStyle.set.call(c2, background);
      N.fillRect.call(c2, 0, 0, width, height);
    } else N.clearRect.call(c2, 0, 0, width, height);
    N.drawImage.call(c2, canvas, 0, 0);
    return { copy, c2, width, height };
  };

  /** The target canvas (the largest visible one), composited over white: a PNG data URL with format 'png' (the grader, which sends it out of the page: a tenth of the raw bytes, lossless), else its RGBA bytes (the check page, in the page). */
  const pixels = (format) => {
    const canvas = target();
    if (!canvas) return null;
    const { copy, c2, width, height } = copyOf(canvas, '#fff');
    const api = N.getAttribute.call(canvas, 'data-grade-api');
    if (format === 'png') return { width, height, api, png: N.toDataURL.call(copy, 'image/png') };
    return { width, height, api, data: N.getImageData.call(c2, 0, 0, width, height).data };
  };
  Object.defineProperty(g, 'pixels', { value: pixels, enumerable: true, configurable: true });

  /**
   * The first of a picture's two channels: the target canvas as read back, its alpha kept (a PNG
   * data URL), with where it lies in the viewport and the viewport's size, in CSS pixels ({ x, y,
   * width, height }; a screenshot's clip is in the viewport's pixels, wherever the page is
   * scrolled): the driver takes the second, a screenshot of that box from outside the page. Null
   * where there is no canvas.
   */
  const readBack = () => {
    const canvas = target();
    if (!canvas) return null;
    const { copy, width, height } = copyOf(canvas, null);
    // the canvas's own picture lies inside its border (a CSS border shows around it, not over it)
    const r = N.getBoundingClientRect.call(canvas), read = (k) => N[k].get.call(canvas);
    return {
      width, height, api: N.getAttribute.call(canvas, 'data-grade-api'), png: N.toDataURL.call(copy, 'image/png'),
      box: { x: r.x + read('clientLeft'), y: r.y + read('clientTop'), width: read('clientWidth'), height: read('clientHeight') },
      view: { x: 0, y: 0, width: N.innerWidth.get.call(window), height: N.innerHeight.get.call(window) },
    };
  };
  Object.defineProperty(g, 'readBack', { value: readBack, enumerable: true, configurable: true });
}
