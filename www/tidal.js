// The tidal calculator (appendix, Eq. (A.1)–(A.7)): typed inputs parsed by the core's unit parser,
// the core's tidal card (rows beside the paper's printed numbers, compared by the core's one rule,
// and the verdict) laid out. The typed inputs live in the state and so in the link.
import { editable, parseQuantity, printedDigits, qty, sig } from './core.js';
import { $, el, errText, linkify } from './dom.js';
import { app } from './state.js';

/** The calculator's fields and their SI units. */
export const TIDAL_FIELDS = [
  { key: 'planet_mass', label: 'planet mass M', unit: 'kg' },
  { key: 'distance', label: 'distance d', unit: 'm' },
  { key: 'radius', label: 'grain radius r', unit: 'm' },
  { key: 'density', label: 'density ρ', unit: 'kg/m³' },
  { key: 'surface_energy', label: 'surface energy γ', unit: 'J/m²' },
];

const rows = new Map();
let hooks = { schedule: () => {}, validate: () => {} };

// Planet mass and distance read best in plain SI with an exponent (5.688e26 kg, 1.336e8 m).
const shown = (f, v) => (f.key === 'planet_mass' || f.key === 'distance' ? sig(v, 12) : editable(v, f.unit));

export function buildTidal(h) {
  hooks = h;
  const box = $('tidal-inputs');
  for (const f of TIDAL_FIELDS) {
    const id = `t-${f.key}`;
    const typed = el('input', { type: 'text', id, inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off', 'data-field': f.key, 'aria-describedby': `${id}-err` });
    const err = el('span', { class: 'err', id: `${id}-err`, role: 'status' });
    const root = el('div', { class: 'tparam', 'data-field': f.key },
      el('label', { for: id }, f.label),
      el('span', { class: 'typed' }, typed, el('span', { class: 'unit' }, f.unit)),
      err);
    const commit = () => {
      const text = typed.value.trim();
      if (text === '') return;
      try {
        const base = app.res && app.res.tidal ? app.res.tidal.input : app.tidalIn;
        const cand = { ...base, [f.key]: parseQuantity(`tidal.${f.key}`, text, f.unit) };
        hooks.validate(cand); // the core's check; throws naming the field
        app.tidalIn = cand;
        err.textContent = '';
        root.classList.remove('invalid');
        typed.removeAttribute('aria-invalid');
        hooks.schedule();
      } catch (e) {
        let msg = errText(e);
        if (!msg.includes(f.key)) msg = `tidal.${f.key}: ${msg}`;
        // As in the scene's fields: the typed text stays, and the value drawn is shown beside it.
        const drawn = app.res && app.res.tidal ? app.res.tidal.input[f.key] : undefined;
        err.textContent = Number.isFinite(drawn) ? `${msg} — the card shows ${qty(drawn, f.unit, 6)}` : msg;
        root.classList.add('invalid');
        typed.setAttribute('aria-invalid', 'true');
      }
    };
    typed.addEventListener('change', commit);
    typed.addEventListener('keydown', (e) => { if (e.key === 'Enter') commit(); });
    box.append(root);
    rows.set(f.key, { f, root, typed, err });
  }
  $('tidal-reset').addEventListener('click', () => {
    app.tidalIn = null;
    for (const row of rows.values()) { row.err.textContent = ''; row.root.classList.remove('invalid'); row.typed.removeAttribute('aria-invalid'); }
    hooks.schedule();
  });
}

let shownKey = null;
export function showTidal(res) {
  const t = res.tidal;
  const note = $('tidal-note');
  const failed = res.errors.find((e) => e.part === 'tidal');
  // Rebuilt only when it changes (issue 26: most edits leave the appendix as it is).
  const key = JSON.stringify([t, failed, app.tidalIn]);
  if (key === shownKey) return;
  shownKey = key;
  note.hidden = !failed;
  note.textContent = failed ? `⚠ not computed: ${failed.message}` : '';
  $('tidal').hidden = !t;
  if (!t) return;
  const inp = t.input;
  for (const row of rows.values()) {
    if (document.activeElement !== row.typed && !row.root.classList.contains('invalid')) row.typed.value = shown(row.f, inp[row.f.key]);
  }
  $('tidal-source').textContent = app.tidalIn ? '(typed values, kept in the link)' : '(following the scene)';
  // The core's card: its rows, each compared by the core's one rule where the inputs are the
  // paper's example, its notes and its one verdict (the terminal and `rime tidal` say the same).
  const line = (r) => {
    const c = r.comparison;
    const text = t.paper_inputs || r.note_always ? r.note : '';
    const tr = el('tr', {},
      el('td', {}, r.equation ? `${r.label} (${r.equation})` : r.label),
      el('td', { class: 'num' }, Number.isFinite(r.computed) ? `${sig(r.computed, 4)} ${r.unit}` : '—'),
      el('td', { class: `num ${c ? (c.agrees ? 'ok' : 'bad') : ''}` },
        r.printed === null ? '—' : `${sig(r.printed, printedDigits(r.printed))} ${r.unit}${c ? ` ${c.mark}` : ''}`),
      el('td', { class: 'note' }, text));
    return text ? [tr, el('tr', { class: 'note-row' }, el('td', { colspan: 3 }, text))] : [tr];
  };
  $('tidal').replaceChildren(
    el('tr', {}, el('th', { scope: 'col' }, 'quantity'), el('th', { scope: 'col' }, 'computed'), el('th', { scope: 'col' }, 'paper'), el('th', { class: 'note', scope: 'col' }, 'note')),
    ...t.rows.flatMap(line),
    el('tr', { class: t.holds ? 'ok' : 'bad' }, el('td', { colspan: 4 }, t.verdict)));
  linkify($('tidal'));
}
