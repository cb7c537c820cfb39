// The controls: the parameter panel (help on every control, human option names, sliders that
// announce values, greyed and disabled when their effect is off), the toolbar (preset, accuracy,
// undo/redo) and the view fields (speed range with units, map range, experiments). Every edit goes
// through the core (app.ex); a value it rejects is refused at the control, naming the field.
import { HELP, editable, parseChartSpeed, parseSpeed, qty, sig } from './core.js';
import { $, attr, el, errText, linked, put, setText } from './dom.js';
import { syncCompare } from './compare.js';
import { app, canRedo, canUndo, onHistory, redo, remember, undo } from './state.js';

const SLIDER_STEPS = 1000;
const GROUPS = [
  ['grains', 'Grains'],
  ['bulk', 'Bulk material (Eq. (4))'],
  ['contact_end', 'Contact'],
  ['layer', 'Soft layer (Eq. (8)–(10))'],
  ['adhesion', 'Adhesion (Eq. (11)–(17))'],
  ['friction', 'Friction (Eq. (18)–(26))'],
];

const rows = new Map();
let hooks = { schedule: () => {}, notice: () => {} };

const helpOf = (path) => (HELP.parameters[path] || {}).help || '';
const optionName = (path, o) => ((HELP.parameters[path] || {}).options || {})[o] || o;
const sliderRange = (p) => (HELP.parameters[p.path] || {}).slider || [p.min, p.max];
/** Whether the page writes this parameter's values with their unit ("20 mm", "10 GPa"; not "900"
 *  for kg/m³). */
const carriesUnit = (p) => !!p.unit && /\d\s*[^\d\s.eE+-]/.test(editable(sliderRange(p)[0] || 1, p.unit));
const shown = (p, v) => (p.unit ? qty(v, p.unit, 4) : sig(v, 4));

function toSlider(p, v) {
  const [lo, hi] = sliderRange(p);
  let f = p.log ? (Math.log10(v) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo)) : (v - lo) / (hi - lo);
  if (!Number.isFinite(f)) f = 0;
  return Math.round(Math.min(1, Math.max(0, f)) * SLIDER_STEPS);
}

function fromSlider(p, pos) {
  const [lo, hi] = sliderRange(p);
  const f = pos / SLIDER_STEPS;
  const v = p.log ? 10 ** (Math.log10(lo) + f * (Math.log10(hi) - Math.log10(lo))) : lo + f * (hi - lo);
  return Number(sig(v, p.log ? 3 : 4));
}

function setErr(path, msg) {
  const row = rows.get(path);
  if (!row) return;
  // Written only when they change (issue 26: every slider step passes here).
  setText(row.err, msg || '');
  if (row.root.classList.contains('invalid') !== !!msg) row.root.classList.toggle('invalid', !!msg);
  if (!msg && row.typed && row.typed.dataset.refused) row.typed.dataset.refused = '';
  for (const input of [row.typed, row.sel, row.cb]) {
    if (!input) continue;
    attr(input, 'aria-invalid', msg ? 'true' : null);
  }
}

/** The scene as the editor holds it changed: ask for its frame. */
function changed() {
  app.wantScene = app.ex.toJson();
  reflectScene();
  hooks.schedule();
}

/** What follows the scene outside its own controls: the preset menu names it (a preset's name, or
 *  "edited" once it differs from all) and Compare offers only the models it can run. */
export function reflectScene() {
  // Asked of the scene in the core, not of its text read back (issue 36: every slider step passes here).
  syncCompare((section) => app.ex.get(section) === 'true');
  const first = $('preset').options[0];
  if (!first) return;
  const match = app.ex.preset();
  setText(first, match ? `${match} (this scene) — load a preset` : 'an edited scene — load a preset');
}

/** Applies one edit (`fn` on app.ex) of `key` through the core; records it for undo. A value the
 *  core rejects is refused at the control (message naming the field, also to the console) and the
 *  control goes back to the drawn scene. */
export function edit(key, fn) {
  const before = app.wantScene;
  try {
    fn();
    const after = app.ex.toJson();
    if (after !== before) remember(before, key);
    app.wantScene = after;
    app.edited = key;
    reflectScene();
    setErr(key, '');
    hooks.schedule();
    return true;
  } catch (e) {
    let msg = errText(e);
    if (rows.has(key) && !msg.includes(key)) msg = `${key}: ${msg}`;
    console.error(`rime: refused: ${msg}`);
    setErr(key, msg + keepRow(key));
    return false;
  }
}

/** After a refused value: a typed field keeps the user's text (marked invalid, so the typo can be
 *  fixed) and says what the chart shows; a slider, menu or checkbox goes back to the drawn value.
 *  Returns the words to append to the error ("" when there is no drawn value). */
function keepRow(path) {
  const row = rows.get(path);
  if (!row || !app.res) return '';
  const v = app.res.values[path];
  if (row.sel) row.sel.value = v ?? '';
  if (row.cb) row.cb.checked = v === true;
  if (!row.typed) return '';
  row.typed.dataset.refused = '1';
  if (v === null || v === undefined) return '';
  row.slider.value = toSlider(row.p, v);
  return ` — the chart shows ${editable(v, row.p.unit)}`;
}

function helpLine(path, id) {
  const text = helpOf(path);
  return text ? el('p', { class: 'help', id }, ...linked(text)) : null;
}

export function buildControls(h) {
  hooks = h;
  const box = $('controls');
  box.append(el('h2', { id: 'parameters-heading', tabindex: '-1' }, 'Parameters of this scene'));
  box.append(el('p', { class: 'hint' }, 'Type a value with units (e.g. "2 kPa s", "5 µm") and press Enter, or drag the slider. Undo with Ctrl+Z.'));
  for (const [prefix, title] of GROUPS) {
    const head = el('h3', {}, el('span', {}, ...linked(title)));
    box.append(head);
    if (prefix === 'bulk') {
      const sel = el('select', { id: 'damping-form', 'aria-describedby': 'h-damping-form' },
        el('option', { value: 'time' }, 'A given directly'),
        el('option', { value: 'viscosities' }, 'A from viscosities η₁, η₂'));
      sel.addEventListener('change', () => {
        if (sel.value === 'time') edit('bulk.damping.time', () => app.ex.set('bulk.damping.time', '1e-4'));
        else edit('bulk.damping.viscosities.formula', () => app.ex.set('bulk.damping.viscosities.formula', 'brilliantov'));
      });
      box.append(el('div', { class: 'param choice' }, el('label', { class: 'name', for: 'damping-form' }, 'damping A'), sel,
        el('p', { class: 'help', id: 'h-damping-form' }, 'give A itself, or derive it from the bulk viscosities (', ...linked('Eq. (4)'), ')')));
    }
    for (const p of app.params.filter((q) => q.path === prefix || q.path.startsWith(`${prefix}.`))) {
      const id = `p-${p.path}`;
      const hid = `h-${p.path}`;
      if (p.kind === 'toggle') {
        const cb = el('input', { type: 'checkbox', id, 'aria-describedby': hid });
        cb.addEventListener('change', () => edit(p.path, () => app.ex.set(p.path, cb.checked ? 'on' : 'off')));
        head.append(el('label', { class: 'toggle', for: id }, cb, ` ${p.label} on`));
        const err = el('span', { class: 'err', role: 'status' });
        const help = helpLine(p.path, hid);
        head.after(...[help, err].filter(Boolean));
        rows.set(p.path, { p, root: head, cb, err });
      } else if (p.kind === 'choice') {
        const sel = el('select', { id, 'aria-describedby': hid }, ...p.options.map((o) => el('option', { value: o }, optionName(p.path, o))));
        sel.addEventListener('change', () => edit(p.path, () => app.ex.set(p.path, sel.value)));
        const err = el('span', { class: 'err', role: 'status' });
        const root = el('div', { class: 'param choice', 'data-path': p.path },
          el('label', { class: 'name', for: id }, p.label), sel, helpLine(p.path, hid), err);
        box.append(root);
        rows.set(p.path, { p, root, sel, err });
      } else {
        const slider = el('input', { type: 'range', min: 0, max: SLIDER_STEPS, step: 1, 'aria-label': `${p.label} (slider)`, 'data-path': p.path, 'aria-describedby': hid });
        const typed = el('input', { type: 'text', id, inputmode: 'decimal', spellcheck: 'false', 'data-path': p.path, autocomplete: 'off', 'aria-describedby': `${hid} ${id}-err`, ...(carriesUnit(p) ? { title: `a value with its unit; a bare number is in ${p.unit}` } : {}) });
        const err = el('span', { class: 'err', id: `${id}-err`, role: 'status' });
        slider.addEventListener('input', () => {
          const v = fromSlider(p, Number(slider.value));
          slider.setAttribute('aria-valuetext', shown(p, v));
          if (edit(p.path, () => app.ex.setNumber(p.path, v))) typed.value = editable(v, p.unit);
        });
        typed.addEventListener('change', () => {
          const text = typed.value.trim();
          if (text === '') return;
          if (edit(p.path, () => app.ex.set(p.path, text))) typed.dataset.dirty = '';
        });
        typed.addEventListener('input', () => { typed.dataset.dirty = '1'; });
        const root = el('div', { class: 'param', 'data-path': p.path },
          el('label', { class: 'name', for: id }, p.label),
          el('span', { class: 'slider-box' }, slider),
          // A typed value that carries its unit ("20 mm") has no unit column after it (issue 37: it
          // read "20 mm m"; a bare number is taken in the SI unit, as its title says); one written
          // bare ("900" kg/m³) keeps it.
          el('span', { class: 'typed' }, el('span', { class: 'typed-box' }, typed), ...(carriesUnit(p) ? [] : [el('span', { class: 'unit' }, p.unit || '')])),
          helpLine(p.path, hid),
          err);
        box.append(root);
        rows.set(p.path, { p, root, slider, typed, err });
      }
    }
  }
}

/** Shows the drawn scene and view in every control (a field being typed in keeps its text). An
 *  inactive parameter (its effect off) is greyed and disabled, its slider at the start. */
export function syncControls() {
  const values = app.res.values;
  // A frame older than the newest edit (a slider still being dragged while the worker catches up)
  // leaves the control in the user's hand where the user put it: its thumb used to jump back.
  const stale = app.wantScene !== null && app.drawn !== null && app.drawn.scene !== app.wantScene;
  for (const [path, row] of rows) {
    const v = values[path];
    if (row.cb) {
      put(row.cb, 'checked', v === true);
    } else if (row.sel) {
      const off = v === null;
      row.root.classList.toggle('inactive', off);
      put(row.sel, 'disabled', off);
      if (!off) put(row.sel, 'value', v); else put(row.sel, 'selectedIndex', -1);
    } else {
      const off = v === null;
      row.root.classList.toggle('inactive', off);
      put(row.slider, 'disabled', off);
      put(row.typed, 'disabled', off);
      const typing = document.activeElement === row.typed && row.typed.dataset.dirty === '1';
      if (off) {
        put(row.typed, 'value', '');
        put(row.typed, 'placeholder', 'off');
        put(row.slider, 'value', '0');
        attr(row.slider, 'aria-valuetext', 'off');
      } else {
        put(row.typed, 'placeholder', '');
        if (!(stale && document.activeElement === row.slider)) {
          put(row.slider, 'value', String(toSlider(row.p, v)));
          attr(row.slider, 'aria-valuetext', shown(row.p, v));
        }
        // A refused text stays until it is fixed (or the slider moves): the user's typo is not lost.
        if (!typing && row.typed.dataset.refused !== '1') put(row.typed, 'value', editable(v, row.p.unit));
      }
    }
  }
  put($('damping-form'), 'value', values['bulk.damping.time'] === null ? 'viscosities' : 'time');
  const view = app.drawn.view;
  put($('accuracy'), 'value', view.accuracy);
  showTrade();
  const keep = (id) => document.activeElement === $(id) && $(id).dataset.dirty === '1';
  if (!keep('view-from')) put($('view-from'), 'value', editable(view.from, 'm/s'));
  if (!keep('view-to')) put($('view-to'), 'value', editable(view.to, 'm/s'));
  put($('view-experiments'), 'checked', view.experiments);
  // Live collections (kept by the browser; a query per frame cost about 0.2 ms of the page's thread).
  for (const r of document.getElementsByName('yscale')) put(r, 'checked', r.value === view.yScale);
  for (const box of $('overlay-list').getElementsByTagName('input')) put(box, 'checked', view.overlays.includes(box.value));
  put($('chart-sources'), 'hidden', !view.experiments);
  if (!keep('view-mapmax')) put($('view-mapmax'), 'value', view.mapMax === null ? '' : editable(view.mapMax, 'm/s'));
}

/** What the chosen level trades (how ε_N is obtained, its bound, its cost), beside the menu. */
function showTrade() {
  const l = HELP.levels.find((x) => x.name === $('accuracy').value);
  let text = l ? l.trade : '';
  // The literal layer reading has no table: `precise` integrates each contact at rtol 1e-13 for its
  // 1e-10 bound, `integrated` at 1e-9 for 1e-6, so here precise is the slower (issue 37; physics.md
  // "Accuracy").
  if (l && l.name === 'precise' && literalLayer()) text += ' — on this literal layer reading it integrates each contact at rtol 1e-13 for that bound: slower than integrated (rtol 1e-9, bound 1e-6)';
  setText($('accuracy-help'), text);
}

let literalKey = null;
let literalSeen = false;
/** Whether the scene being edited reads the soft layer literally (Eq. (8) as printed). */
function literalLayer() {
  const json = app.wantScene;
  if (json !== literalKey) {
    literalKey = json;
    try { const s = JSON.parse(json); literalSeen = !!(s && s.layer && s.layer.reading === 'literal'); } catch { literalSeen = false; }
  }
  return literalSeen;
}

/** Goes back (or forward) in the history of scene edits. */
export function step(back) {
  const target = back ? undo(app.wantScene) : redo(app.wantScene);
  if (target === null) return false;
  app.ex.setJson(target);
  for (const path of rows.keys()) setErr(path, '');
  changed();
  $('history-status').textContent = back ? 'undone' : 'redone';
  return true;
}

function historyButtons() {
  put($('undo'), 'disabled', !canUndo());
  put($('redo'), 'disabled', !canRedo());
}

export function wireToolbar(presets) {
  $('preset').replaceChildren(el('option', { value: '' }, '— load a preset —'),
    ...presets.map((p) => el('option', { value: p.name }, `${p.name}: ${p.description}`)));
  reflectScene();
  $('preset').addEventListener('change', () => {
    const name = $('preset').value;
    if (!name) return;
    // Loading a preset is an edit like any other (undoable); the menu goes back to its prompt, so
    // that choosing the same preset again reloads it.
    if (edit('preset', () => app.ex.loadPreset(name))) $('history-status').textContent = `loaded ${name}`;
    $('preset').value = '';
  });
  // The core's levels, each with its trade (how, bound, cost).
  $('accuracy').replaceChildren(...HELP.levels.map((l) => el('option', { value: l.name }, l.name)));
  $('accuracy').addEventListener('change', () => { app.view.accuracy = $('accuracy').value; showTrade(); hooks.schedule(); });
  showTrade();
  $('undo').addEventListener('click', () => step(true));
  $('redo').addEventListener('click', () => step(false));
  onHistory(historyButtons);
  historyButtons();
  document.addEventListener('keydown', (ev) => {
    if (!(ev.ctrlKey || ev.metaKey) || ev.altKey) return;
    const t = ev.target;
    // Text fields keep their own undo.
    if (t && (t.tagName === 'TEXTAREA' || (t.tagName === 'INPUT' && t.type === 'text'))) return;
    const k = ev.key.toLowerCase();
    if (k === 'z' || k === 'y') {
      if (step(k === 'z' && !ev.shiftKey)) ev.preventDefault();
    }
  });
}

export function wireView() {
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
    try { from = parseChartSpeed('g from', $('view-from').value); } catch (e) { return refuse('view-err', errText(e)); }
    try { to = parseChartSpeed('g to', $('view-to').value); } catch (e) { return refuse('view-err', errText(e)); }
    if (!(from < to)) return refuse('view-err', 'g from: must be below "to"');
    app.view.from = from; app.view.to = to;
    $('view-from').dataset.dirty = ''; $('view-to').dataset.dirty = '';
    $('view-err').textContent = '';
    hooks.schedule();
  };
  $('view-experiments').addEventListener('change', () => { app.view.experiments = $('view-experiments').checked; hooks.schedule(); });
  $('view-from').addEventListener('change', range);
  $('view-to').addEventListener('change', range);
  $('view-mapmax').addEventListener('change', () => {
    const t = $('view-mapmax').value.trim();
    try {
      app.view.mapMax = t === '' || t === 'auto' ? null : parseSpeed('map max speed', t);
    } catch (e) { return refuse('mapmax-err', errText(e)); }
    $('view-mapmax').dataset.dirty = '';
    $('mapmax-err').textContent = '';
    hooks.schedule();
  });
}

