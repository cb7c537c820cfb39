// Downloads: the figures exactly as the screen draws them (the core's figure descriptions: axes
// mode, range, overlays, pinned curve, palette) with the core's caption (level, scene, version,
// citation) and the date, and the data as the core's records (units in the headers) after the
// core's context lines ("# ": what, version, level, date, scene, citation).
import { mapRecords, qty } from './core.js';
import { $, el, wrapText } from './dom.js';
import { chartSpec } from './chart.js';
import { classColors, epsTSpec, mapSpec } from './map.js';
import { CanvasPainter, SvgPainter, chartLegendHeight, drawCaption, drawChart, drawLines, drawMap } from './plot.js';
import { app } from './state.js';
import { ring } from './ring.js';
import { writeHashNow } from './url.js';

let version = '';
export function setVersion(v) { version = v; }

// ---------- CSV: the core's one record contract (identical to `rime curve` / `rime map --format
// csv`), after the core's context lines; nothing is built here. ----------

/** This scene's ε_N records (as `rime curve --format csv`) with their context. */
export function curvesCsv(res = app.res) {
  return res.records.context.curve + res.records.curve;
}

/** Every curve of the chart (scene, clean surface, family, comparisons, measured laws, pinned)
 *  with its context; with the ring card's ε_cr line on the chart, its column too (issue 37 F2.5),
 *  as the terminal's export writes it: `eps_cr [ring τ = 0.5]`, on every row inside the frame's
 *  speeds. */
export function familyCsv(res = app.res) {
  const c = ring.card;
  const g = res.g;
  if (!c || !ring.onChart || !g || g.length === 0) return res.records.context.family + res.records.family;
  const epsCr = c.eps_cr_line.points[0][1];
  const tau = c.record && Number.isFinite(c.record.tau) ? c.record.tau : ring.tau;
  const [lo, hi] = [g[0], g[g.length - 1]];
  const lines = res.records.family.split('\n');
  const out = lines.map((line, k) => {
    if (line === '') return line;
    if (k === 0) return `${line},eps_cr [ring τ = ${String(tau)}]`;
    const v = Number(line.slice(0, line.indexOf(',')));
    return `${line},${v >= lo && v <= hi ? String(epsCr) : ''}`;
  });
  return res.records.context.family + out.join('\n');
}

/** The stick map's records (as `rime map --format csv`) with their context, or null. */
export function mapCsv(res = app.res) {
  // Formatted by the core only now, from the drawn map's arrays (too costly for every frame).
  return res.map ? res.records.context.map + mapRecords(res.map.g, res.map.epsT, res.map.codes) : null;
}

/** The caption and parameter block of figure `fig` (the core's), wrapped to `width` px. */
function captionLines(fig, width, extra = '') {
  const chars = Math.max(40, Math.floor((width - 16) / 5.6));
  return [
    ...wrapText(`${fig.title}${extra}`, chars),
    ...wrapText(fig.caption, chars),
    ...wrapText(`Drawn ${new Date().toISOString().slice(0, 19)}Z from ${location.origin}${location.pathname}`, chars),
  ];
}

const CHART_W = 720;
const CHART_H = 460;

/** The chart figure (as on screen) with its caption, on painter `make(w, h)`. */
function chartFigure(make) {
  const view = app.drawn.view;
  const fig = app.res.figures[0];
  const lines = captionLines(fig, CHART_W, `; impact speeds ${qty(fig.x.min, 'm/s', 3)} to ${qty(fig.x.max, 'm/s', 3)}.`);
  // The plot keeps its height; the legend (full labels, wrapped, never cut) and the caption follow.
  const spec = { ...chartSpec(app.res, view, null), plotHeight: CHART_H };
  const top = CHART_H + chartLegendHeight(spec, CHART_W);
  const p = make(CHART_W, top + 10 + lines.length * 14);
  p.rect(0, 0, CHART_W, p.height, { fill: '#fff' });
  drawChart(p, spec);
  drawCaption(p, lines, top);
  return p;
}

/** The stick map with its legend, ε_T along the chosen row and the caption. */
function mapFigure(make) {
  const m = app.res.map;
  const W = 560;
  const legendH = 18 * app.classes.length + 8;
  const fig = app.res.figures.find((f) => f.map) || { title: 'Stick map', caption: '' };
  const lines = captionLines(fig, W, ` (g_T across, g_N up, 0 to ${qty(m.max, 'm/s', 3)}); below: ε_T along one g_N row.`);
  // The map square is W − 84 wide; its axes end 44 px below it (plot.js drawMap).
  const mapBottom = 10 + (W - 84) + 44;
  const H = mapBottom + legendH + 220 + 16 + lines.length * 14;
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
  p.meta(app.res.figures[0].title, app.res.figures[0].caption);
  return p.svg();
}

export function mapSvg() {
  if (!app.res.map) return null;
  const p = mapFigure((w, h) => new SvgPainter(w, h));
  const fig = app.res.figures.find((f) => f.map);
  if (fig) p.meta(fig.title, fig.caption);
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
  // The browser reads the blob after this task, when it gets to it: revoked after 1 s, a busy
  // machine lost the download (seen in the e2e run under load). A minute is ample; the memory is
  // one file's.
  setTimeout(() => URL.revokeObjectURL(url), 60000);
}

export function wireDownloads(onError) {
  // Never a preview (issue 26): the downloads wait for the requested level.
  const ok = () => app.res && app.drawn && !app.preview;
  $('dl-curves').addEventListener('click', () => ok() && download('rime-curve.csv', 'text/csv', curvesCsv()));
  $('dl-family').addEventListener('click', () => ok() && download('rime-curves-all.csv', 'text/csv', familyCsv()));
  $('dl-map').addEventListener('click', () => ok() && mapCsv() && download('rime-map.csv', 'text/csv', mapCsv()));
  $('dl-chart-svg').addEventListener('click', () => ok() && download('rime-chart.svg', 'image/svg+xml', chartSvg()));
  $('dl-map-svg').addEventListener('click', () => ok() && app.res.map && download('rime-map.svg', 'image/svg+xml', mapSvg()));
  const png = (name, fig) => pngOf(fig).then((b) => download(name, 'image/png', b)).catch((e) => onError(e));
  $('dl-chart-png').addEventListener('click', () => ok() && png('rime-chart.png', chartFigure));
  $('dl-map-png').addEventListener('click', () => ok() && app.res.map && png('rime-map.png', mapFigure));
  $('dl-scene').addEventListener('click', () => app.drawn && !app.preview && download('rime-scene.json', 'application/json', JSON.stringify(JSON.parse(app.drawn.scene), null, 2) + '\n'));
  $('copy-link').addEventListener('click', async () => {
    try {
      // The state now, not the link written a second after the last edit (issue 37).
      writeHashNow();
      await navigator.clipboard.writeText(location.href);
      $('copy-status').textContent = 'link copied';
    } catch {
      $('copy-status').textContent = 'copy the address bar: it holds the full state';
    }
  });
}
