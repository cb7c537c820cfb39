// The rime web explorer: controls, requests to the computing worker (coalesced per animation
// frame), drawing of the frame it returns, URL state. Each part of a frame fails on its own: what
// succeeded is drawn, the failing part leaves a note in its place, the banner names the cause and
// the console gets the error; controls and the link always show the scene actually drawn.
import init, { Explorer } from './pkg/rime_wasm.js';
import { Computer } from './compute.js';
import { CollisionView } from './collision.js';
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
const DEFAULT_VIEW = { accuracy: 'fast', from: 1e-7, to: 10, mapMax: null, experiments: true, overlays: [] };
// Colours of the overlays (measured laws solid, other models dotted), in the order chosen.
const OVERLAY_COLORS = ['#0072b2', '#e69f00', '#009e73', '#cc79a7', '#56b4e9', '#d55e00', '#000000'];
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
  ex: null, // the scene being edited (main thread: validation only; always valid)
  wantScene: null, // its JSON, the newest scene asked of the worker
  drawn: null, // {scene, view} of the frame on screen
  computer: null,
  hoverEx: null, // the drawn scene, for hover readouts (set lazily)
  hoverScene: null,
  calls: 0, // calls across the wasm boundary on the main thread since the last drawn frame
  callsPerUpdate: [],
  bannerKey: '',
  bannerDismissed: '',
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
// Test hook: parts of the frame to fail on purpose (see the view's `fail` in wasm/src/frame.rs).
window.rimeTest = { fail: [], delayMs: 0 };

/** Counts the calls made across the wasm boundary through `obj` (an Explorer). */
function counted(obj) {
  return new Proxy(obj, {
    get(t, k) {
      const v = t[k];
      if (typeof v !== 'function') return v;
      return (...args) => { app.calls++; return v.apply(t, args); };
    },
  });
}

const errText = (e) => String(e && e.message ? e.message : e);

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

/** Applies one edit through the core; a value it rejects is refused at the control (message naming
 *  the field, also to the console) and the control goes back to the drawn scene. */
function apply(path, fn) {
  try {
    fn();
    app.wantScene = app.ex.toJson();
    setErr(path, '');
    schedule();
    return true;
  } catch (e) {
    let msg = errText(e);
    if (!msg.includes(path)) msg = `${path}: ${msg}`;
    setErr(path, msg);
    console.error(`rime: refused: ${msg}`);
    revertRow(path);
    return false;
  }
}

/** Shows the drawn scene's value in the control of `path` again. */
function revertRow(path) {
  const row = app.rows.get(path);
  if (!row || !app.res) return;
  const v = app.res.values[path];
  if (row.typed) {
    row.typed.dataset.dirty = '';
    row.typed.value = v === null || v === undefined ? '' : fmtNum(v, 6);
    if (v !== null && v !== undefined) row.slider.value = toSlider(path, row.p, v);
  }
  if (row.sel) row.sel.value = v ?? '';
  if (row.cb) row.cb.checked = v === true;
  syncDampingForm();
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
        // Enter fires `change` too (committing twice would cost a second pass through the core).
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

function syncDampingForm() {
  if (!app.res) return;
  $('damping-form').value = app.res.values['bulk.damping.time'] === null ? 'viscosities' : 'time';
}

/** Shows the drawn scene and view in every control (a field being typed in keeps its text). */
function syncControls() {
  const values = app.res.values;
  for (const [path, row] of app.rows) {
    const v = values[path];
    if (row.cb) {
      row.cb.checked = v === true;
    } else if (row.sel) {
      row.root.classList.toggle('inactive', v === null);
      if (v !== null) row.sel.value = v;
      else row.sel.selectedIndex = -1;
    } else {
      row.root.classList.toggle('inactive', v === null);
      const typing = document.activeElement === row.typed && row.typed.dataset.dirty === '1';
      if (v === null) {
        if (!typing) row.typed.value = '';
        row.typed.placeholder = 'off';
      } else {
        row.slider.value = toSlider(path, row.p, v);
        if (!typing) row.typed.value = fmtNum(v, 6);
      }
    }
  }
  syncDampingForm();
  const view = app.drawn.view;
  $('accuracy').value = view.accuracy;
  const keep = (id) => document.activeElement === $(id) && $(id).dataset.dirty === '1';
  if (!keep('view-from')) $('view-from').value = fmtNum(view.from, 6);
  if (!keep('view-to')) $('view-to').value = fmtNum(view.to, 6);
  $('view-experiments').checked = view.experiments;
  for (const box of document.querySelectorAll('#overlay-list input')) box.checked = view.overlays.includes(box.value);
  $('chart-sources').hidden = !view.experiments;
  if (!keep('view-mapmax')) $('view-mapmax').value = view.mapMax === null ? '' : fmtNum(view.mapMax, 6);
}

// ---------- compute ----------

function schedule() {
  if (app.pending) return;
  app.pending = true;
  requestAnimationFrame(() => {
    app.pending = false;
    request();
  });
}

/** Asks the worker for the frame of the wanted scene and view (a newer request supersedes it). */
function request() {
  const v = app.view;
  const view = {
    accuracy: v.accuracy, from: v.from, to: v.to, points: CURVE_POINTS, mapMax: v.mapMax, mapN: MAP_N,
    tidal: app.tidalIn,
    overlays: [...v.overlays],
  };
  if (window.rimeTest.fail.length) view.fail = [...window.rimeTest.fail];
  // Test hook: hold the worker this long before it computes (a stand-in for a slow level).
  if (window.rimeTest.delayMs > 0) view.testDelayMs = window.rimeTest.delayMs;
  // Main-thread calls across the wasm boundary made for this request (edits since the last one).
  const calls = app.calls;
  app.calls = 0;
  app.computer.request(app.wantScene, view, { view: { ...v }, t0: performance.now(), calls });
}

/** The frame's parts as typed-array views into its two flat arrays. */
function decode(msg, req) {
  const j = JSON.parse(msg.json);
  const F = (r) => msg.numbers.subarray(r.at, r.at + r.len);
  const U = (r) => msg.codes.subarray(r.at, r.at + r.len);
  const m = j.map;
  return {
    accuracy: req.view.accuracy,
    values: j.values,
    g: F(j.g),
    eps: j.curve ? F(j.curve.eps) : null,
    status: j.curve ? U(j.curve.status) : null,
    gaps: j.curve ? j.curve.failed : 0,
    clean: j.clean ? F(j.clean.eps) : null,
    family: j.family && {
      ...j.family, curves: j.family.curves.map((c) => (c ? F(c.eps) : null)),
    },
    crit: j.critical,
    warnings: j.warnings,
    friction: j.friction,
    map: m && !m.error ? { n: m.n, max: m.max, note: m.note, codes: U(m.class), epsT: F(m.epsT), epsN: F(m.epsN), g: F(m.g) } : null,
    mapFailed: m && m.error ? m : null,
    mapNote: m ? m.note : null,
    tidal: j.tidal.error ? null : j.tidal,
    overlays: (j.overlays || []).map((o) => ({ ...o, g: F(o.g), eps: F(o.eps) })),
    errors: j.errors,
  };
}

/** The worker's answer to the newest request: draw what succeeded, report what failed. */
function onFrame(msg, req) {
  const t1 = performance.now();
  if (msg.error || !req) {
    // The request itself was refused (it never is for a scene the page accepted): keep the drawn
    // frame and put the controls back to it.
    showBanner([{ part: 'request', message: msg.error }]);
    if (app.drawn) {
      app.ex.setJson(app.drawn.scene);
      app.wantScene = app.drawn.scene;
      app.view = { ...app.drawn.view };
      syncControls();
    }
    return;
  }
  const res = decode(msg, req.page);
  app.res = res;
  app.drawn = { scene: req.scene, view: req.page.view };
  draw();
  replayCollision();
  showWarnings(res);
  showTidal(res);
  showBanner(res.errors);
  syncControls();
  writeHash();
  const t2 = performance.now();
  app.callsPerUpdate.push(req.page.calls + msg.calls);
  app.timings.push(msg.ms);
  app.totals.push(t2 - req.page.t0);
  if (app.timings.length > 200) { app.timings.shift(); app.totals.shift(); app.callsPerUpdate.shift(); }
  $('timing').textContent = `frame ${msg.ms.toFixed(1)} ms in the worker (median ${median(app.timings).toFixed(1)} ms) · shown after ${(t2 - req.page.t0).toFixed(1)} ms · ${res.accuracy}`;
  $('timing').classList.remove('busy');
  const s = window.rimeState;
  Object.assign(s, {
    ready: true,
    sceneJson: req.scene,
    view: { ...req.page.view },
    g: Array.from(res.g),
    eps: res.eps ? Array.from(res.eps) : [],
    status: res.status ? Array.from(res.status, (c) => app.statusNames[c] ?? 'failed') : [],
    family: res.family && { path: res.family.path, values: res.family.values, curves: res.family.curves.map((c) => c && Array.from(c)) },
    critical: res.crit,
    warnings: res.warnings,
    mapClasses: res.map ? Array.from(res.map.codes) : null,
    mapNote: res.mapNote,
    overlay: experimentOverlay(),
    overlays: (res.overlays || []).map((o) => ({ key: o.key, label: o.label, band: o.band, score: o.score, g: Array.from(o.g), eps: Array.from(o.eps), speeds: o.speeds })),
    tidal: res.tidal,
    frameErrors: res.errors,
    computeMs: [...app.timings],
    totalMs: [...app.totals],
    callsPerUpdate: [...app.callsPerUpdate],
    workerRestarts: app.computer.restarts,
    updates: (s.updates || 0) + 1,
  });
  document.body.dataset.updates = String(s.updates);
  void t1;
}

let busyTimer = null;
function onBusy(busy) {
  clearTimeout(busyTimer);
  if (!busy) { $('timing').classList.remove('busy'); return; }
  // Say so only when it takes long enough to notice.
  busyTimer = setTimeout(() => {
    if (!app.computer.busy) return;
    $('timing').classList.add('busy');
    $('timing').textContent = `computing (${app.view.accuracy})… the controls stay live; a newer edit replaces this one`;
  }, 120);
}

/** The banner naming every part that failed (role=alert), each error also to the console. */
function showBanner(errors) {
  const key = JSON.stringify(errors);
  if (key !== app.bannerKey) {
    for (const e of errors) console.error(`rime: ${e.part}: ${e.message}`);
    app.bannerKey = key;
  }
  const b = $('banner');
  if (!errors.length || app.bannerDismissed === key) { b.hidden = true; return; }
  $('banner-list').replaceChildren(...errors.map((e) => el('li', {}, el('strong', {}, e.part), `: ${e.message}`)));
  b.hidden = false;
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
  if (!app.drawn || !app.drawn.view.experiments || !app.experiments) return null;
  const { from, to } = app.drawn.view;
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
    res.family.values.forEach((v, k) => res.family.curves[k] && series.push({
      x: res.g, y: res.family.curves[k], color: SERIES_COLORS[k % SERIES_COLORS.length], width: 1.3,
      label: `${res.family.sym} = ${fmtNum(v, 3)} ${res.family.unit}`,
    }));
  }
  // Overlays beneath the scene's own curves: measured ranges as boxes, laws over their measured
  // speeds only, other models dotted over the whole view.
  const overlayBands = [];
  const overlayMarkers = [];
  (res.overlays || []).forEach((o, k) => {
    const color = OVERLAY_COLORS[k % OVERLAY_COLORS.length];
    if (o.band) {
      overlayBands.push({ x: [o.g[0], o.g[1]], y: [o.eps[0], o.eps[1]], fill: `${color}22`, stroke: color, label: o.label, short: o.key.split(':')[1] });
    } else {
      series.push({ x: o.g, y: o.eps, color, width: 1.6, dash: o.key.startsWith('model:') ? [2, 3] : undefined, label: o.key.startsWith('model:') ? o.key.slice(6) : o.label });
    }
    for (const s of o.speeds) overlayMarkers.push({ x: s.value, label: `${o.key.slice(6)} ${s.name}: ${fmtSpeed(s.value)}`, short: `${s.name} ${fmtSpeed(s.value)}` });
  });
  if (res.clean) series.push({ x: res.g, y: res.clean, color: '#555', width: 1.4, dash: [6, 4], label: 'clean surface' });
  if (res.eps) series.push({ x: res.g, y: res.eps, color: '#111', width: 2.4, label: res.gaps ? 'this scene (gaps: failed)' : 'this scene' });
  let minPos = 1;
  for (const arr of [res.eps, res.clean]) if (arr) for (const v of arr) if (v > 0 && v < minPos) minPos = v;
  const yMin = Math.max(1e-12, 10 ** Math.floor(Math.log10(minPos) - 1e-9));
  const yMin2 = Math.min(yMin, 1e-2);
  let maxY = 1;
  if (res.eps) for (const v of res.eps) if (v > maxY) maxY = v;
  // Critical velocities; the bisected stick threshold only where it differs from Eq. (10)/(15).
  const markers = [];
  for (const c of res.crit) {
    if (markers.some((m) => Math.abs(m.x / c.value - 1) < 0.01)) continue;
    markers.push({ x: c.value, label: `${c.label}: ${fmtSpeed(c.value)}`, short: `${c.key === 'stick' ? 'stick' : 'g_s'} ${fmtSpeed(c.value)}` });
  }
  for (const m of overlayMarkers) if (m.x > app.drawn.view.from && m.x < app.drawn.view.to) markers.push(m);
  return {
    xMin: app.drawn.view.from, xMax: app.drawn.view.to, yMin: yMin2, yMax: 10 ** Math.ceil(Math.log10(maxY) - 1e-12) || 1,
    xLabel: 'impact speed g_N [m/s]', yLabel: 'ε_N', series, markers, hover, bands: [...(overlay ? overlay.bands : []), ...overlayBands],
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
  showPartNotes(app.res);
}

/** A visible note in place of each part of the chart that failed (the banner has the details). */
function showPartNotes(res) {
  const chartNotes = [];
  for (const e of res.errors) {
    if (e.part === 'stick map' || e.part === 'tidal') continue;
    const what = e.part === 'curve' ? `this scene: ${res.gaps} of ${res.g.length} speeds failed, drawn as gaps`
      : e.part === 'clean' ? 'clean surface: gaps where ε_N failed'
        : e.part.startsWith('family') ? `${e.part.replace('family ', 'family curve ')} not drawn`
          : e.part.startsWith('marker') ? `${e.part} not drawn`
            : `${e.part}: not drawn`;
    chartNotes.push(what);
  }
  const cn = $('chart-note');
  cn.textContent = chartNotes.length ? `⚠ ${chartNotes.join(' · ')} (see the message above)` : '';
  cn.hidden = !chartNotes.length;
  const rn = $('map-range-note');
  rn.textContent = res.mapNote ? `Note: ${res.mapNote}.` : '';
  rn.hidden = !res.mapNote;
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
    mapCanvas.setAttribute('aria-label', `stick map, 0 to ${fmtSpeed(res.map.max)}`);
  } else {
    const failed = res.mapFailed;
    const p = new CanvasPainter(mapCanvas, mw, failed ? 160 : 120);
    p.rect(0, 0, mw, p.height, { fill: failed ? '#fdf3f2' : '#fafafa', stroke: failed ? '#e2a49f' : undefined });
    if (failed) {
      p.text(mw / 2, 50, '⚠ stick map not computed', { size: 14, align: 'center', color: '#b3261e' });
      wrapText(failed.error, Math.max(20, Math.floor((mw - 24) / 6.6))).slice(0, 4)
        .forEach((line, k) => p.text(mw / 2, 76 + k * 17, line, { size: 12, align: 'center', color: '#444' }));
      mapCanvas.setAttribute('aria-label', `stick map not computed: ${failed.error}`);
    } else {
      p.text(mw / 2, 60, res.friction ? 'no stick map for this scene' : 'friction is off: no tangential restitution, no stick map', { size: 13, align: 'center', color: '#666' });
      mapCanvas.setAttribute('aria-label', 'stick map (friction is off)');
    }
    app.mapGeom = null;
  }
}

/** Splits `text` into lines of at most `width` characters at spaces. */
function wrapText(text, width) {
  const lines = [];
  let line = '';
  for (const w of String(text).split(/\s+/)) {
    if (line && line.length + 1 + w.length > width) { lines.push(line); line = w; } else line = line ? `${line} ${w}` : w;
  }
  if (line) lines.push(line);
  return lines;
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

/** One checkbox per measured law, measured range and other model (the core's list). */
function buildOverlayChoices() {
  const kinds = { law: 'measured law', range: 'measured range', model: 'model' };
  $('overlay-list').replaceChildren(...app.overlayChoices.map((c) => {
    const box = el('input', { type: 'checkbox', value: c.key });
    box.addEventListener('change', () => {
      const chosen = [...document.querySelectorAll('#overlay-list input')].filter((b) => b.checked).map((b) => b.value);
      app.view.overlays = chosen;
      schedule();
    });
    const where = c.valid ? ` · ${fmtSpeed(c.valid[0])}–${fmtSpeed(c.valid[1])}, ${c.temperature[0] === c.temperature[1] ? c.temperature[0] : `${c.temperature[0]}–${c.temperature[1]}`} K, ${c.geometry}` : '';
    return el('label', { class: 'overlay-choice', title: c.label }, box, ` ${c.key.split(':')[1]} (${kinds[c.kind] || c.kind}${where})`);
  }));
}

/** "Fit this scene to that entry": A fitted to the first checked measured law, applied. */
function fitToEntry() {
  const law = app.view.overlays.find((k) => {
    const c = app.overlayChoices.find((x) => x.key === k);
    return c && c.kind === 'law';
  });
  if (!law) { $('overlay-fit-result').textContent = 'check a measured law first'; return; }
  const id = law.slice('atlas:'.length);
  try {
    const r = JSON.parse(app.ex.fitToEntry(id, 'fast'));
    app.wantScene = app.ex.toJson();
    $('overlay-fit-result').textContent = `A = ${fmtNum(r.value, 4)} s` +
      (r.standard_error === null ? '' : ` ± ${fmtNum(r.standard_error, 2)} s`) +
      ` fitted to ${id} (rms ${fmtNum(r.rms_error, 2)} over its measured speeds)` +
      (r.warnings.length ? ` — ${r.warnings.join('; ')}` : '');
    schedule();
  } catch (e) {
    const msg = errText(e);
    console.error(`rime: ${msg}`);
    $('overlay-fit-result').textContent = `${msg} (scene unchanged)`;
  }
}

/** The score of the scene against each measured overlay, and what failed among them. */
function showOverlayScores(res) {
  const items = (res.overlays || []).filter((o) => o.score !== null && o.score !== undefined)
    .map((o) => el('li', {}, `rms ε_N difference against ${o.label}: ${fmtNum(o.score, 3)}`));
  for (const e of res.errors) if (/^(atlas|model):/.test(e.part)) items.push(el('li', { class: 'err' }, `${e.part}: ${e.message}`));
  $('overlay-scores').replaceChildren(...items);
}

function showWarnings(res) {
  showOverlayScores(res);
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
      if (text === '') return;
      try {
        const base = app.res && app.res.tidal ? app.res.tidal.input : (app.tidalIn || PAPER_TIDAL_INPUT);
        const cand = { ...base, [f.key]: parseQuantity(f, text) };
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

function showTidal(res) {
  const t = res.tidal;
  const note = $('tidal-note');
  const failed = res.errors.find((e) => e.part === 'tidal');
  note.hidden = !failed;
  note.textContent = failed ? `⚠ not computed: ${failed.message}` : '';
  $('tidal').hidden = !t;
  if (!t) return;
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
    const n = probe(g, 'fast');
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

/** One collision of the drawn scene at `app.collisionG` (main thread: one live integration). */
function replayCollision() {
  if (!app.drawn || !app.collisionView) return;
  probe(app.collisionG, 'fast'); // points hoverEx at the drawn scene
  try {
    const d = JSON.parse(app.hoverEx.collision(app.collisionG, 300, app.drawn.view.accuracy));
    app.collisionView.show(d);
    window.rimeState.collision = {
      g: d.g, eps_n: d.eps_n, t_c: d.t_c, status: d.status, closure: d.ledger.closure,
      n: d.t.length, dynamic: d.dynamic !== null, animating: app.collisionView.animating,
      reduced: app.collisionView.reduced,
    };
  } catch (e) {
    console.error(`rime: collision: ${errText(e)}`);
    app.collisionView.fail(errText(e));
  }
}

/** The normal result at `g` for the drawn scene (main thread; hover readouts and tests). */
function probe(g, accuracy) {
  if (!app.drawn) throw new Error('nothing drawn yet');
  if (app.hoverScene !== app.drawn.scene) {
    app.hoverEx.setJson(app.drawn.scene);
    app.hoverScene = app.drawn.scene;
  }
  return JSON.parse(app.hoverEx.normal(g, accuracy));
}

// ---------- URL state ----------

let hashTimer = null;
function writeHash() {
  // Coalesced: browsers throttle history.replaceState when it is called at slider rates.
  if (hashTimer !== null) return;
  hashTimer = setTimeout(() => { hashTimer = null; writeHashNow(); }, 150);
}

/** The link of the drawn scene and view. */
function writeHashNow() {
  if (!app.drawn) return;
  const v = { ...app.drawn.view };
  const hash = `#s=${encodeURIComponent(app.drawn.scene)}&v=${encodeURIComponent(JSON.stringify(v))}`;
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
  if (obj.overlays !== undefined) {
    const known = new Set((app.overlayChoices || []).map((c) => c.key));
    if (!Array.isArray(obj.overlays) || obj.overlays.some((o) => !known.has(o))) {
      throw new Error('view.overlays: a list of atlas:ID or model:NAME among the offered ones');
    }
    v.overlays = [...obj.overlays];
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
    app.ex.setJson(s);
    app.view = view;
    app.wantScene = app.ex.toJson();
    return null;
  } catch (e) {
    // Fall back to the defaults (also when a pasted link is broken after start).
    app.ex.loadPreset('ice');
    app.view = { ...DEFAULT_VIEW };
    app.wantScene = app.ex.toJson();
    console.error(`rime: link: ${errText(e)}`);
    return errText(e);
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
    // Failed speeds (gaps) and parts not computed are empty cells.
    const at = (arr) => (arr && Number.isFinite(arr[i]) ? arr[i] : '');
    const row = [res.g[i], at(res.eps), res.status ? app.statusNames[res.status[i]] ?? 'failed' : '', at(res.clean)];
    if (res.family) res.family.curves.forEach((c) => row.push(at(c)));
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

// Exposed for the end-to-end test: the SVG and CSV texts the buttons download.
window.rimeExports = {
  chartSvg: () => { const p = new SvgPainter(720, 460); drawChart(p, chartSpec(app.res, null)); return p.svg(); },
  mapSvg: () => app.res.map && mapSvg(app.res.map),
  curvesCsv: () => curvesCsv(app.res),
  mapCsv: () => app.res.map && mapCsv(app.res.map),
  bridgesAt: (g) => bridgesAt(g),
  probe: (g) => probe(g, app.drawn.view.accuracy),
};

// ---------- start ----------

function wireView() {
  $('accuracy').addEventListener('change', () => { app.view.accuracy = $('accuracy').value; schedule(); });
  for (const id of ['view-from', 'view-to', 'view-mapmax']) $(id).addEventListener('input', () => { $(id).dataset.dirty = '1'; });
  const refuse = (errId, msg) => {
    $(errId).textContent = msg;
    console.error(`rime: refused: ${msg}`);
    if (app.drawn) {
      app.view = { ...app.drawn.view };
      for (const id of ['view-from', 'view-to', 'view-mapmax']) $(id).dataset.dirty = '';
      syncControls();
    }
  };
  const range = () => {
    let from, to;
    try { from = parseSpeed($('view-from').value); } catch (e) { return refuse('view-err', `g from: ${e.message}`); }
    try { to = parseSpeed($('view-to').value); } catch (e) { return refuse('view-err', `g to: ${e.message}`); }
    if (!(from < to)) return refuse('view-err', 'g from: must be below "to"');
    app.view.from = from; app.view.to = to;
    $('view-from').dataset.dirty = ''; $('view-to').dataset.dirty = '';
    $('view-err').textContent = '';
    schedule();
  };
  $('view-experiments').addEventListener('change', () => { app.view.experiments = $('view-experiments').checked; schedule(); });
  $('view-from').addEventListener('change', range);
  $('view-to').addEventListener('change', range);
  $('view-mapmax').addEventListener('change', () => {
    const t = $('view-mapmax').value.trim();
    try {
      app.view.mapMax = t === '' || t === 'auto' ? null : parseSpeed(t);
    } catch (e) { return refuse('mapmax-err', `map max speed: ${e.message}`); }
    $('view-mapmax').dataset.dirty = '';
    $('mapmax-err').textContent = '';
    schedule();
  });
  $('preset').addEventListener('change', () => {
    const name = $('preset').value;
    if (!name) return;
    try {
      app.ex.loadPreset(name);
      app.wantScene = app.ex.toJson();
      for (const path of app.rows.keys()) setErr(path, '');
      schedule();
    } catch (e) { showNotice(e.message); }
  });
  $('banner-close').addEventListener('click', () => { app.bannerDismissed = app.bannerKey; $('banner').hidden = true; });
  const chart = $('chart');
  chart.addEventListener('pointermove', chartHover);
  chart.addEventListener('click', (ev) => {
    if (!app.chartGeom) return;
    const x = ev.clientX - chart.getBoundingClientRect().left;
    const { box, inv } = app.chartGeom;
    if (x < box.l || x > box.r) return;
    app.collisionG = inv(x);
    replayCollision();
  });
  chart.addEventListener('pointerdown', chartHover);
  chart.addEventListener('pointerleave', () => { app.hover.chart = null; if (app.res) drawChartCanvas(); });
  const map = $('map');
  map.addEventListener('pointermove', mapHover);
  map.addEventListener('click', () => {
    const m = app.res && app.res.map;
    if (!m || !app.hover.map || m.g[app.hover.map.i] <= 0) return;
    app.collisionG = m.g[app.hover.map.i];
    replayCollision();
  });
  map.addEventListener('pointerdown', mapHover);
  map.addEventListener('pointerleave', () => { app.hover.map = null; if (app.res) drawMapCanvas(); });
  let resizeQueued = false;
  window.addEventListener('resize', () => {
    if (resizeQueued) return;
    resizeQueued = true;
    requestAnimationFrame(() => { resizeQueued = false; draw(); });
  });
  window.addEventListener('hashchange', () => {
    // Our own replaceState does not fire this; a pasted or edited link does.
    showNotice(loadHash());
    schedule();
  });
}

async function main() {
  // One compiled module for the page (validation, readouts) and the worker (frames).
  const bytes = await (await fetch(new URL('./pkg/rime_wasm_bg.wasm', import.meta.url))).arrayBuffer();
  const module = await WebAssembly.compile(bytes);
  await init({ module_or_path: module });
  app.ex = counted(new Explorer());
  app.hoverEx = new Explorer();
  app.collisionG = 0.01;
  app.collisionView = new CollisionView();
  app.params = JSON.parse(Explorer.parameters());
  app.classes = JSON.parse(Explorer.classes());
  app.statusNames = JSON.parse(Explorer.statusNames());
  $('version').textContent = Explorer.version();
  const presets = JSON.parse(Explorer.presets());
  $('preset').replaceChildren(el('option', { value: '' }, '— choose —'),
    ...presets.map((p) => el('option', { value: p.name, title: p.description }, p.name)));
  app.experiments = JSON.parse(Explorer.experiments());
  app.overlayChoices = JSON.parse(Explorer.overlays());
  buildOverlayChoices();
  $('overlay-fit').addEventListener('click', fitToEntry);
  buildControls();
  buildTidal();
  wireView();
  wireDownloads();
  app.computer = new Computer(module, onFrame, onBusy);
  app.wantScene = app.ex.toJson();
  showNotice(loadHash());
  app.calls = 0;
  request();
}

main().catch((e) => {
  console.error(`rime: failed to start: ${errText(e)}`);
  window.rimeState.errors.push(String(e && e.message ? e.message : e));
  $('timing').textContent = `failed to start: ${e && e.message ? e.message : e}`;
});
