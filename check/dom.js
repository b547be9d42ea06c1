// What the check page and the class page share of the DOM: an element made with its properties
// (its data- attributes under `dataset`) and its children (null and undefined left out), a picture
// as a PNG data: URL, and the box a hand-in or a download is dropped on.
export const el = (tag, { dataset, ...props } = {}, ...children) => {
  const e = Object.assign(document.createElement(tag), props);
  if (dataset) Object.assign(e.dataset, dataset);
  e.append(...children.filter((c) => c !== null && c !== undefined));
  return e;
};

/** Makes `box` a drop target: marked while something is dragged over it, `dropped(dataTransfer)` on a drop. */
export function dropBox(box, dropped) {
  for (const type of ['dragenter', 'dragover']) box.addEventListener(type, (e) => { e.preventDefault(); box.classList.add('over'); });
  box.addEventListener('dragleave', () => box.classList.remove('over'));
  box.addEventListener('drop', (e) => {
    e.preventDefault();
    box.classList.remove('over');
    dropped(e.dataTransfer);
  });
}

/** An image { width, height, data } as a PNG data: URL. */
export function pngURL(img) {
  const c = el('canvas', { width: img.width, height: img.height });
  const pixels = new Uint8ClampedArray(img.data.buffer, img.data.byteOffset, img.data.byteLength);
  c.getContext('2d').putImageData(new ImageData(pixels, img.width, img.height), 0, 0);
  return c.toDataURL('image/png');
}
