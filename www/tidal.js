// The tidal calculator (appendix, Eq. (A.1)–(A.7)): typed inputs parsed by the core's unit parser,
// the core's numbers beside the paper's printed ones, compared by the core's one rule
// (agreesToPrinted). The typed inputs live in the state and so in the link.
import { HELP, agrees, editable, parseQuantity, printedDigits, qty, sig } from './core.js';
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
  const r = t.result, q = t.paper, inp = t.input;
  for (const row of rows.values()) {
    if (document.activeElement !== row.typed && !row.root.classList.contains('invalid')) row.typed.value = shown(row.f, inp[row.f.key]);
  }
  $('tidal-source').textContent = app.tidalIn ? '(typed values, kept in the link)' : '(following the scene)';
  // The paper's printed numbers are for its example only: compare only there.
  const example = Object.keys(HELP.tidalPaper).every((k) => inp[k] === HELP.tidalPaper[k]);
  const row = (name, v, unit, paper, noteText, always = false) => {
    let mark = '', cls = '';
    if (paper !== undefined && example) {
      const ok = agrees(v, paper);
      mark = ok ? ' ✓' : ' ⚠';
      cls = ok ? 'ok' : 'bad';
    }
    const text = example || always ? (noteText || '') : '';
    const tr = el('tr', {},
      el('td', {}, name),
      el('td', { class: 'num' }, Number.isFinite(v) ? `${sig(v, 4)} ${unit}` : '—'),
      el('td', { class: `num ${cls}` }, paper === undefined ? '—' : `${sig(paper, printedDigits(paper))} ${unit}${mark}`),
      el('td', { class: 'note' }, text));
    return text ? [tr, el('tr', { class: 'note-row' }, el('td', { colspan: 3 }, text))] : [tr];
  };
  const rMax = r.r_max ?? NaN;
  $('tidal').replaceChildren(
    el('tr', {}, el('th', { scope: 'col' }, 'quantity'), el('th', { scope: 'col' }, 'computed'), el('th', { scope: 'col' }, 'paper'), el('th', { class: 'note', scope: 'col' }, 'note')),
    ...[row('ΔF tidal force difference (A.1)', r.delta_f, 'N', q.delta_f),
    row('F_s = πγR_eff, R_eff = r/2 (A.2)', r.surface_force, 'N', q.surface_force, 'the printed 6.28e-3 N is πγr, twice Eq. (A.2)'),
    row('πγr (what the paper prints as F_s)', r.surface_force_paper, 'N', q.surface_force),
    row('F_g mutual gravity (A.3)', r.gravity, 'N', undefined, 'not printed', true),
    row('d_Roche (A.7)', r.d_roche, 'm', q.d_roche),
    row('d_min (A.6)', r.d_min, 'm', q.d_min, 'printed 5.43e4 m is not reproduced: A.6 (both printed forms) gives 3.08e5 m, also inside the planet'),
    r.r_max === null
      ? row('r_max (A.5)', rMax, 'm', q.r_max, 'none: at or outside d_Roche self-gravity holds grains of any size', true)
      : row('r_max (A.5)', rMax, 'm', q.r_max, 'A.5 gives 37.72 m vs printed 37.6 m (0.3 %); r_max moves −27× any relative change of 4M/d³'),
    ].flat(),
    // The core's one verdict (the terminal and `rime tidal` say the same).
    ...(t.verdict ? [el('tr', { class: t.verdict.holds ? 'ok' : 'bad' }, el('td', { colspan: 4 }, t.verdict.text))] : []));
  linkify($('tidal'));
}
