// The ring card (issue 24): what the scene's law does to a ring at optical depth τ and orbital
// frequency Ω (or the tidal card's planet and distance). Everything is the core's ring card
// (rime_core::explorer::ring, through the flat binding ringCard): the verdict, the sentence, the
// printed rows (the numbers `rime ring` prints) and, when asked, the ε_cr line, the point where the
// scene's ε_N curve meets it and the ring's mean impact speed, added to the ε_N chart's figure as
// the core's series and marker (so the chart, its downloads and the terminal draw them alike).
import * as wasm from './pkg/rime_wasm.js';
import { calls, parseQuantity } from './core.js';
import { $, el, errText, put } from './dom.js';
import { app } from './state.js';

/** The card's inputs as the page starts (a link carries only inputs that differ). */
export const RING_DEFAULTS = Object.freeze({ tau: 0.5, omega: 1.3143527e-4, planet: false, onChart: false, sizes: 'one' });

/** The width of the ring's ε_cr line on the chart (px; comparisons 1.5, this scene 2.6 solid). */
const RING_LINE_WIDTH = 2.6;

/** The card's inputs (in the link, `&r=`) and its last result. */
export const ring = { ...RING_DEFAULTS, card: null, error: null };

let hooks = { schedule: () => {} };

/** The request for the core's card with the inputs `r` over the chart's speed range. */
function request(r, chart) {
  const input = { tau: r.tau, chart, sizes: r.sizes };
  const t = app.res && app.res.tidal ? app.res.tidal.input : null;
  if (r.planet && t) {
    input.planet_mass = t.planet_mass;
    input.distance = t.distance;
  } else {
    input.omega = r.omega;
  }
  return JSON.stringify(input);
}

/** The core's card, or the core's message naming the field. */
function card(scene, text) {
  try {
    calls.compute++;
    return { card: JSON.parse(wasm.ringCard(scene, text)), error: null };
  } catch (e) {
    return { card: null, error: errText(e) };
  }
}

/** Why the core refuses `value` for the card's input `key` (`tau`, `omega`) on `scene` (JSON) over
 *  the speeds `range`, or null: a link's value gets the card's own range check (issue 37: a link
 *  carried τ = 1e308 past it). */
export function ringInputProblem(key, value, scene, range) {
  const trial = card(scene, request({ ...ring, planet: false, [key]: value }, range));
  return trial.error && trial.error.startsWith(`ring.${key}`) ? trial.error : null;
}

/** The ring card's inputs for a frame request (the worker computes the card with the frame). */
export function ringInputs() {
  return { tau: ring.tau, omega: ring.omega, planet: ring.planet, onChart: ring.onChart, sizes: ring.sizes };
}

/** Takes the card the worker computed after the frame (`out`: {json} or {error}). */
export function takeRing(out) {
  if (out.error) Object.assign(ring, { card: null, error: out.error });
  else Object.assign(ring, { card: JSON.parse(out.json), error: null });
}

/** Before the chart is drawn: takes the card the worker computed with the frame (`out`: {json} or
 *  {error}; null: a preview without it, the card on screen stays) and, when asked, adds it to the
 *  ε_N figure. */
export function ringOverlay(res, out) {
  if (out) takeRing(out);
  const fig = res.figures[0];
  const c = ring.card;
  if (!c || !ring.onChart) return;
  const line = c.eps_cr_line;
  const series = (name, short, points, stroke) => ({
    name, short, color: line.color, stroke, dashed: stroke !== 'solid' && stroke !== 'points',
    x: Float64Array.from(points, (p) => p[0]), y: Float64Array.from(points, (p) => p[1]),
  });
  // Drawn thicker than every comparison (issue 37: its blue dashes looked like borderies1984's
  // cyan ones): the one wide dashed line of the chart.
  fig.series.push({ ...series(line.name, line.short, line.points, line.stroke), width: RING_LINE_WIDTH });
  if (c.meeting) fig.series.push(series('ε_N meets the ring\'s ε_cr', 'meets ε_cr', [c.meeting], 'points'));
  fig.markers.push(c.impact_marker);
}

export function buildRing(h) {
  hooks = h;
  const box = $('ring-inputs');
  const field = (key, label, unit, parse) => {
    const id = `r-${key}`;
    const input = el('input', { type: 'text', id, inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off', value: String(ring[key]), 'aria-describedby': `${id}-err` });
    const err = el('span', { class: 'err', id: `${id}-err`, role: 'status' });
    const commit = () => {
      try {
        const value = parse(input.value.trim());
        // The core checks the value (naming the field); a refused value leaves the card as drawn.
        if (app.drawn && app.res) {
          const fig = app.res.figures[0];
          const trial = card(app.drawn.scene, request({ ...ring, [key]: value }, [fig.x.min, fig.x.max]));
          if (trial.error && trial.error.startsWith(`ring.${key}`)) throw new Error(trial.error);
        }
        ring[key] = value;
        err.textContent = '';
        input.removeAttribute('aria-invalid');
        hooks.schedule();
      } catch (e) {
        err.textContent = errText(e);
        input.setAttribute('aria-invalid', 'true');
      }
    };
    input.addEventListener('change', commit);
    input.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
    box.append(el('div', { class: 'tparam' }, el('label', { for: id }, label), el('span', { class: 'typed' }, input, el('span', { class: 'unit' }, unit)), err));
  };
  field('tau', 'optical depth τ', '', (t) => parseQuantity('ring.tau', t, '1'));
  field('omega', 'orbital frequency Ω', '1/s', (t) => parseQuantity('ring.omega', t, '1/s'));
  const check = (key, label) => {
    const input = el('input', { type: 'checkbox', id: `r-${key}` });
    input.checked = ring[key];
    input.addEventListener('change', () => { ring[key] = input.checked; hooks.schedule(); });
    box.append(el('label', { class: 'check', for: `r-${key}` }, input, ` ${label}`));
  };
  check('planet', 'Ω from the tidal card\'s planet and distance');
  check('onChart', 'draw ε_cr and the impact speed on the ε_N chart');
  // The grain sizes (issue 38): the core's choices, named and labelled by the core.
  const sizes = el('select', { id: 'r-sizes' });
  for (const { name, label } of JSON.parse(wasm.ringSizes())) sizes.append(el('option', { value: name }, label));
  sizes.value = ring.sizes;
  sizes.addEventListener('change', () => { ring.sizes = sizes.value; hooks.schedule(); });
  box.append(el('div', { class: 'tparam' }, el('label', { for: 'r-sizes' }, 'grain sizes'), sizes));
}


/** Shows the card's inputs as they are in `ring` (after a link set them). */
export function reflectRing() {
  for (const key of ['tau', 'omega']) {
    const input = $(`r-${key}`);
    if (input) {
      input.value = String(ring[key]);
      input.removeAttribute('aria-invalid');
      $(`r-${key}-err`).textContent = '';
    }
  }
  for (const key of ['planet', 'onChart']) {
    const input = $(`r-${key}`);
    if (input) input.checked = ring[key];
  }
  const sizes = $('r-sizes');
  if (sizes) sizes.value = ring.sizes;
}

let shownKey = null;
/** After a frame: the card's verdict, sentence and rows (or why it could not be computed). */
export function showRing() {
  const c = ring.card;
  const note = $('ring-note');
  // Each written only when it changes (issue 26: a write invalidates the page's style).
  put(note, 'hidden', !ring.error);
  const noteText = ring.error ? `⚠ not computed: ${ring.error}` : '';
  if (note.textContent !== noteText) note.textContent = noteText;
  put($('ring'), 'hidden', !c);
  window.rimeState.ring = c ? { verdict: c.verdict, equilibrium: c.equilibrium, rows: c.rows, meeting: c.meeting, record: c.record, sizes: c.sizes, viscosity: c.viscosity } : null;
  if (!c) return;
  // Rebuilt only when what it prints changes (issue 26: rebuilding the table every frame was the
  // largest part of the page's layout per frame, and most edits leave the card as it is).
  const key = JSON.stringify([c.equilibrium, c.verdict, c.sentence, c.rows]);
  if (key === shownKey) return;
  shownKey = key;
  $('ring').replaceChildren(
    el('tr', { class: c.equilibrium ? 'ok' : 'bad' }, el('th', { scope: 'row' }, 'verdict'), el('td', {}, c.verdict)),
    el('tr', {}, el('td', { colspan: 2 }, c.sentence)),
    ...c.rows.map((r) => el('tr', {}, el('th', { scope: 'row' }, r.label), el('td', { class: 'num' }, r.text))));
}
