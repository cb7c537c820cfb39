// The stick map (as Fig. 4 of the paper: g_T across, g_N up) in the core's palette, its legend
// with every class explained and the artifact marked as such, the note on Eq. (23)'s radicand
// beside it, ε_T(g_T) along one g_N row beside it, hover/keyboard readouts from the frame's own
// values and a text alternative.
import { HELP, PALETTE, sig, speed } from './core.js';
import { $, attr, debounced, DESCRIBE_AFTER_MS, el, followLater, linked, put, setText, viewportHeight, wrapText } from './dom.js';
import { CanvasPainter, drawLines, drawMap, drawNote, mapGeometry, sizeElement } from './plot.js';
import { app } from './state.js';

let geom = null;
let legendCounts = null; // the legend's share elements, one per class
let hooks = { replay: () => {} };

/** The classes' colours in code order (the core's palette). */
export const classColors = () => app.classes.map((c) => PALETTE.classes[c.name]);
const isArtifact = (name) => HELP.classes.some((c) => c.name === name && c.artifact);

function side(canvas, width) {
  const w = Math.max(200, Math.floor((width ?? canvas.parentElement.clientWidth) - 2));
  // A square that leaves room to scroll on a phone.
  return Math.min(w, 560, Math.max(260, Math.round(viewportHeight() * 0.6)));
}

/** The g_N row whose ε_T is plotted: the chosen one, else the middle of the map. */
export function mapRow(m) {
  const r = app.mapRow;
  return r !== null && r < m.n ? r : Math.floor(m.n / 2);
}

export function mapSpec(m, hover) {
  return { n: m.n, codes: m.codes, max: m.max, colors: classColors(), hover, row: mapRow(m) };
}

export function epsTSpec(m, hoverJ = null) {
  const i = mapRow(m);
  const y = Array.from({ length: m.n }, (_, j) => m.epsT[i * m.n + j]);
  return {
    x: m.g, y, xMax: m.max, yMin: -1, yMax: 1, color: PALETTE.scene, hover: hoverJ,
    title: `ε_T along g_N = ${speed(m.g[i])}`, xLabel: 'tangential speed g_T', yLabel: 'ε_T',
  };
}

export function drawMapCanvas(widths = {}) {
  const res = app.res;
  if (!res) return;
  const canvas = $('map');
  const s = side(canvas, widths.map);
  const et = $('eps-t');
  let map = null; // what to draw: {w, h, spec, lines: {w, h, spec}} or {w, h, note}
  if (res.map) {
    const m = res.map;
    const h = app.hover.map;
    const lw = Math.max(200, Math.floor((widths.epsT ?? et.parentElement.clientWidth) - 2));
    map = { w: s, h: s - 28, spec: mapSpec(m, h), lines: { w: lw, h: 220, spec: epsTSpec(m, h && h.i === mapRow(m) ? h.j : null) } };
    geom = mapGeometry(map.w, map.h);
    put(et, 'hidden', false);
    attr(canvas, 'aria-label', `stick map over g_T (across) and g_N (up), 0 to ${speed(m.max)}; summary below`);
  } else {
    geom = null;
    et.hidden = true;
    const failed = res.mapFailed;
    const lines = [];
    if (failed) {
      lines.push({ y: 50, text: '⚠ stick map not computed', size: 14, color: '#b3261e' });
      wrapText(failed.error, Math.max(20, Math.floor((s - 24) / 6.6))).slice(0, 4)
        .forEach((line, k) => lines.push({ y: 76 + k * 17, text: line, size: 12, color: '#444' }));
      attr(canvas, 'aria-label', `stick map not computed: ${failed.error}`);
    } else {
      lines.push({ y: 55, text: res.friction ? 'no stick map for this scene' : 'friction is off: no ε_T, no stick map', size: 13, color: '#555' });
      attr(canvas, 'aria-label', 'stick map (friction is off)');
    }
    map = { w: s, h: failed ? 160 : 100, note: { fill: failed ? '#fdf3f2' : '#fafafa', stroke: failed ? '#e2a49f' : undefined, lines } };
  }
  if (app.painter) {
    // Drawn in the painter worker (issue 26).
    sizeElement(canvas, map.w, map.h);
    if (map.lines) sizeElement(et, map.lines.w, map.lines.h);
    app.painter.map(map);
  } else {
    const p = new CanvasPainter(canvas, map.w, map.h);
    if (map.note) drawNote(p, map.note);
    else {
      drawMap(p, map.spec);
      drawLines(new CanvasPainter(et, map.lines.w, map.lines.h), map.lines.spec);
    }
  }
  readout();
}

function readout() {
  const m = app.res && app.res.map;
  const h = app.hover.map;
  const out = $('map-readout');
  if (!m || !h) { setText(out, m ? 'hover, tap or use the arrow keys on the map for values; click or Enter picks the ε_T row' : ''); return; }
  const k = h.i * m.n + h.j;
  const c = app.classes[m.codes[k]];
  setText(out, `g_N = ${speed(m.g[h.i], 4)} · g_T = ${speed(m.g[h.j], 4)} · ε_N = ${sig(m.epsN[h.i], 5)} · ε_T = ${sig(m.epsT[k], 5)} · ${c ? c.label : '?'}${c && isArtifact(c.name) ? ' (artifact)' : ''} · at ${app.res.accuracy}`);
}

/** The legend (every class explained, artifacts marked), the artifact note and the text alternative. */
export function drawLegend(res) {
  const counts = new Array(app.classes.length).fill(0);
  if (res.map) { const codes = res.map.codes; for (let k = 0; k < codes.length; k++) counts[codes[k]]++; }
  const total = res.map ? res.map.codes.length : 0;
  const colors = classColors();
  // The entries are built once; a frame writes only the shares that changed (issue 26: rebuilding
  // the list was a third of a redraw's time on the page's thread).
  if (!legendCounts) {
    legendCounts = app.classes.map(() => el('span', { class: 'count' }, ''));
    $('legend').replaceChildren(...app.classes.map((c, k) => el('li', { class: isArtifact(c.name) ? 'artifact' : null },
      el('span', { class: 'sw', style: `background:${colors[k]}`, 'aria-hidden': 'true' }),
      el('span', {}, ...linked(c.meaning), ' ', legendCounts[k]))));
  }
  // The shares follow once the frames pause, as the text alternatives do: while a slider is dragged
  // they would be unreadable, and writing them was the only change a frame made to the document,
  // which cost it a rendering update of the page's thread (the chart and map are drawn in the
  // painter worker; issue 26). Meanwhile they are marked as the previous frame's (greyed after
  // 0.2 s, as the ring and collision cards are).
  const texts = counts.map((n) => (total ? `(${sig((100 * n) / total, 3)} %)` : ''));
  followLater($('legend'), texts.join('|'), () => legendCounts.forEach((span, k) => setText(span, texts[k])));
  res.classCounts = counts;
  const gap = app.classes.findIndex((c) => isArtifact(c.name));
  const note = $('artifact-note');
  const shown = res.map && gap >= 0 && counts[gap] > 0;
  if (note.hidden !== !shown) {
    note.hidden = !shown;
    note.replaceChildren(...(shown ? linked(HELP.artifact_note) : []));
  }
  let desc = '';
  if (res.map) {
    const parts = app.classes.map((c, k) => [c, counts[k]]).filter(([, n]) => n > 0)
      .map(([c, n]) => `${c.label} ${sig((100 * n) / total, 3)} %`);
    desc = `Stick map, g_T across and g_N up from 0 to ${speed(res.map.max)}: ${parts.join(', ')}.`;
  }
  // The text alternative follows once the frames pause, as the chart's (an absolutely positioned
  // box is never laid out alone: writing it laid out the page on every frame).
  describeLater(() => setText($('map-desc'), desc));
}
const describeLater = debounced(DESCRIBE_AFTER_MS, 'timer:describe');


function cellAt(ev) {
  const m = app.res && app.res.map;
  if (!m || !geom) return null;
  const rect = $('map').getBoundingClientRect();
  const fx = (ev.clientX - rect.left - geom.box.l) / geom.size;
  const fy = (geom.box.b - (ev.clientY - rect.top)) / geom.size;
  if (fx < 0 || fx >= 1 || fy < 0 || fy >= 1) return null;
  return { i: Math.min(m.n - 1, Math.floor(fy * m.n)), j: Math.min(m.n - 1, Math.floor(fx * m.n)) };
}

export function wireMap(h) {
  hooks = h;
  const map = $('map');
  map.addEventListener('pointermove', (ev) => {
    const c = cellAt(ev);
    if (!c) return;
    app.hover.map = c;
    drawMapCanvas();
  });
  map.addEventListener('pointerleave', () => { app.hover.map = null; drawMapCanvas(); });
  map.addEventListener('click', (ev) => {
    const c = cellAt(ev);
    if (!c) return;
    app.mapRow = c.i;
    app.hover.map = c;
    drawMapCanvas();
    const g = app.res.map.g[c.i];
    if (g > 0) hooks.replay(g);
  });
  map.addEventListener('keydown', (ev) => {
    const m = app.res && app.res.map;
    if (!m) return;
    const c = app.hover.map || { i: mapRow(m), j: Math.floor(m.n / 2) };
    const step = ev.shiftKey ? 10 : 1;
    const clamp = (v) => Math.max(0, Math.min(m.n - 1, v));
    if (ev.key === 'ArrowUp') c.i = clamp(c.i + step);
    else if (ev.key === 'ArrowDown') c.i = clamp(c.i - step);
    else if (ev.key === 'ArrowRight') c.j = clamp(c.j + step);
    else if (ev.key === 'ArrowLeft') c.j = clamp(c.j - step);
    else if (ev.key === 'Enter' || ev.key === ' ') { app.mapRow = c.i; if (m.g[c.i] > 0) hooks.replay(m.g[c.i]); } else return;
    ev.preventDefault();
    app.hover.map = { ...c };
    drawMapCanvas();
  });
  map.addEventListener('blur', () => { app.hover.map = null; drawMapCanvas(); });
}
