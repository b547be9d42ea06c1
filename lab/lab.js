// The lab page: charts and tables from lab/results.json (written by npm run bench).
import { run, notify } from '../common/page.js';
import { SHININESS, chooseLevel } from '../common/sphere.js';
import { EYE_DISTANCE, FOVY } from '../common/course.js';

const COLOURS = { flat: '#8d6e63', gouraud: '#e65100', phong: '#1565c0', impostor: '#2e7d32' };
const NAMES = { flat: 'flat (per triangle)', gouraud: 'Gouraud (WP04P4)', phong: 'Phong shading (WP04P5)', impostor: 'exact impostor' };
const STEP = 1 / 255;
const APIS = { webgl2: 'WebGL 2', webgpu: 'WebGPU' };
/** A row's API: rows from before the WebGPU bench have none and are WebGL 2. */
const apiOf = (f) => f.api || 'webgl2';

// Writes a number in the level's label next to each point (a Chart.js plugin).
const levelLabels = {
  id: 'levelLabels',
  afterDatasetsDraw(chart) {
    const { ctx } = chart;
    ctx.save();
    ctx.font = '11px sans-serif';
    chart.data.datasets.forEach((ds, i) => {
      if (!ds.labelPoints) return;
      chart.getDatasetMeta(i).data.forEach((el, k) => {
        ctx.fillStyle = ds.borderColor;
        ctx.fillText(ds.data[k].label, el.x + 5, el.y - 5);
      });
    });
    ctx.restore();
  },
};

function table(id, head, rows) {
  const t = document.getElementById(id);
  const tr = (cells, tag) => `<tr>${cells.map((c) => `<${tag}>${c}</${tag}>`).join('')}</tr>`;
  // numbers and fixed words only: nothing from outside the results file is written as HTML
  t.innerHTML = tr(head, 'th') + rows.map((r) => tr(r, 'td')).join('');
}

function pareto(points) {
  const sorted = [...points].sort((a, b) => a.x - b.x || a.y - b.y);
  const front = [];
  for (const p of sorted) if (!front.length || p.y < front[front.length - 1].y) front.push(p);
  return front;
}

async function main() {
  const response = await fetch('results.json');
  if (!response.ok) throw new Error('No results yet: run "npm run bench" to measure them (lab/results.json is missing).');
  const r = await response.json();
  const m = r.meta;
  document.getElementById('meta').textContent =
    `Measured ${m.date.slice(0, 10)} on ${m.machine}; ${m.browser}, ${m.api}, renderer: ${m.renderer}` +
    `${m.rendererWebGPU ? `; WebGPU adapter: ${m.rendererWebGPU}` : ''}. ` +
    `View: ${m.view}. ${m.load ? `Load average ${m.load.join(' → ')} on ${m.machine.split(' ')[0]} cores. ` : ''}${m.quick ? 'A quick run (fewer levels and frames).' : ''}`;
  if (m.quick) notify('These are the results of a quick run: run "npm run bench" for the full picture.');

  const sizes = [...new Set(r.frames.map((f) => f.size))];
  const select = document.getElementById('size');
  for (const s of sizes) select.add(new Option(`${s} × ${s} px`, String(s)));
  select.value = String(sizes[sizes.length - 1]);

  const chart = new window.Chart(document.querySelector('#speed-accuracy canvas'), {
    type: 'scatter',
    data: { datasets: [] },
    plugins: [levelLabels],
    options: {
      animation: false, maintainAspectRatio: false,
      scales: {
        x: { type: 'logarithmic', title: { display: true, text: 'ms per frame (median, log)' } },
        y: { type: 'logarithmic', title: { display: true, text: 'interior RMSE in 8-bit steps (log)' } },
      },
      plugins: { tooltip: { callbacks: { label: (c) => `${c.dataset.label} ${c.raw.label}: ${c.raw.x} ms, ${c.raw.y.toFixed(2)}/255` } } },
    },
  });
  function draw(size) {
    const rows = r.frames.filter((f) => f.size === size);
    // one line per method and API: WebGL 2 solid with round points, WebGPU dashed with triangles
    const datasets = Object.keys(APIS).flatMap((api) => Object.keys(NAMES).map((method) => {
      const chosen = r.chosen[size][method]; // the level the exercise of this method picks
      const pts = rows.filter((f) => f.method === method && apiOf(f) === api)
        .map((f) => ({ x: Math.max(f.msMedian, 0.01), y: Math.max(f.rmse / STEP, 0.01), label: f.level === null ? '' : `L${f.level}`, level: f.level }));
      const gpu = api === 'webgpu';
      return { label: `${NAMES[method]} · ${APIS[api]}`, data: pts, borderColor: COLOURS[method], backgroundColor: gpu ? '#fff' : COLOURS[method],
        borderDash: gpu ? [4, 3] : [], showLine: method !== 'impostor', labelPoints: !gpu, pointRadius: pts.map((p) => (p.level === chosen ? 7 : 3)),
        pointStyle: pts.map((p) => (p.level === chosen ? 'rectRot' : gpu ? 'triangle' : 'circle')) };
    })).filter((d) => d.data.length);
    const all = datasets.flatMap((d) => d.data);
    datasets.push({ label: 'Pareto front', data: pareto(all), borderColor: '#555', borderDash: [6, 4], showLine: true,
      pointRadius: 0, backgroundColor: 'transparent' });
    chart.data.datasets = datasets;
    chart.update();
  }
  select.addEventListener('change', () => draw(Number(select.value)));
  draw(Number(select.value));

  // The claim, answered from the numbers (WebGL 2: the two APIs draw the same pixels)
  const size = sizes[sizes.length - 1];
  const claim = [];
  for (const method of ['flat', 'gouraud', 'phong']) {
    const rows = r.frames.filter((f) => f.size === size && f.method === method && apiOf(f) === 'webgl2').sort((a, b) => a.level - b.level);
    const shade = rows.find((f) => f.rmse <= STEP);
    const edge = rows.find((f) => f.silhouetteErrorPx <= 1);
    const best = rows.reduce((a, b) => (b.rmse < a.rmse ? b : a));
    claim.push(`${NAMES[method]}: ` +
      (shade ? `error within 1/255 from level ${shade.level} (${shade.vertices.toLocaleString('en')} vertices, ${shade.msMedian} ms per frame)` : `never within 1/255 up to level ${rows[rows.length - 1].level} (best ${(best.rmse / STEP).toFixed(2)}/255 at level ${best.level})`) +
      (edge ? `; silhouette within 1 px from level ${edge.level}.` : '.'));
  }
  const imp = r.frames.find((f) => f.size === size && f.method === 'impostor' && apiOf(f) === 'webgl2');
  if (imp) claim.push(`The exact impostor: ${(imp.rmse / STEP).toFixed(2)}/255 with no mesh at all, ${imp.msMedian} ms per frame.`);
  const box = document.getElementById('claim');
  box.replaceChildren(...claim.map((text) => Object.assign(document.createElement('p'), { textContent: text })));

  // Both APIs at the level each exercise picks, on every canvas
  const at = (api, method, s, level) => r.frames.find((f) => apiOf(f) === api && f.method === method && f.size === s && f.level === level);
  const both = [];
  for (const s of sizes) {
    for (const method of Object.keys(NAMES)) {
      const level = method === 'impostor' ? null : r.chosen[s][method];
      const [a, b] = [at('webgl2', method, s, level), at('webgpu', method, s, level)];
      if (!a || !b) continue;
      both.push([NAMES[method], `${s} px`, level ?? '–', a.msMedian, b.msMedian, (b.msMedian / a.msMedian).toFixed(2),
        `${(a.rmse / STEP).toFixed(2)}/255`, `${(b.rmse / STEP).toFixed(2)}/255`]);
    }
  }
  table('api-table', ['method', 'canvas', 'level', 'WebGL 2 ms', 'WebGPU ms', 'WebGPU / WebGL 2', 'WebGL 2 error', 'WebGPU error'], both);

  const gpuChange = r.levelChange.some((l) => l.gpuOursMs !== undefined);
  new window.Chart(document.querySelector('#level-change canvas'), {
    type: 'line',
    data: {
      labels: r.levelChange.map((l) => `L${l.level}`),
      datasets: [
        { label: 'ours: a click (common/sphere.js)', data: r.levelChange.map((l) => l.oursMs), borderColor: COLOURS.phong },
        { label: 'ours cold: a jump', data: r.levelChange.map((l) => l.coldMs), borderColor: COLOURS.phong, borderDash: [8, 3], pointStyle: 'rect' },
        { label: 'classic', data: r.levelChange.map((l) => l.classicMs), borderColor: COLOURS.gouraud },
        { label: 'bound', data: r.levelChange.map((l) => l.boundMs), borderColor: '#555', borderDash: [6, 4] },
        ...(gpuChange ? [
          { label: 'WebGPU ours (writeBuffer)', data: r.levelChange.map((l) => l.gpuOursMs), borderColor: COLOURS.phong, borderDash: [2, 2], pointStyle: 'triangle' },
          { label: 'WebGPU classic', data: r.levelChange.map((l) => l.gpuClassicMs), borderColor: COLOURS.gouraud, borderDash: [2, 2], pointStyle: 'triangle' },
          { label: 'WebGPU bound', data: r.levelChange.map((l) => l.gpuBoundMs), borderColor: '#999', borderDash: [2, 2], pointStyle: 'triangle' },
        ] : []),
      ],
    },
    options: { animation: false, maintainAspectRatio: false, scales: { y: { type: 'logarithmic', title: { display: true, text: 'ms per level change (log)' } } } },
  });
  const gpuHead = gpuChange ? ['WebGPU ours ms', 'WebGPU cold ms', 'WebGPU classic ms', 'WebGPU bound ms', 'WebGPU ours / bound', 'WebGPU cold / bound'] : [];
  table('level-table', ['level', 'vertices', 'bytes', 'ours ms', 'cold ms', 'classic ms', 'bound ms', 'classic / ours', 'ours / bound', 'cold / bound', ...gpuHead],
    r.levelChange.map((l) => [l.level, l.vertices.toLocaleString('en'), l.bytes.toLocaleString('en'), l.oursMs, l.coldMs, l.classicMs, l.boundMs, l.classicOverOurs, l.oursOverBound, l.coldOverBound,
      ...(gpuChange ? [l.gpuOursMs, l.gpuColdMs, l.gpuClassicMs, l.gpuBoundMs, l.gpuOursOverBound, l.gpuColdOverBound] : [])]));
  table('stability', ['method', 'level', 'angles with a highlight', 'peak error rms', 'peak error max', 'position error rms (px)', 'position error max (px)', 'largest frame-to-frame jump beyond the exact one'],
    r.stability.map((s) => [NAMES[s.method], s.level, `${s.anglesWithHighlight} of ${s.angles}`, `${(s.peakErrorRms / STEP).toFixed(1)}/255`,
      `${(s.peakErrorMax / STEP).toFixed(1)}/255`, s.positionErrorRmsPx, s.positionErrorMaxPx, `${(s.peakJumpMax / STEP).toFixed(1)}/255`]));
  table('indexed', ['level', 'vertices (indexed)', 'index bits', 'bytes indexed', 'bytes arrays', 'level change ms (indexed / arrays)', 'frame ms (indexed / arrays)', 'same pixels'],
    r.indexed.map((x) => [x.level, x.vertices.toLocaleString('en'), x.indexBits, x.bytes.toLocaleString('en'), x.bytesArrays.toLocaleString('en'),
      `${x.changeMs} / ${x.changeMsArrays}`, `${x.frameMs} / ${x.frameMsArrays}`, x.pixelsEqual ? 'yes' : 'NO']));
  const cases = [...new Set((r.edgeCases || []).map((e) => e.case))];
  const cell = (name, method) => {
    const e = r.edgeCases.find((x) => x.case === name && x.method === method);
    return e ? `${(e.rmse / STEP).toFixed(2)}/255${e.fails ? ` <b>fails</b>: ${e.fails}` : ''}` : '';
  };
  // The level each material needs, from the calibrated table (no bench results needed)
  const SIZES = [128, 256, 512];
  const needs = (size, shading, shininess) => {
    const c = chooseLevel(size, FOVY, EYE_DISTANCE, { shading, shininess });
    return c.rmse > 1 ? `${c.level}+` : c.level;
  };
  table('needs', ['material', ...SIZES.map((x) => `Gouraud (WP04P4) ${x} px`), ...SIZES.map((x) => `Phong shading (WP04P5) ${x} px`)],
    [['diffuse light (WP04P3)', ...SIZES.map((x) => needs(x, 'diffuse')), '', '', ''],
      ...SHININESS.map((s) => [`s = ${s}`, ...SIZES.map((x) => needs(x, 'gouraud', s)), ...SIZES.map((x) => needs(x, 'phong', s))])]);
  table('edge-cases', ['case', 'Gouraud (WP04P4)', 'Phong shading (WP04P5)'], cases.map((c) => [c, cell(c, 'gouraud'), cell(c, 'phong')]));
  window.labReady = true;
}

run(main);
