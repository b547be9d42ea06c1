// The page's canvases as the grader sees them, as an init script after pixels.js: window.__grade.canvases()
// lists each with its size and the names a teacher reads it by (its id, class, title, aria-label
// and the short texts beside it), and chooseCanvas(index) makes pixels.js read that one where it is
// among the largest (gather/step-canvas.js: P5's Phong canvas beside a Gouraud one). It calls the
// browser's own functions as they were before the page's first script ran.
export function canvasesScript() {
  const g = window.__grade;
  if (!g || g.canvases) return;
  const C = HTMLCanvasElement.prototype, E = Element.prototype;
  const property = (proto, name) => Object.getOwnPropertyDescriptor(proto, name);
  const N = {
    querySelectorAll: Document.prototype.querySelectorAll,
    getClientRects: E.getClientRects, getAttribute: E.getAttribute, querySelector: E.querySelector,
    width: property(C, 'width'), height: property(C, 'height'), tagName: property(E, 'tagName'),
    previous: property(E, 'previousElementSibling'), next: property(E, 'nextElementSibling'),
    parent: property(Node.prototype, 'parentElement'), text: property(Node.prototype, 'textContent'),
  };
  // (a text longer than this is a paragraph about the page, not a canvas's name)
  const TEXT_NEAR = 120;
  const all = () => [...N.querySelectorAll.call(document, 'canvas')];
  let chosen = null;

  const CONTROLS = 'button, input, select, textarea';
  /** The text of element `e` where it is short and `e` holds no control (controls name themselves), or null. */
  const shortText = (e) => {
    if (N.querySelector.call(e, CONTROLS)) return null;
    const t = (N.text.get.call(e) || '').replace(/\s+/g, ' ').trim();
    return t && t.length <= TEXT_NEAR ? t : null;
  };
  /** The short text of the element beside a canvas (not a canvas, nor one that holds one), or null. */
  const beside = (e) => (!e || N.tagName.get.call(e) === 'CANVAS' || N.querySelector.call(e, 'canvas') ? null : shortText(e));
  /** The short text of a canvas's parent that holds no other canvas (a figure, a cell), or null. */
  const parentText = (parent) =>
    (parent && all().filter((x) => N.parent.get.call(x) === parent).length === 1 ? shortText(parent) : null);

  /**
   * Every canvas on the page, in the document's order: { index, width, height, shown, labels }
   * (labels: its id, class, title and aria-label, the short texts of the elements just before and
   * after it, and its parent's where the parent holds no other canvas and no control).
   */
  const canvases = () => all().map((c, index) => {
    const width = N.width.get.call(c), height = N.height.get.call(c);
    const parent = N.parent.get.call(c);
    const near = [beside(N.previous.get.call(c)), beside(N.next.get.call(c)), parentText(parent)];
    const attrs = ['id', 'class', 'title', 'aria-label'].map((a) => N.getAttribute.call(c, a));
    const shown = width > 0 && height > 0 && N.getClientRects.call(c).length > 0;
    return { index, width, height, shown, labels: [...attrs, ...near].filter(Boolean) };
  });
  /** pixels.js reads canvas `index` where it is among the largest (null: the largest, the first of equals); true where it is on the page. */
  const chooseCanvas = (index) => {
    chosen = index === null ? null : all()[index] || null;
    return index === null || !!chosen;
  };
  const define = (name, value) => Object.defineProperty(g, name, { value, enumerable: true, configurable: true });
  define('canvases', canvases);
  define('chooseCanvas', chooseCanvas);
  define('chosenCanvas', () => chosen);
}
