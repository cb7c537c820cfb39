// Drawing only: the figures (the ε_N chart, the stick map, ε_T, captions, legends) from one
// figure description, painted on either surface of surfaces.js (re-exported here), so that a
// download shows what the screen shows. Colours and labels come in the description (the core's
// palette and formatters); this module has none of its own.
import { axisTicks, qty, sig } from './core.js';

export { CanvasPainter, SvgPainter, sizeElement } from './surfaces.js';

const AXIS = '#333333';
const GRID = '#e6e6e6';
const TICK = '#999999';

/** "Nice" linear ticks from lo to hi, about `count` of them. */
export function niceTicks(lo, hi, count) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / Math.max(1, count);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? 10 * mag;
  const out = [];
  for (let k = Math.ceil(lo / step - 1e-9); k * step <= hi * (1 + 1e-9) + 1e-300; k++) out.push(Math.abs(k) < 1e-9 ? 0 : k * step);
  return out;
}

const textWidth = (text, size) => String(text).length * size * 0.56;

/**
 * The legend beneath the plot: entries in columns of at least 220 px, each label wrapped to its
 * column (never cut: issue 22, labels were cut with "…" and the legend on top squeezed the plot).
 * Returns the rows ({y, h, items: [{x, lines, …entry}]}) and the total height.
 */
export function legendLayout(entries, x0, width, size = 11) {
  // Columns as wide as the longest label needs, between 150 and 260 px.
  const longest = Math.max(0, ...entries.map((e) => textWidth(e.label, size)));
  const cols = Math.max(1, Math.min(entries.length, Math.floor(width / Math.min(260, Math.max(150, longest + 42)))));
  const colW = width / cols;
  const chars = Math.max(12, Math.floor((colW - 42) / (size * 0.56)));
  const rows = [];
  let y = 0;
  for (let k = 0; k < entries.length; k += cols) {
    const items = entries.slice(k, k + cols).map((e, c) => ({ ...e, x: x0 + c * colW, lines: wrapLabel(e.label, chars) }));
    const h = Math.max(...items.map((i) => i.lines.length)) * (size + 3) + 5;
    rows.push({ y, h, items });
    y += h;
  }
  return { rows, height: y };
}

function wrapLabel(text, chars) {
  const lines = [];
  let line = '';
  for (let w of String(text).split(/\s+/)) {
    while (w.length > chars) { if (line) { lines.push(line); line = ''; } lines.push(w.slice(0, chars)); w = w.slice(chars); }
    if (line && line.length + 1 + w.length > chars) { lines.push(line); line = w; } else line = line ? `${line} ${w}` : w;
  }
  if (line) lines.push(line);
  return lines.length ? lines : [''];
}

/** The legend entries of a chart spec: series (short or full labels), then the measured ranges. */
function chartEntries(spec) {
  const pick = (o) => (spec.shortLabels && o.short ? o.short : o.label);
  const entries = spec.series.filter((s) => s.label).map((s) => ({ label: pick(s), color: s.color, dash: s.dash, width: s.width }));
  for (const b of spec.bands || []) entries.push({ label: pick(b), color: b.color, box: true });
  return entries;
}

/** The height of the chart's legend drawn beneath a `width` px plot (0 without entries). */
export function chartLegendHeight(spec, width) {
  const entries = chartEntries(spec);
  return entries.length ? legendLayout(entries, 8, width - 16).height + 6 : 0;
}

/** The y label's lines: whole when it fits beside the plot's height, else split at its "(". */
function yLabelLines(label, height, size) {
  if (textWidth(label, size) <= height - 8) return [label];
  const k = label.indexOf(' (');
  return k > 0 ? [label.slice(0, k), label.slice(k + 1)] : [label];
}

/** Lines of a caption block below a figure, `size` px text; returns the height used. */
export function drawCaption(p, lines, y0, size = 10) {
  lines.forEach((line, k) => p.text(8, y0 + 13 + k * (size + 4), line, { size, color: '#444' }));
  return lines.length ? 10 + lines.length * (size + 4) : 0;
}

/**
 * The ε_N(g_N) chart: log x axis; y log (decades) or linear (0 … 1, where sticking, ε_N = 0, shows).
 * spec: {xMin, xMax, yScale: 'log'|'lin', yMin, yMax, xLabel, yLabel, series: [{x, y, color, width,
 *        dash, label}], bands: [{x: [lo, hi], y: [lo, hi], color, label, short}], markers: [{x,
 *        label, short, color}], hover: {x, y} | null}
 * Returns the plot box and the coordinate transforms (for hover).
 */
/** Where everything of the chart goes (shared by its two layers and by exports). */
export function chartGeometry(p, spec) {
  // The plot takes `spec.plotHeight` (the painter's height by default); the legend lies beneath it.
  const W = p.width;
  const H = spec.plotHeight ?? p.height;
  const entries = chartEntries(spec);
  const legend = legendLayout(entries, 8, W - 16);
  const yLines = yLabelLines(spec.yLabel, H - 52, 12);
  const box = { l: 46 + 14 * yLines.length, r: W - 12, t: 10, b: H - 42 };
  const log = spec.yScale !== 'lin';
  const lx = [Math.log10(spec.xMin), Math.log10(spec.xMax)];
  const ly = log ? [Math.log10(spec.yMin), Math.log10(spec.yMax)] : [spec.yMin, spec.yMax];
  const fy = (v) => (log ? Math.log10(v) : v);
  const X = (v) => box.l + ((Math.log10(v) - lx[0]) / (lx[1] - lx[0])) * (box.r - box.l);
  const Y = (v) => box.b - ((fy(v) - ly[0]) / (ly[1] - ly[0])) * (box.b - box.t);
  const inv = (px) => 10 ** (lx[0] + ((px - box.l) / (box.r - box.l)) * (lx[1] - lx[0]));

  return { W, H, entries, legend, yLines, box, log, lx, ly, X, Y, inv };
}

/** The chart's background layer: legend, grid, ticks and axis labels (what an edit of the scene
 *  alone leaves unchanged, so the page redraws it only when it changes). */
export function drawChartBack(p, spec, g = chartGeometry(p, spec)) {
  const { W, H, entries, legend, yLines, box, log, lx, ly, X, Y } = g;
  p.rect(0, 0, W, H + (entries.length ? legend.height + 6 : 0), { fill: '#fff' });
  legend.rows.forEach((row) => row.items.forEach((e) => {
    const y = H + 4 + row.y + 6;
    // A swatch long enough to tell dashes (6/3) from long dashes (14/4).
    if (e.box) p.rect(e.x + 6, y - 5, 18, 10, { fill: e.color, alpha: 0.18, stroke: e.color });
    else p.line([[e.x, y], [e.x + 30, y]], { color: e.color, width: Math.max(1.5, e.width || 1.5), dash: e.dash });
    e.lines.forEach((line, k) => p.text(e.x + 36, y + 4 + k * 14, line, { size: 11 }));
  }));
  // x and y: the core's ticks (the terminal and the exported SVG/PNG draw the same), as many
  // labels as fit; a labelled tick carries a grid line, a minor one a short mark.
  const decadesX = lx[1] - lx[0];
  const xt = axisTicks(spec.xMin, spec.xMax, true, Math.max(2, Math.floor((box.r - box.l) / 46)));
  xt.values.forEach((v, i) => {
    const x = X(v);
    if (xt.labels[i] === null) { p.line([[x, box.b], [x, box.b - 4]], { color: TICK }); return; }
    p.line([[x, box.t], [x, box.b]], { color: GRID });
    p.line([[x, box.b], [x, box.b + 5]], { color: AXIS });
    p.text(x, box.b + 17, xt.labels[i], { size: 11, align: 'center' });
  });
  if (decadesX < 1.5) {
    // Less than two decades in view: label the edges too, so that the scale can be read.
    p.text(box.l, box.b + 30, qty(spec.xMin, 'm/s', 3), { size: 10, align: 'left', color: '#555' });
    p.text(box.r, box.b + 30, qty(spec.xMax, 'm/s', 3), { size: 10, align: 'right', color: '#555' });
  }
  const yt = axisTicks(spec.yMin, spec.yMax, log, log ? Math.max(2, Math.floor((box.b - box.t) / 18)) : Math.max(3, Math.floor((box.b - box.t) / 40)));
  yt.values.forEach((v, i) => {
    const y = Y(v);
    if (yt.labels[i] === null) { if (y < box.b) p.line([[box.l, y], [box.l + 4, y]], { color: TICK }); return; }
    p.line([[box.l, y], [box.r, y]], { color: GRID });
    p.line([[box.l - 5, y], [box.l, y]], { color: AXIS });
    p.text(box.l - 8, y + 4, yt.labels[i], { size: 11, align: 'right' });
  });
  p.text((box.l + box.r) / 2, H - 8, spec.xLabel, { size: 12, align: 'center' });
  // Rotated, centred on the plot (never on the figure with its caption), inside the canvas.
  yLines.forEach((line, k) => p.text(16 + 14 * k, (box.t + box.b) / 2, line, { size: 12, align: 'center', rotate: -Math.PI / 2 }));

}

/** The chart's data layer: bands, markers, series, hover cursor and the plot's frame. */
export function drawChartFront(p, spec, g = chartGeometry(p, spec)) {
  const { H, entries, legend, box, log, X, Y, inv } = g;
  p.clip(box.l, box.t, box.r - box.l, box.b - box.t, () => {
    for (const b of spec.bands || []) {
      const x0 = X(b.x[0]), x1 = X(b.x[1]), y0 = Y(b.y[1]), y1 = Y(b.y[0]);
      p.rect(x0, y0, x1 - x0, y1 - y0, { fill: b.color, alpha: 0.16, stroke: b.color });
      // The box's name only (its temperature and score are in the legend).
      // Inside the plot: near its right edge the name ends at the edge instead of being cut.
      const name = (b.short || '').split(' (')[0];
      if (x1 - x0 > 18) p.text(Math.max(box.l + 2, Math.min(x0 + 3, box.r - textWidth(name, 10) - 3)), y0 + 12, name, { size: 10, color: b.color });
    }
    const shown = (spec.markers || []).filter((m) => m.x > spec.xMin && m.x < spec.xMax);
    for (const m of shown) p.line([[X(m.x), box.t], [X(m.x), box.b]], { color: m.color || '#555', width: 1.2, dash: [2, 3] });
    // Series: broken where ε_N is not finite; on a log axis also where it is 0 (stuck).
    for (const s of spec.series) {
      let seg = [];
      const flush = () => { if (seg.length > 1) p.line(seg, { color: s.color, width: s.width || 1.5, dash: s.dash }); seg = []; };
      for (let i = 0; i < s.x.length; i++) {
        const v = s.y[i];
        const ok = Number.isFinite(v) && (log ? v > 0 && v >= spec.yMin * 0.5 : true);
        if (ok) seg.push([X(s.x[i]), Y(log ? Math.max(v, spec.yMin * 0.5) : v)]);
        else flush();
      }
      flush();
    }
    // The markers' labels over the curves (issue 37: the curves struck them through), one row each.
    shown.forEach((m, i) => {
      const x = X(m.x);
      let label = m.label;
      const fits = (t) => t.length * 5.9 + 6;
      let right = x + fits(label) <= box.r || x - fits(label) < box.l;
      if (x + fits(label) > box.r && x - fits(label) < box.l) {
        label = m.short || label;
        right = x + fits(label) <= box.r;
      }
      // Fitting neither side whole: inside the plot from its left edge (never cut by it).
      const inside = !right && x - fits(label) < box.l;
      p.text(inside ? box.l + 2 : x + (right ? 4 : -4), box.b - 8 - i * 15, label, { size: 10.5, color: AXIS, align: right || inside ? 'left' : 'right', bg: 'rgba(255,255,255,0.85)' });
    });
    if (spec.hover) {
      const x = X(spec.hover.x);
      p.line([[x, box.t], [x, box.b]], { color: '#888', width: 1 });
      if (Number.isFinite(spec.hover.y) && (log ? spec.hover.y >= spec.yMin : true)) p.circle(x, Y(spec.hover.y), 3.5, { fill: '#111' });
    }
  });
  p.rect(box.l, box.t, box.r - box.l, box.b - box.t, { stroke: AXIS });
  return { box, X, Y, inv, bottom: H + (entries.length ? legend.height + 6 : 0) };
}

/** The whole chart on one painter (exports): background, then data. */
export function drawChart(p, spec) {
  const g = chartGeometry(p, spec);
  drawChartBack(p, spec, g);
  return drawChartFront(p, spec, g);
}

/** Where the stick map's cells go on a W×H figure (the page reads it for hover). */
export function mapGeometry(W, H) {
  const size = Math.max(60, Math.min(W - 84, H - 50));
  return { size, box: { l: 70, t: 10, r: 70 + size, b: 10 + size }, bottom: 10 + size + 44 };
}

/** A note in place of a figure: a filled box and centred lines ({y, text, size, color}). */
export function drawNote(p, spec) {
  p.rect(0, 0, p.width, p.height, { fill: spec.fill, stroke: spec.stroke });
  for (const l of spec.lines) p.text(p.width / 2, l.y, l.text, { size: l.size, align: 'center', color: l.color });
}

/**
 * The stick map as Fig. 4 of the paper: g_T across, g_N up, both from 0 to `max` (linear).
 * spec: {n, codes (index i·n + j: g_N index i, g_T index j), max, colors (by code), hover: {i, j} | null,
 *        row: i | null (the g_N whose ε_T is plotted)}
 */
export function drawMap(p, spec) {
  const { width: W, height: H } = p;
  const { size, box } = mapGeometry(W, H);
  const n = spec.n;
  p.rect(0, 0, W, H, { fill: '#fff' });
  p.grid(box.l, box.t, size, size, n, spec.codes, spec.colors);
  const ticks = niceTicks(0, spec.max, size < 260 ? 3 : 5);
  for (const t of ticks) {
    const frac = t / spec.max;
    const x = box.l + frac * size;
    const y = box.b - frac * size;
    const label = t === 0 ? '0' : qty(t, 'm/s', 3);
    p.line([[x, box.b], [x, box.b + 5]], { color: AXIS });
    p.text(x, box.b + 17, label, { size: 10, align: frac > 0.95 ? 'right' : 'center' });
    p.line([[box.l - 5, y], [box.l, y]], { color: AXIS });
    p.text(box.l - 7, y + 4, label, { size: 10, align: 'right' });
  }
  p.rect(box.l, box.t, size, size, { stroke: AXIS });
  p.text(box.l + size / 2, box.b + 34, 'tangential speed g_T', { size: 12, align: 'center' });
  p.text(12, box.t + size / 2, 'normal (impact) speed g_N', { size: 12, align: 'center', rotate: -Math.PI / 2 });
  const c = size / n;
  if (spec.row !== null && spec.row !== undefined) {
    const y = box.t + (n - 1 - spec.row) * c;
    p.rect(box.l, y, size, c, { stroke: '#000000', width: 1 });
  }
  if (spec.hover) p.rect(box.l + spec.hover.j * c, box.t + (n - 1 - spec.hover.i) * c, c, c, { stroke: '#000000', width: 1.5 });
  return { box, size, bottom: box.b + 44 };
}

/**
 * A small line plot on linear axes (ε_T against g_T): spec {x, y, xMax, yMin, yMax, color, xLabel,
 * yLabel, title, hover: index | null}.
 */
export function drawLines(p, spec) {
  const { width: W, height: H } = p;
  const box = { l: 50, r: W - 10, t: 24, b: H - 40 };
  const X = (v) => box.l + (v / spec.xMax) * (box.r - box.l);
  const Y = (v) => box.b - ((v - spec.yMin) / (spec.yMax - spec.yMin)) * (box.b - box.t);
  p.rect(0, 0, W, H, { fill: '#fff' });
  p.text(box.l, 14, spec.title, { size: 11, bold: true });
  for (const t of niceTicks(spec.yMin, spec.yMax, 4)) {
    const y = Y(t);
    p.line([[box.l, y], [box.r, y]], { color: t === 0 ? '#999999' : GRID });
    p.text(box.l - 6, y + 4, sig(t, 2), { size: 10, align: 'right' });
  }
  for (const t of niceTicks(0, spec.xMax, box.r - box.l < 360 ? 3 : 5)) {
    const x = X(t);
    p.line([[x, box.b], [x, box.b + 4]], { color: AXIS });
    p.text(x, box.b + 16, t === 0 ? '0' : qty(t, 'm/s', 3), { size: 10, align: t / spec.xMax > 0.95 ? 'right' : 'center' });
  }
  p.text((box.l + box.r) / 2, H - 6, spec.xLabel, { size: 11, align: 'center' });
  p.text(14, (box.t + box.b) / 2, spec.yLabel, { size: 11, align: 'center', rotate: -Math.PI / 2 });
  p.clip(box.l, box.t, box.r - box.l, box.b - box.t, () => {
    let seg = [];
    const flush = () => { if (seg.length > 1) p.line(seg, { color: spec.color, width: 1.8 }); seg = []; };
    for (let k = 0; k < spec.x.length; k++) {
      if (Number.isFinite(spec.y[k])) seg.push([X(spec.x[k]), Y(spec.y[k])]); else flush();
    }
    flush();
    if (spec.hover !== null && spec.hover !== undefined && Number.isFinite(spec.y[spec.hover])) {
      p.circle(X(spec.x[spec.hover]), Y(spec.y[spec.hover]), 3.5, { fill: '#111111' });
    }
  });
  p.rect(box.l, box.t, box.r - box.l, box.b - box.t, { stroke: AXIS });
  return { box, X, Y };
}
