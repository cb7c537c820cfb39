// Small DOM helpers shared by the page's modules (no state, no physics).
import { equationAnchor, physicsUrl } from './core.js';
import { later } from './test-hooks.js';

export const $ = (id) => document.getElementById(id);

export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children) if (c !== null && c !== undefined) e.append(c);
  return e;
}

/** Sets an element's text only when it differs (a write invalidates the page's style and layout). */
export function setText(e, text) {
  if (e.textContent === text) return;
  // A lone text node's data is rewritten in place: replacing the node (textContent) costs a new
  // layout object and a wider relayout (issue 26: a frame's text writes are the page thread's cost).
  const t = e.firstChild;
  if (t && t === e.lastChild && t.nodeType === Node.TEXT_NODE && text !== '') t.data = text;
  else e.textContent = text;
}

/** How long after the newest frame a text alternative is written [ms]: a screen reader needs no
 *  description of every slider step and preview, and writing one cost each frame a layout of the
 *  page (issue 26). */
export const DESCRIBE_AFTER_MS = 100;

/** A function that runs the `fn` of its newest call `ms` after that call (earlier ones are
 *  dropped); its `cancel()` drops the one waiting. `name`: the timer's name for a check that holds
 *  it (www/test-hooks.js). */
export function debounced(ms, name) {
  let timer = null;
  const run = (fn) => {
    if (timer) timer.cancel();
    timer = later(name, () => { timer = null; fn(); }, ms);
  };
  run.cancel = () => { if (timer) timer.cancel(); timer = null; };
  return run;
}

/** A card or list being recomputed greys only once that has lasted this long [ms]: a flash at
 *  every slider step would be noise. */
const GREY_AFTER_MS = 200;
const greyTimers = new WeakMap();
/** Marks `e` as showing what was before the newest edit: `aria-busy` at once (assistive technology
 *  waits for it), and greyed by the style (`data-stale`) once that has lasted GREY_AFTER_MS. A CSS
 *  transition with that delay greyed it alike, but kept the page's thread restyling the element at
 *  every display frame while it waited (issue 26). Writes only what changes. */
export function markBusy(e, busy) {
  attr(e, 'aria-busy', busy ? 'true' : 'false');
  if (busy) {
    if (greyTimers.has(e) || e.hasAttribute('data-stale')) return;
    greyTimers.set(e, setTimeout(() => {
      greyTimers.delete(e);
      if (e.getAttribute('aria-busy') === 'true') e.setAttribute('data-stale', '');
    }, GREY_AFTER_MS));
  } else {
    clearTimeout(greyTimers.get(e));
    greyTimers.delete(e);
    attr(e, 'data-stale', null);
  }
}

const follows = new WeakMap();
/** Writes a part of the page that describes the frame (a note, a list) once the frames pause, as
 *  the text alternatives are: `key` names what it would show, `write` writes it. While what is
 *  written differs from the newest frame's, the part is marked busy (markBusy: greyed after 0.2 s).
 *  A frame during a drag then changes nothing in the document (issue 26). */
export function followLater(e, key, write) {
  let f = follows.get(e);
  if (!f) {
    f = { key: undefined, pending: false, later: debounced(DESCRIBE_AFTER_MS, 'timer:describe') };
    follows.set(e, f);
  }
  if (key === f.key && !f.pending) return;
  if (key !== f.key) markBusy(e, true);
  // (A write still pending is replaced by this frame's, even when it changes nothing.)
  f.pending = true;
  f.later(() => {
    f.pending = false;
    if (f.key !== key) write();
    f.key = key;
    markBusy(e, false);
  });
}

export const errText = (e) => String(e && e.message ? e.message : e);

const EQ = /Eq\. \((A\.\d+|\d+)\)(?:–\((A\.\d+|\d+)\))?|decision (\d+)/g;

/** `text` as nodes, each "Eq. (N)" (or "Eq. (N)–(M)") and "decision N" a link to the physics notes. */
export function linked(text) {
  text = String(text);
  const out = [];
  let at = 0;
  for (const m of text.matchAll(EQ)) {
    if (m.index > at) out.push(text.slice(at, m.index));
    const anchor = m[3] ? `decision-${m[3]}` : equationAnchor(m[1]);
    // Out of the Tab order (issue 22: 35 of the ~50 stops before the parameters were equation
    // links); clickable, and every anchor is reachable from the notes' link at the top of the page.
    out.push(el('a', { href: physicsUrl(anchor), class: 'eq', target: '_blank', rel: 'noopener', tabindex: '-1' }, m[0]));
    at = m.index + m[0].length;
  }
  if (at < text.length) out.push(text.slice(at));
  return out;
}

/** Turns every "Eq. (N)" in the text under `root` into a link (not inside links, options, code). */
export function linkify(root) {
  const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT, {
    acceptNode(n) {
      if (!/Eq\. \(|decision \d/.test(n.data)) return NodeFilter.FILTER_REJECT;
      if (n.parentElement.closest('a, option, select, script, style, textarea, canvas, button, label.raw')) return NodeFilter.FILTER_REJECT;
      return NodeFilter.FILTER_ACCEPT;
    },
  });
  const nodes = [];
  while (walker.nextNode()) nodes.push(walker.currentNode);
  for (const n of nodes) n.replaceWith(...linked(n.data));
}

export function median(a) {
  if (!a.length) return NaN;
  const s = [...a].sort((x, y) => x - y);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

/** Splits `text` into lines of at most `width` characters at spaces (long words are cut). */
export function wrapText(text, width) {
  const lines = [];
  let line = '';
  for (let w of String(text).split(/\s+/)) {
    while (w.length > width) { if (line) { lines.push(line); line = ''; } lines.push(w.slice(0, width)); w = w.slice(width); }
    if (line && line.length + 1 + w.length > width) { lines.push(line); line = w; } else line = line ? `${line} ${w}` : w;
  }
  if (line) lines.push(line);
  return lines;
}

/** Writes a property (`put`) or an attribute (`attr`; `null` removes it) only when it differs
 *  (issue 26: every write invalidates the page's style, and a frame rewrote controls, notes and
 *  labels that had not changed). */
export const put = (e, k, v) => { if (e[k] !== v) e[k] = v; };
export const attr = (e, k, v) => {
  if (e.getAttribute(k) === v) return;
  if (v === null) e.removeAttribute(k);
  else e.setAttribute(k, v);
};

let viewHeight = null;
/** The window's inner height [CSS px], kept by a resize listener: reading `window.innerHeight`
 *  after a write to the page forces a layout of the whole page, and a frame read it twice (issue 26). */
export function viewportHeight() {
  if (viewHeight === null) {
    viewHeight = window.innerHeight;
    window.addEventListener('resize', () => { viewHeight = window.innerHeight; });
  }
  return viewHeight;
}

/** Calls `fn` once, after the next display frame is made (its animation frame's task is over), or
 *  after 50 ms where the page gets no animation frames (a hidden tab). */
export function afterPresented(fn) {
  let called = false;
  const once = () => { if (!called) { called = true; fn(); } };
  requestAnimationFrame(() => setTimeout(once, 0));
  setTimeout(once, 50);
}
