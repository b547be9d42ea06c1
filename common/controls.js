// The controls of a step, made from the parameters' declarations (common/params.js): a page marks
// where they go with <div class="controls" data-params="kd ks s"></div>, and each gets a real
// button, checkbox, select or range input with a visible label, so it has an accessible name.
// Sliders report on the `input` event, i.e. while they are dragged (slide "Exercise (WP04P4)").
import { MAX_LEVEL } from './sphere.js';

function element(tag, attributes = {}, text = '') {
  const e = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
  if (text) e.textContent = text;
  return e;
}

/** Subdivide and Coarsen, and the line that says the level and the number of vertices. */
function levelControl(place, state, onInput) {
  const subdivide = element('button', { id: 'subdivide', type: 'button' }, 'Subdivide');
  const coarsen = element('button', { id: 'coarsen', type: 'button' }, 'Coarsen');
  const info = element('output', { id: 'info' });
  subdivide.addEventListener('click', () => onInput('level', Math.min(state.level + 1, MAX_LEVEL)));
  coarsen.addEventListener('click', () => onInput('level', Math.max(state.level - 1, 0)));
  place.append(subdivide, ' ', coarsen, ' ', info);
}

function checkbox(place, name, rule, state, onInput) {
  const input = element('input', { id: rule.id || name, type: 'checkbox' });
  input.checked = state[name];
  input.addEventListener('change', () => onInput(name, input.checked));
  const label = element('label');
  label.append(input, ` ${rule.label}`);
  place.append(label);
}

function select(place, name, rule, state, onInput) {
  const id = rule.id || name;
  const input = element('select', { id });
  for (const [value, text] of Object.entries(rule.options)) input.append(element('option', { value }, text));
  input.value = state[name];
  input.addEventListener('change', () => onInput(name, input.value));
  place.append(element('label', { for: id }, rule.label), ' ', input);
}

function slider(place, name, rule, state, onInput) {
  const id = rule.id || name;
  const [min, max, step] = rule.slider;
  const input = element('input', { id, type: 'range', min, max, step });
  const shown = element('output', { for: id });
  input.addEventListener('input', () => {
    shown.value = input.value;
    onInput(name, Number(input.value));
  });
  place.append(element('label', { for: id }, rule.label), input, shown);
  showValue(name, state[name], rule);
}

/**
 * Makes the controls of every element with a `data-params` list, from the declarations in `table`,
 * set to `state`. `onInput(name, value)` is called whenever the user changes one.
 */
export function makeControls(table, state, onInput, root = document) {
  for (const place of root.querySelectorAll('[data-params]')) {
    for (const name of place.dataset.params.split(/\s+/).filter(Boolean)) {
      const rule = table[name];
      if (!rule) throw new Error(`makeControls: no parameter "${name}" is declared`);
      if (name === 'level') levelControl(place, state, onInput);
      else if (rule.type === 'bool') checkbox(place, name, rule, state, onInput);
      else if (rule.type === 'enum') select(place, name, rule, state, onInput);
      else if (rule.slider) slider(place, name, rule, state, onInput);
      else throw new Error(`makeControls: parameter "${name}" has no control`);
    }
  }
}

/**
 * Moves a control (and the value shown beside a slider) to `value` without firing it. A value
 * beyond a slider's range (a URL may give one) widens the range, so that thumb and value agree.
 */
export function showValue(name, value, rule) {
  const input = document.getElementById(rule.id || name);
  if (!input) return;
  if (input.type === 'checkbox') {
    input.checked = value;
    return;
  }
  if (input.type === 'range') {
    if (value < Number(input.min)) input.min = String(value);
    if (value > Number(input.max)) input.max = String(value);
  }
  input.value = String(value);
  const shown = document.querySelector(`output[for="${input.id}"]`);
  if (shown) shown.value = String(value);
}

/** Says the level and its number of vertices; Subdivide and Coarsen stop at the ends. */
export function showLevel(level, vertices, note) {
  document.getElementById('subdivide').disabled = level >= MAX_LEVEL;
  document.getElementById('coarsen').disabled = level <= 0;
  document.getElementById('info').value = `level ${level} · ${vertices.toLocaleString('en')} vertices${note ? ` (${note})` : ''}`;
}
