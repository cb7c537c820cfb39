// "Compare": measured ice laws and other models over the ε_N chart (the core's list and scores),
// and "fit A to the first checked measured law" (the core's fit).
import { qty, sig, speed } from './core.js';
import { $, el, setText } from './dom.js';
import { app } from './state.js';

let hooks = { schedule: () => {}, edit: () => false };

/** One checkbox per measured law, measured range and other model (the core's list). */
export function buildCompare(h) {
  hooks = h;
  const kinds = { law: 'measured law', range: 'measured range', model: 'model' };
  $('overlay-list').replaceChildren(...app.overlayChoices.map((c) => {
    const box = el('input', { type: 'checkbox', value: c.key });
    box.addEventListener('change', () => {
      app.view.overlays = [...document.querySelectorAll('#overlay-list input')].filter((b) => b.checked).map((b) => b.value);
      hooks.schedule();
    });
    const t = c.temperature;
    // An ansatz with no experiment (borderies1984) has no temperature (∞, null in JSON): "any
    // temperature", as the core's label says (issue 37: it read "0–—").
    const temp = !t ? '' : !Number.isFinite(t[1]) ? 'any temperature' : t[0] === t[1] ? qty(t[0], 'K', 3) : `${sig(t[0], 3)}–${qty(t[1], 'K', 3)}`;
    const where = c.valid ? ` · ${speed(c.valid[0])}–${speed(c.valid[1])}, ${temp}, ${c.geometry}` : '';
    const needs = c.needs ? el('span', { class: 'hint needs', 'data-needs': c.needs }, '') : '';
    return el('label', { class: 'overlay-choice', title: c.label }, box, ` ${c.key.split(':')[1]} (${kinds[c.kind] || c.kind}${where})`, needs);
  }));
  $('overlay-fit').addEventListener('click', fitToEntry);
}

/** A model that needs a scene section the scene lacks (thornton1997: plasticity) is not offered: its
 *  box is disabled and says what it needs, instead of failing with a red banner once checked.
 *  Called with every scene the editor holds (controls.js `reflectScene`). */
export function syncCompare(has) {
  for (const hint of document.querySelectorAll('#overlay-list .needs')) {
    const box = hint.parentElement.querySelector('input');
    const lacking = !has(hint.dataset.needs);
    // Written only when it changes (issue 26: this runs on every slider step).
    const off = lacking && !box.checked;
    if (box.disabled !== off) box.disabled = off;
    setText(hint, lacking ? ` — needs a ${hint.dataset.needs} section (a yield pressure): not in this scene` : '');
  }
}

/** "Fit this scene to that entry": A fitted to the first checked measured law, applied (undoable). */
function fitToEntry() {
  const law = app.view.overlays.find((k) => {
    const c = app.overlayChoices.find((x) => x.key === k);
    return c && c.kind === 'law';
  });
  if (!law) { $('overlay-fit-result').textContent = 'check a measured law first'; return; }
  const id = law.slice('atlas:'.length);
  let r = null;
  const ok = hooks.edit('fit', () => { r = JSON.parse(app.ex.fitToEntry(id, 'fast')); });
  if (ok && r) {
    $('overlay-fit-result').textContent = `A = ${qty(r.value, 's', 4)}` +
      (r.standard_error === null ? '' : ` ± ${qty(r.standard_error, 's', 2)}`) +
      ` fitted to ${id} (rms ${sig(r.rms_error, 2)} over its measured speeds; undo with Ctrl+Z)` +
      (r.warnings.length ? ` — ${r.warnings.join('; ')}` : '');
  } else {
    $('overlay-fit-result').textContent = `fit A to ${id} failed (scene unchanged); see the console`;
  }
}

/** The score of the scene against each measured overlay, and what failed among them. */
let scoresKey = null;
export function showOverlayScores(res) {
  const lines = (res.overlays || []).filter((o) => o.score !== null && o.score !== undefined)
    // A measured box scores the distance outside it: 0 means the curve passes through the box
    // (issue 37: a bare "rms 0" read as a perfect fit).
    .map((o) => ['', `rms ε_N difference against ${o.label}: ${sig(o.score, 3)}${o.band && o.score === 0 ? ' (the curve lies inside the box at every measured speed)' : ''}`]);
  for (const e of res.errors) if (/^(atlas|model):/.test(e.part)) lines.push(['err', `${e.part}: ${e.message}`]);
  // Rebuilt only when it changes (issue 26).
  const key = JSON.stringify(lines);
  if (key === scoresKey) return;
  scoresKey = key;
  $('overlay-scores').replaceChildren(...lines.map(([cls, text]) => el('li', { class: cls || null }, text)));
}

