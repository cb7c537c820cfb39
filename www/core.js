// The page's window onto rime-core (compiled to wasm): the one palette, the one set of number
// formatters and unit parsers, the words (citation, glossary, help). Nothing here is defined in
// JavaScript: every colour, every formatted number and every parsed value comes from the core, so
// the page cannot drift from the terminal and the exports. Formatted strings are memoised (a
// redraw formats the same tick labels again), so that a redraw costs no calls across the boundary.
import init, * as wasm from './pkg/rime_wasm.js';

/** Calls across the wasm boundary on the main thread: `compute` (scene edits, probes),
 *  `format` (formatters and parsers, after the memo). */
export const calls = { compute: 0, format: 0 };

/** The core's palette: {scene, critical, clean, experiment, family[], series[], overlays[], pinned, classes{}}. */
export let PALETTE = null;
/** The core's words: {paper, glossary[], parameters{path: {help, options}}, classes[], artifact_note}. */
export let HELP = null;
export let Explorer = null;

/** Loads the wasm module (compiled once, shared with the worker) and reads palette and words. */
export async function start(module) {
  await init({ module_or_path: module });
  Explorer = wasm.Explorer;
  PALETTE = JSON.parse(wasm.palette());
  HELP = JSON.parse(wasm.help());
  calls.format += 2;
}

const memo = new Map();
function cached(key, fn) {
  let v = memo.get(key);
  if (v === undefined) {
    calls.format++;
    v = fn();
    if (memo.size > 20000) memo.clear();
    memo.set(key, v);
  }
  return v;
}

const num = (v) => (v === null || v === undefined ? NaN : Number(v));

/** `v` with `digits` significant digits; `—` when not a finite number. */
export const sig = (v, digits = 4) => cached(`s${digits}|${num(v)}`, () => wasm.fmtSig(num(v), digits));
/** A quantity with its unit and an SI prefix ("6.6 µm/s"). */
export const qty = (v, unit, digits = 4) => cached(`q${digits}|${unit}|${num(v)}`, () => wasm.fmtQty(num(v), unit, digits));
/** A speed with an SI prefix. */
/** The stick map's records (`rime map --format csv`) from the frame's arrays, by the core. */
export const mapRecords = (g, epsT, codes) => { calls.compute++; return wasm.mapRecords(g, epsT, codes); };
export const speed = (v, digits = 3) => qty(v, 'm/s', digits);
/** The shortest text that reads back as exactly `v` (files). */
export const shortest = (v) => cached(`r|${num(v)}`, () => wasm.fmtShortest(num(v)));
/** The value a user edits (no float noise, SI prefix where the unit takes one). */
export const editable = (v, unit) => cached(`e|${unit}|${num(v)}`, () => wasm.fmtEditable(num(v), unit));
/** The core's ticks of an axis (`Axis::ticks`, as the terminal and the exported figures draw them):
 *  {values, labels} with `null` for a minor tick. */
export const axisTicks = (min, max, log, maxLabels) => cached(`t|${min}|${max}|${log}|${maxLabels}`, () => {
  const [values, labels] = JSON.parse(wasm.axisTicks(min, max, log, maxLabels));
  return { values, labels };
});
/** The label of the decade 10^k on a log axis. */
export const decade = (k) => cached(`d|${k}`, () => wasm.fmtDecade(k));
/** The significant digits a printed number has. */
export const printedDigits = (v) => cached(`p|${v}`, () => wasm.printedDigits(v));
/** Whether a computed value reproduces a printed one to its printed digits. */
export const agrees = (computed, printed) => cached(`a|${computed}|${printed}`, () => wasm.agreesToPrinted(computed, printed));

/** A typed speed ("1 um/s", "0.02") for the field `field`; throws naming the field. */
export function parseSpeed(field, text) {
  calls.format++;
  return wasm.parseSpeed(field, String(text));
}

/** A typed end of the chart's speed range, within the core's chart limits; throws naming the field. */
export function parseChartSpeed(field, text) {
  calls.format++;
  return wasm.parseChartSpeed(field, String(text));
}

/** A typed quantity with units compatible with `unit`; throws naming the field. */
export function parseQuantity(field, text, unit) {
  calls.format++;
  return wasm.parseQuantity(field, String(text), unit);
}

/** Counts the calls made across the wasm boundary through `obj` (an Explorer). */
export function counted(obj) {
  return new Proxy(obj, {
    get(t, k) {
      const v = t[k];
      if (typeof v !== 'function') return v;
      return (...args) => { calls.compute++; return v.apply(t, args); };
    },
  });
}

/** The physics notes served beside the page (docs/physics.md rendered by `make www`), at `anchor`. */
export function physicsUrl(anchor = '') {
  return `physics.html${anchor ? `#${anchor}` : ''}`;
}

/** The anchor of the physics notes for an equation ("4", "23", "A.5"): its row of the table
 *  "Equations used" (docs/physics.md: the formula, the code, and a link to its decision; issue 37:
 *  the links landed on the decision, which may not write the equation). An equation without a row
 *  of its own goes to the row of its range (Eq. (14) → Eq. (13)–(16)), else to its decision. */
const EQUATION_ROWS = [1, 2, 4, 5, 8, 9, 10, 11, 12, 15, 17, 22, 23, 25, 26, 27];
export function equationAnchor(eq) {
  if (/^A\./.test(eq)) return 'eq-a1';
  const n = Number(eq);
  if (EQUATION_ROWS.includes(n)) return `eq-${n}`;
  if (n >= 13 && n <= 16) return 'eq-13';
  if (n >= 18 && n <= 21) return 'eq-18';
  if (n >= 18 && n <= 26) return 'decision-6';
  return 'equations-used';
}

/** The paper's citation as one line. */
export function citation() {
  const p = HELP.paper;
  return `${p.authors} (${p.year}), ${p.title}. ${p.journal} ${p.volume}, ${p.pages}.`;
}
