// The ε_N chart: its figure description from the drawn frame (curves, family, clean surface,
// pinned curve, measured laws, markers), drawn on the canvas and in the downloads alike; hover and
// keyboard readouts from the frame's own samples (computed at the chosen level, never stale);
// lin/log y axis; zoom and pan of the speed range; a text alternative.
import { HELP, PALETTE, qty, sig, speed } from './core.js';
import { $, debounced, DESCRIBE_AFTER_MS, el, followLater, setText, viewportHeight } from './dom.js';
import { CanvasPainter, chartGeometry, chartLegendHeight, drawChartBack, drawChartFront, sizeElement } from './plot.js';
import { app } from './state.js';

let geom = null;
let backKey = null;
let backDraws = 0;
let frontDraws = 0;
// What the painter worker last drew (a hover alone then posts only the cursor).
let posted = { res: null, key: null };

/** What the background layer shows: size, axes, labels and the legend's entries. */
function backgroundKey(spec, w, h) {
  const legend = spec.series.map((s) => [s.label, s.short, s.color, s.dash, s.width])
    .concat((spec.bands || []).map((b) => [b.label, b.short, b.color]));
  return JSON.stringify([w, h, window.devicePixelRatio, spec.xMin, spec.xMax, spec.yScale, spec.yMin,
    spec.yMax, spec.xLabel, spec.yLabel, spec.shortLabels, legend]);
}
let hooks = { schedule: () => {}, replay: () => {} };

/**
 * The drawing description of the chart: the core's figure description of the frame (series in
 * draw order, measured data beneath the model, axes as the view asks, markers, bands, the pinned
 * curve, the other models' characteristic speeds, the palette, the short labels) turned into the
 * painters' terms. The screen and the downloads both draw this.
 */
export function chartSpec(res, view, hover = null, { shortLabels = false } = {}) {
  const fig = res.figures[0];
  const color = (i) => PALETTE.series[i] || '#000000';
  const series = fig.series.map((s) => {
    const top = color(s.color) === PALETTE.scene && s.stroke === 'solid';
    const dash = { dashed: [6, 3], dotted: [2, 3], longdash: [14, 4] }[s.stroke] || null;
    return { x: s.x, y: s.y, color: color(s.color), width: s.width || (top ? 2.6 : 1.5), dash, label: s.name, short: s.short };
  });
  const bands = fig.bands.map((b) => ({ x: b.x, y: b.y, color: color(b.color), label: b.label, short: b.short }));
  const markers = fig.markers.map((m) => ({ x: m.x, label: m.label, short: m.short, color: color(m.color) }));
  return {
    xMin: fig.x.min, xMax: fig.x.max, yScale: fig.y.log ? 'log' : 'lin', yMin: fig.y.min, yMax: fig.y.max,
    xLabel: fig.x.label, yLabel: fig.y.label,
    series, bands, markers: markers.filter((m) => m.x > fig.x.min && m.x < fig.x.max), hover, shortLabels,
  };
}

function size(canvas, width) {
  const w = Math.max(240, Math.floor((width ?? canvas.parentElement.clientWidth) - 2));
  const narrow = w < 560;
  // Never taller than about half a phone screen: the page must scroll past it.
  const maxH = Math.min(520, Math.max(260, Math.round(viewportHeight() * 0.62)));
  return [w, Math.min(maxH, Math.max(240, Math.round(w * (narrow ? 1.05 : 0.6))))];
}

/** Draws the chart of the frame on screen (with the hover cursor). */
export function drawChartCanvas(width) {
  const res = app.res;
  if (!res) return;
  const canvas = $('chart');
  const [w, h] = size(canvas, width);
  const i = app.hover.chart;
  const hover = i === null || i >= res.g.length ? null : { x: res.g[i], y: res.eps ? res.eps[i] : NaN };
  // On screen the legend beneath the plot takes the core's short labels (the full ones are in the
  // downloads, the Compare list and the text alternative); the plot keeps its height.
  const spec = { ...chartSpec(res, app.drawn.view, hover, { shortLabels: true }), plotHeight: h };
  const total = h + chartLegendHeight(spec, w);
  // Two layers: the background (legend, grid, ticks, labels) is redrawn only when it changes; a
  // slider step or a hover redraws the data layer alone (issue 26: the redraw was the main
  // thread's cost per frame).
  const back = backgroundKey(spec, w, total);
  const backChanged = back !== backKey;
  if (app.painter) {
    // Drawn in the painter worker (issue 26): here only the layout and what to draw.
    for (const c of [canvas, $('chart-fg')]) sizeElement(c, w, total);
    const g = chartGeometry({ width: w, height: total }, spec);
    const same = posted.res === res && posted.key === back && !backChanged;
    if (same) app.painter.hover(hover);
    else app.painter.chart(spec, w, total, backChanged);
    posted = { res, key: back };
    const { box, X, Y, inv, H, entries, legend } = g;
    geom = { box, X, Y, inv, bottom: H + (entries.length ? legend.height + 6 : 0) };
  } else {
    const front = new CanvasPainter($('chart-fg'), w, total);
    const g = chartGeometry(front, spec);
    if (backChanged) drawChartBack(new CanvasPainter(canvas, w, total), spec, g);
    geom = drawChartFront(front, spec, g);
  }
  if (backChanged) {
    backKey = back;
    backDraws++;
  }
  window.rimeState.chartLayers = { backDraws, frontDraws: ++frontDraws };
  window.rimeState.chartPlot = { ...geom.box, legendBottom: geom.bottom };
  describeSoon();
  readout();
}

const describeLater = debounced(DESCRIBE_AFTER_MS, 'timer:describe');
/** The text alternative follows once the frames pause (it also saves each frame its formatting). */
function describeSoon() {
  describeLater(() => { if (app.res && app.drawn) describe(app.res); });
}

/** The readout at the cursor: the frame's own values at its nearest sample. */
function readout() {
  const res = app.res;
  const i = app.hover.chart;
  const out = $('chart-readout');
  if (!res || i === null || i >= res.g.length) { setText(out, 'hover, tap or use ←/→ on the chart for values'); return; }
  const parts = [`g_N = ${speed(res.g[i], 4)}`];
  if (res.eps) parts.push(`ε_N = ${sig(res.eps[i], 6)} (${app.statusNames[res.status[i]] ?? 'failed'})`);
  if (res.clean) parts.push(`clean ${sig(res.clean[i], 4)}`);
  if (app.pinned && app.pinned.g[i] === res.g[i]) parts.push(`pinned ${sig(app.pinned.eps[i], 4)}`);
  parts.push(`at ${res.accuracy}`);
  setText(out, parts.join(' · '));
}

/** A text alternative of the chart (for screen readers; also visible on request). */
function describe(res) {
  const v = app.drawn.view;
  const parts = [`ε_N of this scene against the impact speed g_N from ${speed(v.from)} to ${speed(v.to)}, ${v.yScale === 'lin' ? 'linear' : 'logarithmic'} ε_N axis.`];
  if (res.eps) {
    const n = res.eps.length;
    parts.push(`ε_N is ${sig(res.eps[0], 3)} at ${speed(res.g[0])} and ${sig(res.eps[n - 1], 3)} at ${speed(res.g[n - 1])}.`);
    const stuck = Array.from(res.eps).filter((e) => e === 0).length;
    if (stuck) parts.push(`The grains stick (ε_N = 0) at ${stuck} of ${n} speeds.`);
  }
  for (const c of res.crit) parts.push(`${c.label}: ${speed(c.value)}.`);
  if (res.family) parts.push(`Family: ${res.family.sym} varied around this scene (${res.family.values.map((x) => qty(x, res.family.unit, 3)).join(', ')}).`);
  if (app.pinned) parts.push(`A pinned curve (${app.pinned.label}) is drawn dashed.`);
  setText($('chart-desc'), parts.join(' '));
}

function nearest(g) {
  const gs = app.res.g;
  let best = 0;
  for (let k = 1; k < gs.length; k++) if (Math.abs(Math.log(gs[k] / g)) < Math.abs(Math.log(gs[best] / g))) best = k;
  return best;
}

function pointer(ev) {
  if (!geom || !app.res) return null;
  const x = ev.clientX - $('chart').getBoundingClientRect().left;
  if (x < geom.box.l || x > geom.box.r) return null;
  return nearest(geom.inv(x));
}

/** Zooms the speed range by `factor` (< 1 in) around its centre, or pans it by `shift` of its span. */
export function zoom(factor, shift = 0) {
  const v = app.view;
  const lo = Math.log10(v.from), hi = Math.log10(v.to);
  const span = Math.max(0.2, (hi - lo) * factor);
  let c = (lo + hi) / 2 + shift * (hi - lo);
  const min = Math.log10(HELP.limits.speed_min), max = Math.log10(HELP.limits.speed_max);
  const half = Math.min(span, max - min) / 2;
  c = Math.min(max - half, Math.max(min + half, c));
  v.from = Number(sig(10 ** (c - half), 6));
  v.to = Number(sig(10 ** (c + half), 6));
  hooks.schedule();
}

/** Keeps the current curve to compare with later edits (or drops it). */
export function pin(on) {
  // A preview is never pinned (issue 26): the pin waits for the requested level.
  if (on && app.preview) { pinButton(); return; }
  if (!on || !app.res || !app.res.eps) { app.pinned = null; } else {
    const v = app.drawn.view;
    app.pinned = {
      g: Array.from(app.res.g), eps: Array.from(app.res.eps), scene: app.drawn.scene, label: 'same scene',
      // What computes it again, for the link.
      source: { scene: app.drawn.scene, accuracy: v.accuracy, from: v.from, to: v.to },
    };
  }
  pinLabel();
  pinButton();
  // The core draws the pinned curve into the figure: ask for the frame again.
  hooks.schedule();
}

/** A pinned curve computed again from the link (`source`: its scene, level and speeds). */
export function restorePin(source, g, eps) {
  app.pinned = { g: Array.from(g), eps: Array.from(eps), scene: source.scene, label: 'same scene', source };
  pinLabel();
  pinButton();
}

function pinButton() {
  $('pin').setAttribute('aria-pressed', String(!!app.pinned));
  $('pin').textContent = app.pinned ? 'unpin the curve' : 'pin this curve';
}

/** What the pinned scene (JSON) had that `current` (JSON) has not, in a few words. */
export function pinnedDiff(pinnedScene, current) {
  const a = JSON.parse(pinnedScene), b = JSON.parse(current);
  const walk = (o, path) => path.split('.').reduce((x, k) => (x !== null && x !== undefined && typeof x === 'object' ? x[k] : undefined), o);
  const diff = [];
  for (const p of app.params) {
    const va = walk(a, p.path), vb = walk(b, p.path);
    if (p.kind === 'toggle') {
      if ((va === null) !== (vb === null)) diff.push(`${p.label} ${va === null ? 'off' : 'on'}`);
    } else if (va !== vb && va !== undefined && va !== null) {
      diff.push(`${p.label.split(' ')[0]} ${typeof va === 'number' ? (p.unit ? qty(va, p.unit, 4) : sig(va, 4)) : va}`);
    }
  }
  return diff.length ? diff.slice(0, 3).join(', ') + (diff.length > 3 ? ', …' : '') : 'same scene';
}

/** The pinned curve for the request (the core draws it into the figure), labelled by what differs. */
export function pinnedForRequest(wantScene) {
  if (!app.pinned) return null;
  app.pinned.label = pinnedDiff(app.pinned.scene, wantScene);
  return { label: app.pinned.label, g: app.pinned.g, eps: app.pinned.eps.map((e) => (Number.isFinite(e) ? e : null)) };
}

/** The pinned curve's note beside the chart. */
export function pinLabel() {
  // Before any edit the pinned curve is the one on screen (issue 37: it read "with same scene").
  const text = !app.pinned ? ''
    : app.pinned.label === 'same scene' ? 'Pinned (dashed grey): this curve, as it is now; edit a parameter to compare with it.'
      : `Pinned (dashed grey): the curve of the scene with ${app.pinned.label}.`;
  setText($('pin-note'), text);
}

export function wireChart(h) {
  hooks = h;
  const chart = $('chart');
  chart.addEventListener('pointermove', (ev) => {
    const i = pointer(ev);
    if (i === null) return;
    app.hover.chart = i;
    drawChartCanvas();
  });
  chart.addEventListener('pointerleave', () => { app.hover.chart = null; drawChartCanvas(); });
  chart.addEventListener('click', (ev) => {
    const i = pointer(ev);
    if (i === null) return;
    app.hover.chart = i;
    // A tap sends no pointermove (and its pointerleave cleared the cursor just before): the click
    // draws the cursor and readout itself, and they stay (issue 37).
    drawChartCanvas();
    hooks.replay(app.res.g[i]);
  });
  chart.addEventListener('keydown', (ev) => {
    if (!app.res) return;
    const n = app.res.g.length;
    const i = app.hover.chart ?? Math.floor(n / 2);
    const step = ev.shiftKey ? 10 : 1;
    if (ev.key === 'ArrowRight') app.hover.chart = Math.min(n - 1, i + step);
    else if (ev.key === 'ArrowLeft') app.hover.chart = Math.max(0, i - step);
    else if (ev.key === '+' || ev.key === '=') return zoom(0.5);
    else if (ev.key === '-') return zoom(2);
    // `,` and `.` pan the speed range, as in the terminal; ←/→ move the readout cursor.
    else if (ev.key === ',' || ev.key === '<') return zoom(1, -0.25);
    else if (ev.key === '.' || ev.key === '>') return zoom(1, 0.25);
    else if (ev.key === 'Enter' || ev.key === ' ') { hooks.replay(app.res.g[i]); app.hover.chart = i; } else return;
    ev.preventDefault();
    drawChartCanvas();
  });
  chart.addEventListener('blur', () => { app.hover.chart = null; drawChartCanvas(); });
  $('zoom-in').addEventListener('click', () => zoom(0.5));
  $('zoom-out').addEventListener('click', () => zoom(2));
  $('pan-left').addEventListener('click', () => zoom(1, -0.25));
  $('pan-right').addEventListener('click', () => zoom(1, 0.25));
  $('pin').addEventListener('click', () => pin(!app.pinned));
  for (const r of document.querySelectorAll('input[name="yscale"]')) {
    r.addEventListener('change', () => { if (r.checked) { app.view.yScale = r.value; hooks.schedule(); } });
  }
  pinButton();
}

/** The family's meaning, beside the chart. */
export function familyNote(res) {
  const f = res.family;
  const key = f ? JSON.stringify([f.sym, f.values, f.unit, f.isScene]) : '';
  // Written once the frames pause (the values of a derived parameter change at every step).
  followLater($('family-note'), key, () => $('family-note').replaceChildren(...(f ? [
    el('strong', {}, 'Family: '),
    `${f.sym} varied around this scene (${f.values.map((v, i) => qty(v, f.unit, 3) + (f.isScene && f.isScene[i] ? ' = this scene' : '')).join(', ')}), every other parameter as in the scene.`,
  ] : [])));
}
