// The rime web explorer: controls, recompute (coalesced per animation frame), drawing, URL state.
import init, { Explorer } from './pkg/rime_wasm.js';
import {
  CLASS_COLORS, SERIES_COLORS, CanvasPainter, SvgPainter, drawChart, drawMap, fmtNum, fmtSpeed, prefixFor,
} from './plot.js';

const $ = (id) => document.getElementById(id);

// Slider ranges (UI only; the typed input accepts the registry's full range).
const SLIDER = {
  'grains.radius_1': [1e-6, 1],
  'grains.radius_2': [1e-6, 1],
  'grains.density': [100, 1e4],
  'bulk.youngs_modulus': [1e6, 1e12],
  'bulk.poisson_ratio': [-0.99, 0.5],
  'bulk.damping.time': [1e-8, 1e3],
  'bulk.damping.viscosities.shear': [1, 1e15],
  'bulk.damping.viscosities.bulk': [1, 1e15],
  'layer.thickness': [1e-9, 1e-3],
  'layer.viscosity': [1, 1e7],
  'adhesion.surface_energy': [1e-4, 10],
  'friction.coefficient': [0, 2],
  'friction.kappa': [0.01, 1],
};
const SLIDER_STEPS = 1000;
const GROUPS = [
  ['grains', 'Grains'],
  ['bulk', 'Bulk material (Eq. (4))'],
  ['contact_end', 'Contact'],
  ['layer', 'Soft layer (Eq. (8)–(10))'],
  ['adhesion', 'Adhesion (Eq. (11)–(17))'],
  ['friction', 'Friction (Eq. (18)–(26))'],
];
const FAMILIES = {
  layer: { path: 'layer.viscosity', values: [500, 1000, 2000, 5000], sym: 'η*', unit: 'Pa s' },
  adhesion: { path: 'adhesion.surface_energy', values: [0.05, 0.1, 0.2, 0.5], sym: 'γ', unit: 'J/m²' },
  damping: { path: 'bulk.damping.time', values: null, sym: 'A', unit: 's' },
};
const DEFAULT_VIEW = { accuracy: 'fast', from: 1e-7, to: 10, mapMax: null, experiments: true };
// Drawing styles of the experimental context (values come from wasm: Explorer.experiments()).
const BRIDGES_STYLE = { color: '#8a8a8a', width: 1.1, dash: [4, 3], label: 'Bridges et al. 1984' };
const BAND_STYLES = [
  { fill: 'rgba(78,121,167,0.16)', stroke: 'rgba(58,96,140,0.8)', short: 'H10' },
  { fill: 'rgba(225,87,89,0.14)', stroke: 'rgba(180,60,62,0.8)', short: 'H15' },
];
// The tidal calculator's fields: accepted units (factor to SI) and the first one shown.
const TIDAL_FIELDS = [
  { key: 'planet_mass', label: 'planet mass M', units: { kg: 1, t: 1e3 } },
  { key: 'distance', label: 'distance d', units: { m: 1, km: 1e3 } },
  { key: 'radius', label: 'grain radius r', units: { m: 1, cm: 1e-2, mm: 1e-3, 'µm': 1e-6, um: 1e-6 } },
  { key: 'density', label: 'density ρ', units: { 'kg/m³': 1, 'kg/m3': 1, 'g/cm³': 1e3, 'g/cm3': 1e3 } },
  { key: 'surface_energy', label: 'surface energy γ', units: { 'J/m²': 1, 'J/m2': 1, 'mJ/m²': 1e-3, 'mJ/m2': 1e-3 } },
];
// The inputs of the paper's appendix example (its printed numbers are for these).
const PAPER_TIDAL_INPUT = { planet_mass: 5.688e26, distance: 1.336e8, radius: 0.02, density: 900, surface_energy: 0.1 };
const CURVE_POINTS = 240;
const MAP_N = 120;

const app = {
  ex: null,
  view: { ...DEFAULT_VIEW },
  params: [],
  rows: new Map(),
  classes: [],
  statusNames: [],
  res: null,
  hover: { chart: null, map: null },
  chartGeom: null,
  mapGeom: null,
  timings: [],
  totals: [],
  pending: false,
  experiments: null, // {bridges: {a, b, g0, label}, bands: [{x, y, label}]}
  tidalIn: null, // null: the paper's example with the scene's grains; else the typed TidalInput
  tidalRows: new Map(),
};

// Exposed for tests and curious users.
window.rimeState = { ready: false, errors: [] };

function median(a) {
  if (!a.length) return NaN;
  const s = [...a].sort((x, y) => x - y);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

function parseSpeed(text) {
  const v = Number(String(text).trim().replace(/\s*m\/s$/, ''));
  if (!Number.isFinite(v) || v <= 0 || v > 1e6) throw new Error('must be a speed in (0, 1e6] m/s');
  return v;
}

// ---------- controls ----------

function toSlider(path, p, v) {
  const [lo, hi] = SLIDER[path] ?? [p.min, p.max];
  let f = p.log ? (Math.log10(v) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo)) : (v - lo) / (hi - lo);
  if (!Number.isFinite(f)) f = 0;
  return Math.round(Math.min(1, Math.max(0, f)) * SLIDER_STEPS);
}

function fromSlider(path, p, pos) {
  const [lo, hi] = SLIDER[path] ?? [p.min, p.max];
  const f = pos / SLIDER_STEPS;
  const v = p.log ? 10 ** (Math.log10(lo) + f * (Math.log10(hi) - Math.log10(lo))) : lo + f * (hi - lo);
  return Number(v.toPrecision(p.log ? 3 : 4));
}

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function setErr(path, msg) {
  const row = app.rows.get(path);
  if (!row) return;
  row.err.textContent = msg || '';
  row.root.classList.toggle('invalid', !!msg);
}

function apply(path, fn) {
  try {
    fn();
    setErr(path, '');
    schedule();
    return true;
  } catch (e) {
    setErr(path, String(e.message || e));
    return false;
  }
}

function buildControls() {
  const box = $('controls');
  box.append(el('h2', {}, 'Parameters'));
  box.append(el('p', { class: 'hint' }, 'Type a value with units (e.g. "2 kPa s", "5 µm") and press Enter, or drag the slider.'));
  for (const [prefix, title] of GROUPS) {
    const h = el('h3', {}, title);
    box.append(h);
    if (prefix === 'bulk') {
      // Damping form: A given directly or from viscosities.
      const sel = el('select', { id: 'damping-form', 'aria-label': 'damping given as' },
        el('option', { value: 'time' }, 'A given directly'),
        el('option', { value: 'viscosities' }, 'A from viscosities η₁, η₂'));
      sel.addEventListener('change', () => {
        if (sel.value === 'time') apply('bulk.damping.time', () => app.ex.set('bulk.damping.time', '1e-4'));
        else apply('bulk.damping.viscosities.formula', () => app.ex.set('bulk.damping.viscosities.formula', 'brilliantov'));
      });
      const root = el('div', { class: 'param choice' }, el('label', { class: 'name', for: 'damping-form' }, 'damping A'), sel);
      box.append(root);
    }
    for (const p of app.params.filter((q) => q.path === prefix || q.path.startsWith(prefix + '.'))) {
      if (p.kind === 'toggle') {
        const cb = el('input', { type: 'checkbox', id: `p-${p.path}`, 'aria-label': `${p.label} on` });
        cb.addEventListener('change', () => apply(p.path, () => app.ex.set(p.path, cb.checked ? 'on' : 'off')));
        const lab = el('label', { class: 'toggle' }, cb, ' on');
        h.append(lab);
        const err = el('span', { class: 'err' });
        h.after(err);
        app.rows.set(p.path, { p, root: h, cb, err });
      } else if (p.kind === 'choice') {
        const sel = el('select', { id: `p-${p.path}` }, ...p.options.map((o) => el('option', { value: o }, o)));
        sel.addEventListener('change', () => apply(p.path, () => app.ex.set(p.path, sel.value)));
        const err = el('span', { class: 'err' });
        const root = el('div', { class: 'param choice', 'data-path': p.path },
          el('label', { class: 'name', for: `p-${p.path}` }, p.label), sel, err);
        box.append(root);
        app.rows.set(p.path, { p, root, sel, err });
      } else {
        const id = `p-${p.path}`;
        const slider = el('input', { type: 'range', min: 0, max: SLIDER_STEPS, step: 1, 'aria-label': `${p.label} slider`, 'data-path': p.path });
        const typed = el('input', { type: 'text', id, inputmode: 'decimal', spellcheck: 'false', 'data-path': p.path, autocomplete: 'off' });
        const err = el('span', { class: 'err' });
        slider.addEventListener('input', () => {
          const v = fromSlider(p.path, p, Number(slider.value));
          if (apply(p.path, () => app.ex.setNumber(p.path, v))) typed.value = fmtNum(v, 4);
        });
        const commit = () => {
          const text = typed.value.trim();
          if (text === '') return;
          if (apply(p.path, () => app.ex.set(p.path, text))) typed.dataset.dirty = '';
        };
        typed.addEventListener('change', commit);
        typed.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
        typed.addEventListener('input', () => { typed.dataset.dirty = '1'; });
        const unitText = p.unit || (p.log ? '' : '–');
        const root = el('div', { class: 'param', 'data-path': p.path },
          el('label', { class: 'name', for: id }, p.label + (p.log ? '' : '')),
          slider,
          el('span', { class: 'typed' }, typed, el('span', { class: 'unit' }, unitText)),
          err);
        box.append(root);
        app.rows.set(p.path, { p, root, slider, typed, err });
      }
    }
  }
}

function syncControls() {
  const ex = app.ex;
  for (const [path, row] of app.rows) {
    const v = JSON.parse(ex.get(path));
    if (row.cb) {
      row.cb.checked = v === true;
    } else if (row.sel) {
      row.root.classList.toggle('inactive', v === null);
      if (v !== null) row.sel.value = v;
      else row.sel.selectedIndex = -1;
    } else {
      row.root.classList.toggle('inactive', v === null);
      if (v === null) {
        if (document.activeElement !== row.typed && !row.root.classList.contains('invalid')) row.typed.value = '';
        row.typed.placeholder = 'off';
      } else {
        row.slider.value = toSlider(path, row.p, v);
        if (document.activeElement !== row.typed && !row.root.classList.contains('invalid')) row.typed.value = fmtNum(v, 6);
      }
    }
  }
  const time = JSON.parse(ex.get('bulk.damping.time'));
  $('damping-form').value = time === null ? 'viscosities' : 'time';
  $('accuracy').value = app.view.accuracy;
  $('view-from').value = fmtNum(app.view.from, 6);
  $('view-to').value = fmtNum(app.view.to, 6);
  $('view-experiments').checked = app.view.experiments;
  $('chart-sources').hidden = !app.view.experiments;
  $('view-mapmax').value = app.view.mapMax === null ? '' : fmtNum(app.view.mapMax, 6);
}

// ---------- compute ----------

function schedule() {
  if (app.pending) return;
  app.pending = true;
  requestAnimationFrame(() => {
    app.pending = false;
    update();
  });
}

function familySpec(ex) {
  if (JSON.parse(ex.get('layer'))) return FAMILIES.layer;
  if (JSON.parse(ex.get('adhesion'))) return FAMILIES.adhesion;
  const a = ex.dampingTime();
  if (!(a > 0)) return null;
  return { ...FAMILIES.damping, values: [a / 10, a / 3, a * 3, a * 10].map((v) => Number(v.toPrecision(3))) };
}

function compute() {
  const ex = app.ex;
  const { accuracy, from, to } = app.view;
  const eps = ex.curve(from, to, CURVE_POINTS, accuracy);
  const g = ex.curveSpeeds();
  const status = ex.statuses();
  const clean = ex.cleanCurve(from, to, CURVE_POINTS, accuracy);
  const fam = familySpec(ex);
  let family = null;
  if (fam) {
    const flat = ex.family(fam.path, fam.values, from, to, CURVE_POINTS, accuracy);
    family = { ...fam, curves: fam.values.map((_, k) => flat.subarray(k * CURVE_POINTS, (k + 1) * CURVE_POINTS)) };
  }
  const crit = JSON.parse(ex.criticalVelocities(accuracy));
  const warnings = JSON.parse(ex.warnings(from, to));
  let map = null;
  const friction = JSON.parse(ex.get('friction'));
  let mapMax = app.view.mapMax;
  if (mapMax === null) {
    const vs = crit.map((c) => c.value).filter((v) => v > 0);
    mapMax = vs.length ? Number((6 * Math.max(...vs)).toPrecision(2)) : 0.1;
  }
  if (friction) {
    const codes = ex.stickMap(mapMax, MAP_N, accuracy);
    map = { n: MAP_N, max: mapMax, codes, epsT: ex.mapEpsT(), epsN: ex.mapEpsN(), g: ex.mapSpeeds() };
  }
  const tidal = JSON.parse(ex.tidal(app.tidalIn ? JSON.stringify(app.tidalIn) : ''));
  return { g, eps, status, clean, family, crit, warnings, map, mapMax, tidal, accuracy };
}

function update() {
  const t0 = performance.now();
  let res;
  try {
    res = compute();
  } catch (e) {
    window.rimeState.errors.push(String(e.message || e));
    $('timing').textContent = `error: ${e.message || e}`;
    return;
  }
  const t1 = performance.now();
  app.res = res;
  draw();
  showWarnings(res);
  showTidal(res.tidal);
  syncControls();
  writeHash();
  const t2 = performance.now();
  app.timings.push(t1 - t0);
  app.totals.push(t2 - t0);
  if (app.timings.length > 200) { app.timings.shift(); app.totals.shift(); }
  $('timing').textContent = `recompute ${(t1 - t0).toFixed(2)} ms (median ${median(app.timings).toFixed(2)} ms) · with redraw ${(t2 - t0).toFixed(1)} ms · ${res.accuracy}`;
  const s = window.rimeState;
  Object.assign(s, {
    ready: true,
    sceneJson: app.ex.toJson(),
    view: { ...app.view },
    g: Array.from(res.g),
    eps: Array.from(res.eps),
    status: Array.from(res.status, (c) => app.statusNames[c]),
    family: res.family && { path: res.family.path, values: res.family.values, curves: res.family.curves.map((c) => Array.from(c)) },
    critical: res.crit,
    warnings: res.warnings,
    mapClasses: res.map ? Array.from(res.map.codes) : null,
    overlay: experimentOverlay(),
    tidal: res.tidal,
    computeMs: [...app.timings],
    totalMs: [...app.totals],
    updates: (s.updates || 0) + 1,
  });
  document.body.dataset.updates = String(s.updates);
}

// ---------- drawing ----------

/** The Bridges et al. (1984) law ε = a (g/g0)^b, clipped at 1. */
function bridgesAt(g) {
  const b = app.experiments.bridges;
  return Math.min(1, b.a * (g / b.g0) ** b.b);
}

/** The experimental context drawn on the chart (null when switched off): the Bridges line over the
 *  view (with 1 cm/s itself as a point when in view) and the experiments' boxes. */
function experimentOverlay() {
  if (!app.view.experiments || !app.experiments) return null;
  const { from, to } = app.view;
  const n = 120;
  const x = [];
  for (let i = 0; i < n; i++) x.push(10 ** (Math.log10(from) + (i / (n - 1)) * (Math.log10(to) - Math.log10(from))));
  const g0 = app.experiments.bridges.g0;
  if (g0 > from && g0 < to && !x.includes(g0)) { x.push(g0); x.sort((a, b) => a - b); }
  return {
    bridges: { ...app.experiments.bridges, x, y: x.map(bridgesAt), at1cm: bridgesAt(0.01) },
    bands: app.experiments.bands.map((b, k) => ({ ...b, ...BAND_STYLES[k % BAND_STYLES.length] })),
  };
}

function chartSpec(res, hover) {
  const series = [];
  const overlay = experimentOverlay();
  if (overlay) series.push({ x: overlay.bridges.x, y: overlay.bridges.y, ...BRIDGES_STYLE });
  if (res.family) {
    res.family.values.forEach((v, k) => series.push({
      x: res.g, y: res.family.curves[k], color: SERIES_COLORS[k % SERIES_COLORS.length], width: 1.3,
      label: `${res.family.sym} = ${fmtNum(v, 3)} ${res.family.unit}`,
    }));
  }
  const hasEffect = JSON.parse(app.ex.get('layer')) || JSON.parse(app.ex.get('adhesion'));
  if (hasEffect) series.push({ x: res.g, y: res.clean, color: '#555', width: 1.4, dash: [6, 4], label: 'clean surface' });
  series.push({ x: res.g, y: res.eps, color: '#111', width: 2.4, label: 'this scene' });
  let minPos = 1;
  for (const arr of [res.eps, res.clean]) for (const v of arr) if (v > 0 && v < minPos) minPos = v;
  const yMin = Math.max(1e-12, 10 ** Math.floor(Math.log10(minPos) - 1e-9));
  const yMin2 = Math.min(yMin, 1e-2);
  let maxY = 1;
  for (const v of res.eps) if (v > maxY) maxY = v;
  // Critical velocities; the bisected stick threshold only where it differs from Eq. (10)/(15).
  const markers = [];
  for (const c of res.crit) {
    if (markers.some((m) => Math.abs(m.x / c.value - 1) < 0.01)) continue;
    markers.push({ x: c.value, label: `${c.label}: ${fmtSpeed(c.value)}`, short: `${c.key === 'stick' ? 'stick' : 'g_s'} ${fmtSpeed(c.value)}` });
  }
  return {
    xMin: app.view.from, xMax: app.view.to, yMin: yMin2, yMax: 10 ** Math.ceil(Math.log10(maxY) - 1e-12) || 1,
    xLabel: 'impact speed g_N [m/s]', yLabel: 'ε_N', series, markers, hover, bands: overlay ? overlay.bands : [],
  };
}

function canvasSize(canvas, aspect, maxH) {
  const w = Math.max(200, Math.floor(canvas.parentElement.clientWidth - 2));
  const h = Math.min(maxH, Math.max(220, Math.round(w * aspect)));
  return [w, h];
}

function draw() {
  if (!app.res) return;
  drawChartCanvas();
  drawMapCanvas();
  drawLegend(app.res);
}

function drawChartCanvas() {
  const res = app.res;
  const chart = $('chart');
  const narrow = chart.parentElement.clientWidth < 560;
  const [cw, ch] = canvasSize(chart, narrow ? 0.95 : 0.62, 520);
  app.chartGeom = drawChart(new CanvasPainter(chart, cw, ch), chartSpec(res, app.hover.chart));
}

function drawMapCanvas() {
  const res = app.res;
  const mapCanvas = $('map');
  const [mw] = canvasSize(mapCanvas, 1, 600);
  const mh = Math.min(mw, 560) - 10;
  if (res.map) {
    app.mapGeom = drawMap(new CanvasPainter(mapCanvas, mw, mh), {
      n: res.map.n, codes: res.map.codes, max: res.map.max, colors: CLASS_COLORS, hover: app.hover.map,
    });
  } else {
    const p = new CanvasPainter(mapCanvas, mw, 120);
    p.rect(0, 0, mw, 120, { fill: '#fafafa' });
    p.text(mw / 2, 60, 'friction is off: no tangential restitution, no stick map', { size: 13, align: 'center', color: '#666' });
    app.mapGeom = null;
  }
}

function drawLegend(res) {
  const counts = new Array(app.classes.length).fill(0);
  if (res.map) for (const c of res.map.codes) counts[c]++;
  const total = res.map ? res.map.codes.length : 0;
  const ul = $('legend');
  ul.replaceChildren(...app.classes.map((c, k) => el('li', { title: c.description },
    el('span', { class: 'sw', style: `background:${CLASS_COLORS[k]}` }),
    el('span', {}, c.description, ' ', el('span', { class: 'count' }, total ? `(${((100 * counts[k]) / total).toFixed(1)} %)` : '')))));
  res.classCounts = counts;
}

function showWarnings(res) {
  const items = res.warnings.map((w) => el('li', {}, w));
  const gap = app.classes.findIndex((c) => c.name === 'sliding_gap');
  if (res.map && gap >= 0 && res.classCounts && res.classCounts[gap] > 0) {
    items.push(el('li', { class: 'info' }, 'sliding law "paper": Eq. (23) has a negative radicand just above ψ₀ (class sliding_gap, clamped to ε_T = 0), which the paper does not mention; "walton" has no gap.'));
  }
  $('warnings').replaceChildren(...items);
}

/** Significant digits of a printed number (3.84e-11 → 3, 1.341e8 → 4). */
function printedDigits(v) {
  const m = v.toExponential().split('e')[0].replace('.', '').replace('-', '');
  return m.replace(/0+$/, '').length || 1;
}

/** Tidal numbers as the appendix prints them: exponent form outside [0.01, 1000). */
function fmtTidal(v, digits) {
  if (!Number.isFinite(v) || v === 0) return fmtNum(v);
  const a = Math.abs(v);
  if (a >= 0.01 && a < 1000) return String(Number(v.toPrecision(digits)));
  const [m, e] = v.toExponential(digits - 1).split('e');
  return `${Number(m)}e${Number(e)}`;
}

function parseQuantity(f, text) {
  const m = String(text).trim().match(/^([-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)\s*(.*)$/i);
  if (!m) throw new Error(`tidal.${f.key}: not a number ("${text}")`);
  const unit = m[2].trim();
  const factor = unit === '' ? 1 : f.units[unit];
  if (factor === undefined) throw new Error(`tidal.${f.key}: unknown unit "${unit}" (use ${Object.keys(f.units).join(', ')})`);
  const v = Number(m[1]) * factor;
  if (!Number.isFinite(v)) throw new Error(`tidal.${f.key}: not a finite number ("${text}")`);
  return v;
}

function buildTidal() {
  const box = $('tidal-inputs');
  for (const f of TIDAL_FIELDS) {
    const id = `t-${f.key}`;
    const typed = el('input', { type: 'text', id, inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off', 'data-field': f.key });
    const err = el('span', { class: 'err' });
    const root = el('div', { class: 'tparam', 'data-field': f.key },
      el('label', { for: id }, f.label),
      el('span', { class: 'typed' }, typed, el('span', { class: 'unit' }, Object.keys(f.units)[0])),
      err);
    const commit = () => {
      const text = typed.value.trim();
      if (text === '' || !app.res) return;
      try {
        const cand = { ...app.res.tidal.input, [f.key]: parseQuantity(f, text) };
        app.ex.tidal(JSON.stringify(cand)); // validates; throws naming the field
        app.tidalIn = cand;
        err.textContent = '';
        root.classList.remove('invalid');
        schedule();
      } catch (e) {
        let msg = String(e.message || e);
        if (!msg.includes(f.key)) msg = `tidal.${f.key}: ${msg}`;
        err.textContent = msg;
        root.classList.add('invalid');
      }
    };
    typed.addEventListener('change', commit);
    typed.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
    box.append(root);
    app.tidalRows.set(f.key, { f, root, typed, err });
  }
  $('tidal-reset').addEventListener('click', () => {
    app.tidalIn = null;
    for (const row of app.tidalRows.values()) { row.err.textContent = ''; row.root.classList.remove('invalid'); }
    schedule();
  });
}

function showTidal(t) {
  const r = t.result, q = t.paper, inp = t.input;
  for (const row of app.tidalRows.values()) {
    if (document.activeElement !== row.typed && !row.root.classList.contains('invalid')) row.typed.value = fmtNum(inp[row.f.key], 6);
  }
  $('tidal-source').textContent = app.tidalIn ? '(typed values)' : '(following the scene)';
  const example = Object.keys(PAPER_TIDAL_INPUT).every((k) => inp[k] === PAPER_TIDAL_INPUT[k]);
  // Notes on the paper's numbers apply to its example only; `always` notes to any input.
  const row = (name, v, unit, paper, note, always = false) => {
    let mark = '', cls = '';
    if (paper !== undefined && example) {
      const ok = Number(v.toPrecision(printedDigits(paper))) === paper;
      mark = ok ? ' ✓' : ' ⚠';
      cls = ok ? 'ok' : 'bad';
    }
    const text = example || always ? (note || '') : '';
    const tr = el('tr', {},
      el('td', {}, name),
      el('td', { class: 'num' }, Number.isFinite(v) ? `${fmtTidal(v, 4)} ${unit}` : '—'),
      el('td', { class: `num ${cls}` }, paper === undefined ? '—' : `${fmtTidal(paper, printedDigits(paper))} ${unit}${mark}`),
      el('td', { class: 'note' }, text));
    // On narrow screens the note goes on its own line below (CSS).
    return text ? [tr, el('tr', { class: 'note-row' }, el('td', { colspan: 3 }, text))] : [tr];
  };
  const rMax = r.r_max ?? NaN;
  $('tidal').replaceChildren(
    el('tr', {}, el('th', {}, 'quantity'), el('th', {}, 'computed'), el('th', {}, 'paper'), el('th', { class: 'note' }, 'note')),
    ...[row('ΔF tidal force difference (A.1)', r.delta_f, 'N', q.delta_f),
    row('F_s = πγR_eff, R_eff = r/2 (A.2)', r.surface_force, 'N', q.surface_force, 'the printed 6.28e-3 N is πγr, twice Eq. (A.2)'),
    row('πγr (what the paper prints as F_s)', r.surface_force_paper, 'N', q.surface_force),
    row('F_g mutual gravity (A.3)', r.gravity, 'N', undefined, 'not printed', true),
    row('d_Roche (A.7)', r.d_roche, 'm', q.d_roche),
    row('d_min (A.6)', r.d_min, 'm', q.d_min, 'printed 5.43e4 m is not reproduced: A.6 (both printed forms) gives 3.08e5 m, also inside the planet'),
    r.r_max === null
      ? row('r_max (A.5)', rMax, 'm', q.r_max, 'none: at or outside d_Roche self-gravity holds grains of any size', true)
      : row('r_max (A.5)', rMax, 'm', q.r_max, 'A.5 gives 37.72 m vs printed 37.6 m (0.3 %); r_max moves −27× any relative change of 4M/d³'),
  ].flat());
}

// ---------- hover ----------

function chartHover(ev) {
  if (!app.chartGeom || !app.res) return;
  const rect = $('chart').getBoundingClientRect();
  const x = ev.clientX - rect.left;
  const { box, inv } = app.chartGeom;
  if (x < box.l || x > box.r) return;
  const g = inv(x);
  try {
    const n = JSON.parse(app.ex.normal(g, 'fast'));
    app.hover.chart = { x: g, y: n.eps_n };
    $('chart-readout').textContent = `g_N = ${fmtSpeed(g, 4)} · ε_N = ${fmtNum(n.eps_n, 6)} · ${n.status}` +
      (n.t_c === null ? '' : ` · t_c = ${fmtNum(n.t_c, 3)} s`) + ` · ξ_max = ${fmtNum(n.xi_max, 3)} m`;
  } catch (e) {
    $('chart-readout').textContent = String(e.message || e);
  }
  drawChartCanvas();
}

function mapHover(ev) {
  const m = app.res && app.res.map;
  if (!m || !app.mapGeom) return;
  const rect = $('map').getBoundingClientRect();
  const { box, size } = app.mapGeom;
  const fx = (ev.clientX - rect.left - box.l) / size;
  const fy = (box.b - (ev.clientY - rect.top)) / size;
  if (fx < 0 || fx >= 1 || fy < 0 || fy >= 1) return;
  const i = Math.min(m.n - 1, Math.floor(fx * m.n));
  const j = Math.min(m.n - 1, Math.floor(fy * m.n));
  const k = i * m.n + j;
  app.hover.map = { i, j };
  const c = app.classes[m.codes[k]];
  $('map-readout').textContent = `g_N = ${fmtSpeed(m.g[i], 4)} · g_T = ${fmtSpeed(m.g[j], 4)} · ε_N = ${fmtNum(m.epsN[i], 5)} · ε_T = ${fmtNum(m.epsT[k], 5)} · ${c ? c.name : '?'}`;
  drawMapCanvas();
}

// ---------- URL state ----------

let hashTimer = null;
function writeHash() {
  // Coalesced: browsers throttle history.replaceState when it is called at slider rates.
  if (hashTimer !== null) return;
  hashTimer = setTimeout(() => { hashTimer = null; writeHashNow(); }, 150);
}

function writeHashNow() {
  const v = { ...app.view };
  const hash = `#s=${encodeURIComponent(app.ex.toJson())}&v=${encodeURIComponent(JSON.stringify(v))}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

function readView(obj) {
  const v = { ...DEFAULT_VIEW };
  if (obj === null || typeof obj !== 'object') throw new Error('view: not an object');
  if (obj.accuracy !== undefined) {
    if (!['fast', 'balanced', 'precise'].includes(obj.accuracy)) throw new Error('view.accuracy: fast, balanced or precise');
    v.accuracy = obj.accuracy;
  }
  if (obj.from !== undefined) v.from = parseSpeed(obj.from);
  if (obj.to !== undefined) v.to = parseSpeed(obj.to);
  if (!(v.from < v.to)) throw new Error('view: from must be below to');
  if (obj.mapMax !== undefined && obj.mapMax !== null) v.mapMax = parseSpeed(obj.mapMax);
  if (obj.experiments !== undefined) {
    if (typeof obj.experiments !== 'boolean') throw new Error('view.experiments: true or false');
    v.experiments = obj.experiments;
  }
  return v;
}

/** Applies the state in the hash; returns an error message or null. Leaves defaults on error. */
function loadHash() {
  const h = location.hash.slice(1);
  if (!h) return null;
  try {
    const q = new URLSearchParams(h);
    const s = q.get('s');
    if (s === null) throw new Error('no scene in the link');
    const view = q.get('v') ? readView(JSON.parse(q.get('v'))) : { ...DEFAULT_VIEW };
    const ex = Explorer.fromJson(s);
    app.ex.free();
    app.ex = ex;
    app.view = view;
    return null;
  } catch (e) {
    // Fall back to the defaults (also when a pasted link is broken after start).
    app.ex.free();
    app.ex = new Explorer();
    app.view = { ...DEFAULT_VIEW };
    return String(e.message || e);
  }
}

function showNotice(msg) {
  const n = $('notice');
  if (!msg) { n.hidden = true; n.textContent = ''; return; }
  n.hidden = false;
  n.textContent = `The link's state could not be read (${msg}); showing the default scene instead.`;
  window.rimeState.notice = n.textContent;
}

// ---------- downloads ----------

function download(name, type, data) {
  const url = URL.createObjectURL(data instanceof Blob ? data : new Blob([data], { type }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

function curvesCsv(res) {
  const cols = ['g_n', 'eps_n', 'status', 'eps_n_clean'];
  if (res.family) res.family.values.forEach((v) => cols.push(`eps_n[${res.family.path}=${v}]`));
  const lines = [cols.join(',')];
  for (let i = 0; i < res.g.length; i++) {
    const row = [res.g[i], res.eps[i], app.statusNames[res.status[i]], res.clean[i]];
    if (res.family) res.family.curves.forEach((c) => row.push(c[i]));
    lines.push(row.join(','));
  }
  return lines.join('\n') + '\n';
}

function mapCsv(m) {
  const lines = ['g_n,g_t,eps_n,eps_t,class'];
  for (let i = 0; i < m.n; i++) {
    for (let j = 0; j < m.n; j++) {
      const k = i * m.n + j;
      lines.push(`${m.g[i]},${m.g[j]},${m.epsN[i]},${m.epsT[k]},${app.classes[m.codes[k]].name}`);
    }
  }
  return lines.join('\n') + '\n';
}

/** The stick map with its legend on painter `make(width, height)`. */
function mapFigure(m, make) {
  const legendH = 18 * app.classes.length + 10;
  const p = make(560, 560 + legendH);
  const geom = drawMap(p, { n: m.n, codes: m.codes, max: m.max, colors: CLASS_COLORS, hover: null });
  app.classes.forEach((c, k) => {
    const y = geom.box.b + 50 + k * 18;
    p.rect(58, y - 11, 12, 12, { fill: CLASS_COLORS[k], stroke: '#0004' });
    p.text(76, y, c.description, { size: 11 });
  });
  p.height = geom.box.b + 50 + legendH;
  return p;
}

function mapSvg(m) {
  return mapFigure(m, (w, h) => new SvgPainter(w, h)).svg();
}

/** A PNG (Blob) of a figure drawn at a fixed size and 2× resolution on a detached canvas. */
function pngOf(drawFig) {
  const canvas = document.createElement('canvas');
  return new Promise((resolve, reject) => {
    try {
      drawFig(canvas);
      canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('PNG encoding failed'))), 'image/png');
    } catch (e) { reject(e); }
  });
}

function chartPng() {
  return pngOf((c) => drawChart(new CanvasPainter(c, 720, 460, 2), chartSpec(app.res, null)));
}

function mapPng() {
  return pngOf((c) => mapFigure(app.res.map, (w, h) => new CanvasPainter(c, w, h, 2)));
}

function wireDownloads() {
  $('dl-curves').addEventListener('click', () => app.res && download('rime-curves.csv', 'text/csv', curvesCsv(app.res)));
  $('dl-map').addEventListener('click', () => app.res && app.res.map && download('rime-map.csv', 'text/csv', mapCsv(app.res.map)));
  $('dl-chart-svg').addEventListener('click', () => {
    if (!app.res) return;
    const p = new SvgPainter(720, 460);
    drawChart(p, chartSpec(app.res, null));
    download('rime-chart.svg', 'image/svg+xml', p.svg());
  });
  $('dl-map-svg').addEventListener('click', () => app.res && app.res.map && download('rime-map.svg', 'image/svg+xml', mapSvg(app.res.map)));
  const png = (name, make) => make().then((b) => download(name, 'image/png', b))
    .catch((e) => { window.rimeState.errors.push(String(e.message || e)); });
  $('dl-chart-png').addEventListener('click', () => app.res && png('rime-chart.png', chartPng));
  $('dl-map-png').addEventListener('click', () => app.res && app.res.map && png('rime-map.png', mapPng));
  $('dl-scene').addEventListener('click', () => download('rime-scene.json', 'application/json', JSON.stringify(JSON.parse(app.ex.toJson()), null, 2) + '\n'));
  $('copy-link').addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(location.href);
      $('copy-status').textContent = 'link copied';
    } catch {
      $('copy-status').textContent = 'copy the address bar: it holds the full state';
    }
  });
}

// Exposed for the end-to-end test: the SVG and CSV texts the buttons download.
window.rimeExports = {
  chartSvg: () => { const p = new SvgPainter(720, 460); drawChart(p, chartSpec(app.res, null)); return p.svg(); },
  mapSvg: () => app.res.map && mapSvg(app.res.map),
  curvesCsv: () => curvesCsv(app.res),
  mapCsv: () => app.res.map && mapCsv(app.res.map),
  bridgesAt: (g) => bridgesAt(g),
  probe: (g) => JSON.parse(app.ex.normal(g, app.view.accuracy)),
};

// ---------- start ----------

function wireView() {
  $('accuracy').addEventListener('change', () => { app.view.accuracy = $('accuracy').value; schedule(); });
  const range = () => {
    try {
      const from = parseSpeed($('view-from').value);
      const to = parseSpeed($('view-to').value);
      if (!(from < to)) throw new Error('"from" must be below "to"');
      app.view.from = from; app.view.to = to;
      $('view-err').textContent = '';
      schedule();
    } catch (e) { $('view-err').textContent = e.message; }
  };
  $('view-experiments').addEventListener('change', () => { app.view.experiments = $('view-experiments').checked; schedule(); });
  $('view-from').addEventListener('change', range);
  $('view-to').addEventListener('change', range);
  $('view-mapmax').addEventListener('change', () => {
    const t = $('view-mapmax').value.trim();
    try {
      app.view.mapMax = t === '' || t === 'auto' ? null : parseSpeed(t);
      $('mapmax-err').textContent = '';
      schedule();
    } catch (e) { $('mapmax-err').textContent = e.message; }
  });
  $('preset').addEventListener('change', () => {
    const name = $('preset').value;
    if (!name) return;
    try {
      app.ex.loadPreset(name);
      for (const path of app.rows.keys()) setErr(path, '');
      schedule();
    } catch (e) { showNotice(e.message); }
  });
  const chart = $('chart');
  chart.addEventListener('pointermove', chartHover);
  chart.addEventListener('pointerdown', chartHover);
  chart.addEventListener('pointerleave', () => { app.hover.chart = null; if (app.res) drawChartCanvas(); });
  const map = $('map');
  map.addEventListener('pointermove', mapHover);
  map.addEventListener('pointerdown', mapHover);
  map.addEventListener('pointerleave', () => { app.hover.map = null; if (app.res) drawMapCanvas(); });
  let resizeQueued = false;
  window.addEventListener('resize', () => {
    if (resizeQueued) return;
    resizeQueued = true;
    requestAnimationFrame(() => { resizeQueued = false; draw(); });
  });
  window.addEventListener('hashchange', () => {
    showNotice(loadHash());
    schedule();
  });
}

async function main() {
  await init();
  app.ex = new Explorer();
  app.params = JSON.parse(Explorer.parameters());
  app.classes = JSON.parse(Explorer.classes());
  app.statusNames = JSON.parse(Explorer.statusNames());
  $('version').textContent = Explorer.version();
  const presets = JSON.parse(Explorer.presets());
  $('preset').replaceChildren(el('option', { value: '' }, '— choose —'),
    ...presets.map((p) => el('option', { value: p.name, title: p.description }, p.name)));
  app.experiments = JSON.parse(Explorer.experiments());
  buildControls();
  buildTidal();
  wireView();
  wireDownloads();
  showNotice(loadHash());
  update();
}

main().catch((e) => {
  window.rimeState.errors.push(String(e && e.message ? e.message : e));
  $('timing').textContent = `failed to start: ${e && e.message ? e.message : e}`;
});
