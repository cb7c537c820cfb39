// The link: the drawn scene, view, typed tidal inputs, pinned curve and ring card's inputs in the
// URL hash, written shortly after the last change; read field by field, so that one bad field is
// named and the good ones are kept.
import { HELP, parseChartSpeed, parseQuantity, parseSpeed } from './core.js';
import { errText } from './dom.js';
import { later } from './test-hooks.js';
import { DEFAULT_VIEW, START_PRESET, app } from './state.js';
import { RING_DEFAULTS, ring, ringInputProblem, ringInputs } from './ring.js';
import { TIDAL_FIELDS } from './tidal.js';

let timer = null;

/** Writes the link of the drawn frame once the edits have stopped for a second, when the page is
 *  idle: browsers throttle replaceState at slider rates, and each write was followed by a layout
 *  of the page, 8–12 ms of the page's thread (issue 26: a long task on a phone while a slider was
 *  dragged). */
export function writeHash() {
  if (timer) timer.cancel();
  timer = later('timer:hash', () => {
    timer = null;
    if ('requestIdleCallback' in window) requestIdleCallback(() => writeHashNow(), { timeout: 1000 });
    else writeHashNow();
  }, 1000);
}

export function writeHashNow() {
  if (!app.drawn) return;
  let hash = `#s=${encodeURIComponent(app.drawn.scene)}&v=${encodeURIComponent(JSON.stringify(app.drawn.view))}`;
  if (app.drawn.tidal) hash += `&t=${encodeURIComponent(JSON.stringify(app.drawn.tidal))}`;
  // The pinned curve as what computes it again (its scene, level and speeds; issue 22: the page
  // said the link holds the whole state, and the pin was not in it).
  if (app.pinned) hash += `&p=${encodeURIComponent(JSON.stringify(app.pinned.source))}`;
  // The ring card's inputs, where they differ from the page's start.
  const r = ringInputs();
  const changed = Object.fromEntries(Object.entries(r).filter(([k, v]) => v !== RING_DEFAULTS[k]));
  if (Object.keys(changed).length) hash += `&r=${encodeURIComponent(JSON.stringify(changed))}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
}


/** A part of the link as a JSON object, or null with why named in `problems` (`name: not JSON`,
 *  `name: not an object`). */
function linkObject(text, name, problems) {
  let obj;
  try { obj = JSON.parse(text); } catch { problems.push(`${name}: not JSON`); return null; }
  if (obj === null || typeof obj !== 'object' || Array.isArray(obj)) { problems.push(`${name}: not an object`); return null; }
  return obj;
}

/** The view in the link, field by field; each bad field named in `problems` and left at its default. */
function readView(text, problems) {
  const v = { ...DEFAULT_VIEW, overlays: [] };
  if (text === null) return v;
  const obj = linkObject(text, 'view', problems);
  if (!obj) return v;
  const known = new Set(Object.keys(DEFAULT_VIEW));
  for (const k of Object.keys(obj)) if (!known.has(k)) problems.push(`view.${k}: unknown field`);
  const speedOf = (key, parse = parseSpeed) => {
    if (obj[key] === undefined || obj[key] === null) return;
    try { v[key] = parse(`view.${key}`, String(obj[key])); } catch (e) { problems.push(errText(e)); }
  };
  speedOf('from', parseChartSpeed);
  speedOf('to', parseChartSpeed);
  if (!(v.from < v.to)) {
    problems.push('view.to: must be above view.from');
    v.from = DEFAULT_VIEW.from;
    v.to = DEFAULT_VIEW.to;
  }
  speedOf('mapMax');
  if (obj.accuracy !== undefined) {
    const levels = HELP.levels.map((l) => l.name);
    // "balanced" is the former name of "integrated" (old links keep working).
    const a = obj.accuracy === 'balanced' ? 'integrated' : obj.accuracy;
    if (levels.includes(a)) v.accuracy = a;
    else problems.push(`view.accuracy: one of ${levels.join(', ')}`);
  }
  if (obj.experiments !== undefined) {
    if (typeof obj.experiments === 'boolean') v.experiments = obj.experiments;
    else problems.push('view.experiments: true or false');
  }
  if (obj.yScale !== undefined) {
    if (obj.yScale === 'log' || obj.yScale === 'lin') v.yScale = obj.yScale;
    else problems.push('view.yScale: log or lin');
  }
  if (obj.overlays !== undefined) {
    const offered = new Set(app.overlayChoices.map((c) => c.key));
    if (!Array.isArray(obj.overlays)) problems.push('view.overlays: a list of atlas:ID or model:NAME');
    else {
      // Each offered overlay once, so at most as many as are offered (issue 37: 20 000 copies of
      // one valid overlay took 22 s to the first frame); the repeats are dropped and said once.
      let repeats = 0;
      for (const o of obj.overlays) {
        if (!offered.has(o)) problems.push(`view.overlays: ${String(o).slice(0, 40)} is not offered`);
        else if (v.overlays.includes(o)) repeats++;
        else v.overlays.push(o);
      }
      if (repeats) problems.push(`view.overlays: ${repeats} repeated ${repeats === 1 ? 'entry' : 'entries'} dropped (each overlay is drawn once)`);
    }
  }
  return v;
}

/** Sets the scene of the link on the editor: whole if valid, else field by field from the opening
 *  preset, naming each field that could not be kept. */
function readScene(text, problems) {
  let whole = '';
  try { app.ex.setJson(text); return; } catch (e) { whole = errText(e); }
  const named = problems.length;
  app.ex.loadPreset(START_PRESET);
  const obj = linkObject(text, 'scene', problems);
  if (!obj) return;
  const base = JSON.parse(app.ex.toJson());
  for (const k of Object.keys(obj)) {
    if (!(k in base)) problems.push(`scene.${k}: unknown field`);
    else if (base[k] !== null && typeof base[k] === 'object' && obj[k] !== null && typeof obj[k] !== 'object') problems.push(`${k}: expected an object of its fields`);
  }
  const get = (path) => path.split('.').reduce((o, k) => (o !== null && typeof o === 'object' ? o[k] : undefined), obj);
  const set = (path, value) => {
    try { app.ex.set(path, value); } catch (e) {
      const msg = errText(e);
      problems.push(msg.includes(path) ? msg : `${path}: ${msg}`);
    }
  };
  const visc = get('bulk.damping.viscosities');
  if (visc && typeof visc === 'object') set('bulk.damping.viscosities.formula', String(visc.formula ?? 'brilliantov'));
  for (const p of app.params) {
    if (p.kind === 'toggle') {
      const v = obj[p.path];
      if (v === undefined) continue;
      if (v === null) set(p.path, 'off');
      else if (typeof v === 'object') set(p.path, 'on');
      continue;
    }
    const v = get(p.path);
    if (v === undefined || v === null) continue;
    if (typeof v === 'object') { problems.push(`${p.path}: expected a value`); continue; }
    set(p.path, String(v));
  }
  // The core refused the whole scene for a reason no field above names (an unknown nested field,
  // `{"grains":{"radius":…}}`, was dropped without a word): say what it said.
  if (problems.length === named && whole) problems.push(`scene: ${whole}`);
}

/** The typed tidal inputs of the link (null: follow the scene); bad fields named, kept at the
 *  paper's example. */
function readTidal(text, problems, validate) {
  if (text === null) return null;
  let obj;
  try { obj = JSON.parse(text); } catch { problems.push('tidal: not JSON'); return null; }
  if (obj === null || typeof obj !== 'object') { problems.push('tidal: not an object'); return null; }
  const out = { ...HELP.tidal_paper };
  for (const f of TIDAL_FIELDS) {
    if (obj[f.key] === undefined) continue;
    if (typeof obj[f.key] !== 'number' || !Number.isFinite(obj[f.key])) { problems.push(`tidal.${f.key}: not a finite number`); continue; }
    out[f.key] = obj[f.key];
  }
  try { validate(out); } catch (e) { problems.push(errText(e)); return null; }
  return out;
}

/** The pinned curve of the link ({scene, accuracy, from, to}), checked field by field; null when
 *  there is none or it cannot be read (named in `problems`). */
function readPinned(text, problems) {
  if (text === null) return null;
  const obj = linkObject(text, 'pinned', problems);
  if (!obj) return null;
  for (const k of Object.keys(obj)) if (!['scene', 'accuracy', 'from', 'to'].includes(k)) problems.push(`pinned.${k}: unknown field`);
  const out = {};
  try {
    // (A missing scene is named as such, not as the TypeError of reading it: issue 37.)
    if (obj.scene === undefined || obj.scene === null) { problems.push('pinned.scene: missing'); return null; }
    const scene = typeof obj.scene === 'string' ? obj.scene : JSON.stringify(obj.scene);
    app.probeEx.setJson(scene);
    app.probeScene = null; // the probe editor no longer holds the drawn scene
    out.scene = app.probeEx.toJson();
  } catch (e) { problems.push(`pinned.scene: ${errText(e)}`); return null; }
  const levels = HELP.levels.map((l) => l.name);
  if (!levels.includes(obj.accuracy)) { problems.push(`pinned.accuracy: one of ${levels.join(', ')}`); return null; }
  out.accuracy = obj.accuracy;
  try {
    out.from = parseChartSpeed('pinned.from', String(obj.from));
    out.to = parseChartSpeed('pinned.to', String(obj.to));
  } catch (e) { problems.push(errText(e)); return null; }
  if (!(out.from < out.to)) { problems.push('pinned.to: must be above pinned.from'); return null; }
  return out;
}

/**
 * Applies the state in the hash; returns the problems found (empty when all was read). Fields
 * that could not be read keep their defaults and are named.
 */
export function loadHash(validateTidal) {
  const h = location.hash.slice(1);
  if (!h) return [];
  const problems = [];
  const q = new URLSearchParams(h);
  const s = q.get('s');
  if (s === null) {
    problems.push('no scene (s=…) in the link');
    app.ex.loadPreset(START_PRESET);
  } else readScene(s, problems);
  app.view = readView(q.get('v'), problems);
  app.tidalIn = readTidal(q.get('t'), problems, validateTidal);
  app.pinRequest = readPinned(q.get('p'), problems);
  readRing(q.get('r'), problems);
  if (!app.pinRequest) app.pinned = null;
  app.wantScene = app.ex.toJson();
  const shown = capped(problems);
  for (const p of shown) console.error(`rime: link: ${p}`);
  return shown;
}

/** The ring card's inputs in the link (`&r=`), field by field: each bad field named in `problems`
 *  and left as it was; a field absent from the link takes the page's start value. */
function readRing(text, problems) {
  Object.assign(ring, RING_DEFAULTS);
  if (text === null) return;
  const obj = linkObject(text, 'ring', problems);
  if (!obj) return;
  for (const k of Object.keys(obj)) if (!(k in RING_DEFAULTS)) problems.push(`ring.${k}: unknown field`);
  const units = { tau: '1', omega: '1/s' };
  for (const key of ['tau', 'omega']) {
    if (obj[key] === undefined) continue;
    try {
      const v = parseQuantity(`ring.${key}`, String(obj[key]), units[key]);
      if (!(v > 0)) throw new Error(`ring.${key}: must be a positive number`);
      const why = ringInputProblem(key, v, app.ex.toJson(), [app.view.from, app.view.to]);
      if (why) throw new Error(why);
      ring[key] = v;
    } catch (e) { problems.push(errText(e)); }
  }
  for (const key of ['planet', 'onChart']) {
    if (obj[key] === undefined) continue;
    if (typeof obj[key] === 'boolean') ring[key] = obj[key];
    else problems.push(`ring.${key}: true or false`);
  }
  if (obj.sizes !== undefined) {
    const why = ringInputProblem('sizes', obj.sizes, app.ex.toJson(), [app.view.from, app.view.to]);
    if (why) problems.push(why);
    else ring.sizes = obj.sizes;
  }
}

/** At most MAX_PROBLEMS distinct problems, each at most MAX_PROBLEM_CHARS long, then how many more
 *  (a link with 20 000 bad overlays used to print 20 000 lines, one 100 000-character key whole). */
const MAX_PROBLEMS = 12;
const MAX_PROBLEM_CHARS = 160;
function capped(problems) {
  const short = problems.map((p) => (p.length > MAX_PROBLEM_CHARS ? `${p.slice(0, MAX_PROBLEM_CHARS - 1)}…` : p));
  const distinct = [...new Set(short)];
  if (distinct.length <= MAX_PROBLEMS) return distinct;
  const more = distinct.length - (MAX_PROBLEMS - 1);
  return [...distinct.slice(0, MAX_PROBLEMS - 1), `… and ${more} more problems in the link`];
}
