// What the page says in words around the figures: the intro (the core's glossary and citation),
// the banner naming parts of a frame that failed, the notes in their place, the core's warnings,
// and the notice naming fields of a link that could not be read.
import { HELP, citation, physicsUrl } from './core.js';
import { $, el, followLater, linked, put, setText } from './dom.js';
import { showOverlayScores } from './compare.js';

let bannerKey = '';
let bannerDismissed = '';
let bannerListKey = null; // the errors the banner's list shows

export function wireBanner() {
  $('banner-close').addEventListener('click', () => { bannerDismissed = bannerKey; $('banner').hidden = true; });
}

/** The banner naming every part that failed (role=alert), each error also to the console. */
export function showBanner(errors) {
  const key = JSON.stringify(errors);
  if (key !== bannerKey) {
    for (const e of errors) console.error(`rime: ${e.part}: ${e.message}`);
    bannerKey = key;
  }
  const b = $('banner');
  // Written only when it changes (issue 26: a write invalidates the page's style).
  if (!errors.length || bannerDismissed === key) { put(b, 'hidden', true); return; }
  if (bannerListKey !== key) {
    bannerListKey = key;
    $('banner-list').replaceChildren(...errors.map((e) => el('li', {}, el('strong', {}, e.part), `: ${e.message}`)));
  }
  put(b, 'hidden', false);
}

export function showWarnings(res) {
  showOverlayScores(res);
  // The core's warnings, each with its help on hover (the terminal's `?` and the CLI say the same).
  const details = res.warningDetails || res.warnings.map((text) => ({ text, help: '' }));
  // Rebuilt only when they change, once the frames pause (issue 26: a frame's DOM writes are the
  // page thread's cost, and a warning that comes and goes during a drag would flicker).
  followLater($('warnings'), JSON.stringify(details), () => $('warnings').replaceChildren(...details.map((w) => el('li', { title: w.help }, ...linked(w.text)))));
}

/** A visible note in place of each part of the chart that failed (the banner has the details). */
export function showPartNotes(res) {
  const notes = [];
  for (const e of res.errors) {
    if (e.part === 'stick map' || e.part === 'tidal' || /^(atlas|model):/.test(e.part)) continue;
    notes.push(e.part === 'curve' ? `this scene: ${res.gaps} of ${res.g.length} speeds failed, drawn as gaps`
      : e.part === 'clean' ? 'clean surface: gaps where ε_N failed'
        : e.part.startsWith('family') ? `${e.part.replace('family ', 'family curve ')} not drawn`
          : `${e.part}: not drawn`);
  }
  const cn = $('chart-note');
  setText(cn, notes.length ? `⚠ ${notes.join(' · ')} (see the message above)` : '');
  put(cn, 'hidden', !notes.length);
  const rn = $('map-range-note');
  setText(rn, res.mapNote ? `Note: ${res.mapNote}.` : '');
  put(rn, 'hidden', !res.mapNote);
}

export function showNotice(problems) {
  const n = $('notice');
  if (!problems.length) { n.hidden = true; n.textContent = ''; return; }
  n.hidden = false;
  n.replaceChildren(
    el('strong', {}, 'Part of the link could not be read; '), 'the rest of it was kept and the fields named here are at their defaults:',
    el('ul', {}, ...problems.map((p) => el('li', {}, p))));
  window.rimeState.notice = n.textContent;
}

/** The intro: what the page is, the glossary, how to read it, the paper and the notes. */
export function intro() {
  const glossary = new Map(HELP.glossary.map((g) => [g.term, g.meaning]));
  const dl = $('glossary');
  for (const term of ['ε_N', 'g_N', 'g_T', 'this scene', 'g_s', 'ε_T', 'family', 'clean surface', 'stick map']) {
    if (glossary.has(term)) dl.append(el('dt', {}, term), el('dd', {}, ...linked(glossary.get(term))));
  }
  // The full citation, without a link: rime has not verified the paper's DOI, and there is no
  // public repository yet, so the notes are served beside the page and the project is named.
  $('citation').textContent = citation();
  for (const a of document.querySelectorAll('a[data-physics]')) a.href = physicsUrl(a.dataset.physics);
}
