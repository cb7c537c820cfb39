// The page's state: the scene being edited (validated by the core), the view, what is drawn, and
// the undo history of scene edits. Every module reads and writes this one object; nothing else
// keeps state of its own.

/** The preset the page opens on (adhesion): a visible threshold g_s on the chart and a sticking
 *  corner ("aggregation") in the stick map. */
export const START_PRESET = 'ice-sticky';
export const DEFAULT_VIEW = {
  accuracy: 'precise', from: 1e-7, to: 10, mapMax: null, experiments: true, overlays: [], yScale: 'lin',
};

export const app = {
  ex: null, // the scene being edited (main thread: validation only; always valid)
  wantScene: null, // its JSON, the newest scene asked of the worker
  drawn: null, // {scene, view} of the frame on screen
  res: null, // the decoded frame on screen
  preview: false, // whether it is the fast preview of the newest request (never downloaded)
  edited: '', // the parameter whose edit asks for the next frame ('' for any other change)
  computer: null,
  painter: null, // the chart's painter worker (painter.js); null: the chart is drawn on this thread
  probeEx: null, // the drawn scene, for probes and collisions
  probeScene: null,
  pinRequest: null, // {scene, accuracy, from, to}: a pinned curve of the link, computed before the first frame
  view: { ...DEFAULT_VIEW },
  tidalIn: null, // null: the paper's example with the scene's grains; else the typed TidalInput
  pinned: null, // {g, eps, values, label}: a curve kept to compare with later edits
  params: [],
  classes: [],
  statusNames: [],
  experiments: null,
  overlayChoices: [],
  hover: { chart: null, map: null }, // chart: index into g; map: {i (g_T), j (g_N)}
  mapRow: null, // the g_N row whose ε_T(g_T) is plotted (index), null: automatic
  timings: [],
  totals: [],
  callsPerUpdate: [],
  formatCallsPerUpdate: [],
};

// ---------- undo history of scene edits ----------

const history = { past: [], future: [], lastKey: null, lastAt: 0 };
const COALESCE_MS = 800;
const listeners = [];

/** Called with nothing whenever the history changes (buttons enable/disable). */
export function onHistory(fn) { listeners.push(fn); }
const changed = () => listeners.forEach((fn) => fn());

/**
 * Records that the scene is about to change from `before` (JSON) by an edit of `key` (a parameter
 * path, "preset", "fit", "link"). Edits of one key in quick succession (a slider drag) are one step.
 */
export function remember(before, key) {
  const now = performance.now();
  if (before === null) return;
  if (key === history.lastKey && key !== 'preset' && now - history.lastAt < COALESCE_MS && history.past.length) {
    history.lastAt = now;
    history.future = [];
    changed();
    return;
  }
  if (history.past[history.past.length - 1] !== before) history.past.push(before);
  if (history.past.length > 200) history.past.shift();
  history.future = [];
  history.lastKey = key;
  history.lastAt = now;
  changed();
}

/** The scene to go back to (JSON) given the current one, or null. */
export function undo(current) {
  if (!history.past.length) return null;
  const prev = history.past.pop();
  history.future.push(current);
  history.lastKey = null;
  changed();
  return prev;
}

/** The scene to go forward to (JSON) given the current one, or null. */
export function redo(current) {
  if (!history.future.length) return null;
  const next = history.future.pop();
  history.past.push(current);
  history.lastKey = null;
  changed();
  return next;
}

export const canUndo = () => history.past.length > 0;
export const canRedo = () => history.future.length > 0;
export const historySize = () => ({ past: history.past.length, future: history.future.length });
