// Downloads: the figures exactly as the screen draws them (same figure descriptions, same axes
// mode, range, overlays, pinned curve, palette) with a caption and parameter block, and the data
// as CSV with units in the headers and the context (scene, level, version, date, citation) in
// leading "# " lines. Numbers in files are the core's shortest round-trip texts.
import { citation, qty, shortest, sig } from './core.js';
import { $, el, wrapText } from './dom.js';
import { chartSpec } from './chart.js';
import { classColors, epsTSpec, mapSpec } from './map.js';
import { CanvasPainter, SvgPainter, drawCaption, drawChart, drawLines, drawMap } from './plot.js';
import { app } from './state.js';

let version = '';
export function setVersion(v) { version = v; }

/** The scene's parameters in a few words ("R₁ 2 cm, ρ 900 kg/m³, …", effects that are off named). */
export function sceneSummary(values) {
  const parts = [];
  for (const p of app.params) {
    const v = values[p.path];
    const sym = p.label.split(' ')[0];
    if (p.kind === 'toggle') { if (v === false) parts.push(`${p.label} off`); continue; }
    if (v === null || v === undefined) continue;
    parts.push(p.kind === 'number' ? `${sym} ${p.unit ? qty(v, p.unit, 4) : sig(v, 4)}` : `${p.label} ${v}`);
  }
  return parts.join(', ');
}

/** The context of what is drawn: version, date, scene, level, range, citation. */
function context() {
  const d = app.drawn;
  return {
    made: `rime ${version}, ${new Date().toISOString().slice(0, 19)}Z`,
    scene: d.scene,
    summary: sceneSummary(app.res.values),
    accuracy: d.view.accuracy,
    range: `${shortest(d.view.from)}…${shortest(d.view.to)} m/s`,
    cite: citation(),
  };
}

function csvHead(what) {
  const c = context();
  return [
    `# ${what}`,
    `# made with ${c.made} (${location.origin}${location.pathname})`,
    `# accuracy: ${c.accuracy}`,
    `# scene: ${c.scene}`,
    `# model: ${c.cite}`,
  ].join('\n') + '\n';
}

export function curvesCsv(res = app.res) {
  const cols = ['g_n [m/s]', 'eps_n [1]', 'status', 'eps_n_clean [1]'];
  if (res.family) res.family.values.forEach((v) => cols.push(`eps_n[${res.family.path}=${shortest(v)} ${res.family.unit}] [1]`));
  if (app.pinned && app.pinned.g.length === res.g.length) cols.push('eps_n_pinned [1]');
  const lines = [cols.join(',')];
  const at = (arr, i) => (arr && Number.isFinite(arr[i]) ? shortest(arr[i]) : '');
  for (let i = 0; i < res.g.length; i++) {
    const row = [shortest(res.g[i]), at(res.eps, i), res.status ? app.statusNames[res.status[i]] ?? 'failed' : '', at(res.clean, i)];
    if (res.family) res.family.curves.forEach((c) => row.push(at(c, i)));
    if (app.pinned && app.pinned.g.length === res.g.length) row.push(at(app.pinned.eps, i));
    lines.push(row.join(','));
  }
  return csvHead(`ε_N against the impact speed; ${res.g.length} log-spaced speeds ${context().range}`) + lines.join('\n') + '\n';
}

export function mapCsv(m = app.res.map) {
  const lines = ['g_n [m/s],g_t [m/s],eps_n [1],eps_t [1],class'];
  for (let i = 0; i < m.n; i++) {
    for (let j = 0; j < m.n; j++) {
      const k = i * m.n + j;
      lines.push(`${shortest(m.g[i])},${shortest(m.g[j])},${shortest(m.epsN[i])},${shortest(m.epsT[k])},${app.classes[m.codes[k]].name}`);
    }
  }
  return csvHead(`stick map over g_n and g_t from 0 to ${shortest(m.max)} m/s (${m.n}×${m.n})`) + lines.join('\n') + '\n';
}

/** The caption and parameter block of a figure, wrapped to `width` px. */
function captionLines(title, width) {
  const c = context();
  const chars = Math.max(40, Math.floor((width - 16) / 5.6));
  return [
    ...wrapText(title, chars),
    ...wrapText(`scene: ${c.summary}`, chars),
    ...wrapText(`accuracy ${c.accuracy}; ${c.made}`, chars),
    ...wrapText(`model: ${c.cite}`, chars),
  ];
}

const CHART_W = 720;
const CHART_H = 460;

/** The chart figure (as on screen) with its caption, on painter `make(w, h)`. */
function chartFigure(make) {
  const view = app.drawn.view;
  const lines = captionLines(`ε_N against the impact speed g_N, ${view.yScale === 'lin' ? 'linear' : 'log'} ε_N axis, speeds ${context().range}.`, CHART_W);
  const p = make(CHART_W, CHART_H + 10 + lines.length * 14);
  p.rect(0, 0, CHART_W, p.height, { fill: '#fff' });
  p.height = CHART_H;
  drawChart(p, chartSpec(app.res, view, null));
  p.height = CHART_H + 10 + lines.length * 14;
  drawCaption(p, lines, CHART_H);
  return p;
}

/** The stick map with its legend, ε_T along the chosen row and the caption. */
function mapFigure(make) {
  const m = app.res.map;
  const W = 560;
  const legendH = 18 * app.classes.length + 8;
  const lines = captionLines(`Stick map: g_T across, g_N up, 0…${qty(m.max, 'm/s', 3)}; ε_T along one g_N row below.`, W);
  const H = 560 + 40 + legendH + 220 + 10 + lines.length * 14;
  const p = make(W, H);
  p.rect(0, 0, W, H, { fill: '#fff' });
  p.height = 600;
  const g = drawMap(p, mapSpec(m, null));
  const colors = classColors();
  app.classes.forEach((c, k) => {
    const y = g.bottom + 14 + k * 18;
    p.rect(70, y - 11, 12, 12, { fill: colors[k], stroke: '#00000044' });
    p.text(88, y, c.description, { size: 11 });
  });
  const y0 = g.bottom + legendH;
  const sub = { width: W, height: 220, rect: (x, y, w, h, o) => p.rect(x, y + y0, w, h, o), line: (pts, o) => p.line(pts.map(([x, y]) => [x, y + y0]), o), circle: (x, y, r, o) => p.circle(x, y + y0, r, o), text: (x, y, s, o) => p.text(x, y + y0, s, o), clip: (x, y, w, h, body) => p.clip(x, y + y0, w, h, body) };
  drawLines(sub, epsTSpec(m, null));
  p.height = H;
  drawCaption(p, lines, y0 + 220);
  return p;
}

export function chartSvg() {
  const p = chartFigure((w, h) => new SvgPainter(w, h));
  p.meta('rime: ε_N(g_N)', captionLines('ε_N against the impact speed', 2000).join(' '));
  return p.svg();
}

export function mapSvg() {
  if (!app.res.map) return null;
  const p = mapFigure((w, h) => new SvgPainter(w, h));
  p.meta('rime: stick map', captionLines('stick map', 2000).join(' '));
  return p.svg();
}

/** A PNG (Blob) of a figure drawn at 2× resolution on a detached canvas. */
function pngOf(figure) {
  const canvas = document.createElement('canvas');
  return new Promise((resolve, reject) => {
    try {
      figure((w, h) => new CanvasPainter(canvas, w, h, 2));
      canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('PNG encoding failed'))), 'image/png');
    } catch (e) { reject(e); }
  });
}

function download(name, type, data) {
  const url = URL.createObjectURL(data instanceof Blob ? data : new Blob([data], { type }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export function wireDownloads(onError) {
  const ok = () => app.res && app.drawn;
  $('dl-curves').addEventListener('click', () => ok() && download('rime-curves.csv', 'text/csv', curvesCsv()));
  $('dl-map').addEventListener('click', () => ok() && app.res.map && download('rime-map.csv', 'text/csv', mapCsv()));
  $('dl-chart-svg').addEventListener('click', () => ok() && download('rime-chart.svg', 'image/svg+xml', chartSvg()));
  $('dl-map-svg').addEventListener('click', () => ok() && app.res.map && download('rime-map.svg', 'image/svg+xml', mapSvg()));
  const png = (name, fig) => pngOf(fig).then((b) => download(name, 'image/png', b)).catch((e) => onError(e));
  $('dl-chart-png').addEventListener('click', () => ok() && png('rime-chart.png', chartFigure));
  $('dl-map-png').addEventListener('click', () => ok() && app.res.map && png('rime-map.png', mapFigure));
  $('dl-scene').addEventListener('click', () => app.drawn && download('rime-scene.json', 'application/json', JSON.stringify(JSON.parse(app.drawn.scene), null, 2) + '\n'));
  $('copy-link').addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(location.href);
      $('copy-status').textContent = 'link copied';
    } catch {
      $('copy-status').textContent = 'copy the address bar: it holds the full state';
    }
  });
}
