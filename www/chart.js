// The ε_N chart: its figure description from the drawn frame (curves, family, clean surface,
// pinned curve, measured laws, markers), drawn on the canvas and in the downloads alike; hover and
// keyboard readouts from the frame's own samples (computed at the chosen level, never stale);
// lin/log y axis; zoom and pan of the speed range; a text alternative.
import { HELP, PALETTE, qty, sig, speed } from './core.js';
import { $, el } from './dom.js';
import { CanvasPainter, drawChart } from './plot.js';
import { app } from './state.js';

/** The overlay the "experiments" switch adds: the Bridges et al. (1984) law, over its measured speeds. */
export const BRIDGES = 'atlas:bridges1984';

let geom = null;
let hooks = { schedule: () => {}, replay: () => {} };

/** The figure description of the chart for frame `res` seen through `view`. */
export function chartSpec(res, view, hover = null) {
  const P = PALETTE;
  const series = [];
  const bands = [];
  const markers = [];
  if (view.experiments && app.experiments) {
    app.experiments.bands.forEach((b) => bands.push({ x: b.x, y: b.y, color: P.experiment, label: b.label, short: b.label.split(' ')[0] }));
  }
  // Measured laws and other models, beneath the scene's own curves.
  let k = 0;
  for (const o of res.overlays || []) {
    const fromSwitch = o.key === BRIDGES && view.experiments && !view.overlays.includes(BRIDGES);
    const color = o.key === BRIDGES && view.experiments ? P.experiment : P.overlay[k++ % P.overlay.length];
    const model = o.key.startsWith('model:');
    if (o.band) {
      bands.push({ x: [o.g[0], o.g[1]], y: [o.eps[0], o.eps[1]], color, label: o.label, short: o.key.split(':')[1] });
    } else {
      series.push({
        x: o.g, y: o.eps, color, width: 1.6, dash: model ? [2, 3] : [6, 3],
        label: fromSwitch ? 'Bridges et al. 1984 (measured speeds only)' : model ? o.key.slice(6) : o.label,
      });
    }
    for (const s of o.speeds) markers.push({ x: s.value, label: `${o.key.slice(6)} ${s.name}: ${speed(s.value)}`, short: `${s.name} ${speed(s.value)}`, color });
  }
  if (res.family) {
    const f = res.family;
    f.values.forEach((v, i) => {
      if (!f.curves[i]) return;
      const value = `${qty(v, f.unit, 3)}${f.isScene && f.isScene[i] ? ' (= this scene)' : ''}`;
      series.push({
        x: res.g, y: f.curves[i], color: P.family[i % P.family.length], width: 1.3,
        label: i === 0 ? `family, ${f.sym} varied around this scene: ${value}` : `${f.sym} = ${value}`,
      });
    });
  }
  if (res.clean) series.push({ x: res.g, y: res.clean, color: P.clean, width: 1.6, dash: [6, 4], label: 'clean surface (no layer, no adhesion)' });
  if (app.pinned) series.push({ x: app.pinned.g, y: app.pinned.eps, color: P.scene, width: 1.8, dash: [5, 3], label: `pinned: ${app.pinned.label}` });
  if (res.eps) series.push({ x: res.g, y: res.eps, color: P.scene, width: 2.6, label: res.gaps ? 'this scene (gaps: failed)' : 'this scene' });
  // Critical speeds of this scene, in its colour; the bisected threshold only where it differs.
  const crit = [];
  for (const c of res.crit) {
    if (crit.some((m) => Math.abs(m.x / c.value - 1) < 0.01)) continue;
    crit.push({ x: c.value, label: `${c.label}: ${speed(c.value)}`, short: `${c.key === 'stick' ? 'stick' : 'g_s'} ${speed(c.value)}`, color: P.critical });
  }
  const lin = view.yScale === 'lin';
  let minPos = 1, maxY = 1;
  for (const arr of [res.eps, res.clean]) if (arr) for (const v of arr) { if (v > 0 && v < minPos) minPos = v; if (v > maxY) maxY = v; }
  const yMin = lin ? 0 : Math.min(Math.max(1e-12, 10 ** Math.floor(Math.log10(minPos) - 1e-9)), 1e-2);
  const yMax = lin ? Math.max(1, maxY) : 10 ** Math.ceil(Math.log10(maxY) - 1e-12) || 1;
  return {
    xMin: view.from, xMax: view.to, yScale: lin ? 'lin' : 'log', yMin, yMax,
    xLabel: 'impact speed g_N [m/s]', yLabel: lin ? 'ε_N (linear)' : 'ε_N (log)',
    series, bands, markers: [...crit, ...markers.filter((m) => m.x > view.from && m.x < view.to)], hover,
  };
}

function size(canvas, width) {
  const w = Math.max(240, Math.floor((width ?? canvas.parentElement.clientWidth) - 2));
  const narrow = w < 560;
  // Never taller than about half a phone screen: the page must scroll past it.
  const maxH = Math.min(520, Math.max(260, Math.round(window.innerHeight * 0.55)));
  return [w, Math.min(maxH, Math.max(240, Math.round(w * (narrow ? 0.8 : 0.6))))];
}

/** Draws the chart of the frame on screen (with the hover cursor). */
export function drawChartCanvas(width) {
  const res = app.res;
  if (!res) return;
  const canvas = $('chart');
  const [w, h] = size(canvas, width);
  const i = app.hover.chart;
  const hover = i === null || i >= res.g.length ? null : { x: res.g[i], y: res.eps ? res.eps[i] : NaN };
  geom = drawChart(new CanvasPainter(canvas, w, h), chartSpec(res, app.drawn.view, hover));
  describe(res);
  readout();
}

/** The readout at the cursor: the frame's own values at its nearest sample. */
function readout() {
  const res = app.res;
  const i = app.hover.chart;
  const out = $('chart-readout');
  if (!res || i === null || i >= res.g.length) { out.textContent = 'hover, tap or use ←/→ on the chart for values'; return; }
  const parts = [`g_N = ${speed(res.g[i], 4)}`];
  if (res.eps) parts.push(`ε_N = ${sig(res.eps[i], 6)} (${app.statusNames[res.status[i]] ?? 'failed'})`);
  if (res.clean) parts.push(`clean ${sig(res.clean[i], 4)}`);
  if (app.pinned && app.pinned.g.length === res.g.length && app.pinned.g[i] === res.g[i]) parts.push(`pinned ${sig(app.pinned.eps[i], 4)}`);
  parts.push(`at ${res.accuracy}`);
  out.textContent = parts.join(' · ');
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
  $('chart-desc').textContent = parts.join(' ');
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
  const min = Math.log10(HELP.limits.speedMin), max = Math.log10(HELP.limits.speedMax);
  const half = Math.min(span, max - min) / 2;
  c = Math.min(max - half, Math.max(min + half, c));
  v.from = Number((10 ** (c - half)).toPrecision(6));
  v.to = Number((10 ** (c + half)).toPrecision(6));
  hooks.schedule();
}

/** Keeps the current curve to compare with later edits (or drops it). */
export function pin(on) {
  if (!on || !app.res || !app.res.eps) { app.pinned = null; } else {
    const values = { ...app.res.values };
    app.pinned = { g: Array.from(app.res.g), eps: Array.from(app.res.eps), values, label: 'scene when pinned' };
  }
  pinLabel();
  $('pin').setAttribute('aria-pressed', String(!!app.pinned));
  $('pin').textContent = app.pinned ? 'unpin the curve' : 'pin this curve';
  drawChartCanvas();
}

/** The pinned curve's legend: which parameters differ from the scene drawn now. */
export function pinLabel() {
  if (!app.pinned || !app.res) { $('pin-note').textContent = ''; return; }
  const diff = [];
  for (const p of app.params) {
    const a = app.pinned.values[p.path], b = app.res.values[p.path];
    if (a !== b && !(a === null && b === null)) {
      const show = (x) => (x === null ? 'off' : typeof x === 'number' ? qty(x, p.unit, 4) : String(x));
      diff.push(`${p.label.split(' ')[0]} ${show(a)}`);
    }
  }
  app.pinned.label = diff.length ? diff.slice(0, 3).join(', ') + (diff.length > 3 ? ', …' : '') : 'same scene';
  $('pin-note').textContent = `Pinned (dashed): ${app.pinned.label}.`;
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
}

/** The family's meaning, beside the chart. */
export function familyNote(res) {
  const f = res.family;
  $('family-note').replaceChildren(...(f ? [
    el('strong', {}, 'Family: '),
    `${f.sym} varied around this scene (${f.values.map((v, i) => qty(v, f.unit, 3) + (f.isScene && f.isScene[i] ? ' = this scene' : '')).join(', ')}), every other parameter as in the scene.`,
  ] : []));
}
