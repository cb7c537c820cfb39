// What the page shows, told to tests, benchmarks and curious users: the drawn frame in
// `window.rimeState`, a `rime:drawn` event per frame on its canvas, and a probe of the drawn scene.
import { app, historySize } from './state.js';

/** The drawn frame in `window.rimeState` (tests and curious users), once it is on screen. */
export function publish(req, res) {
  const s = window.rimeState;
  const fig = res.figures[0];
  const bridges = fig.series.find((x) => /^Bridges/.test(x.name));
  // The frame's arrays as plain arrays when first read (copying them for every frame was a
  // sizeable part of a frame's time on the page's thread, for tests alone).
  const lazy = (name, fn) => Object.defineProperty(s, name, {
    enumerable: true,
    configurable: true,
    get() { const v = fn(); Object.defineProperty(s, name, { value: v, enumerable: true, configurable: true, writable: true }); return v; },
  });
  lazy('g', () => Array.from(res.g));
  lazy('computeMs', () => [...app.timings]);
  lazy('totalMs', () => [...app.totals]);
  lazy('callsPerUpdate', () => [...app.callsPerUpdate]);
  lazy('formatCallsPerUpdate', () => [...app.formatCallsPerUpdate]);
  lazy('eps', () => (res.eps ? Array.from(res.eps) : []));
  lazy('status', () => (res.status ? Array.from(res.status, (c) => app.statusNames[c] ?? 'failed') : []));
  lazy('family', () => res.family && { path: res.family.path, values: res.family.values, isScene: res.family.isScene, curves: res.family.curves.map((c) => c && Array.from(c)) });
  lazy('mapClasses', () => (res.map ? Array.from(res.map.codes) : null));
  lazy('experiments', () => (bridges || fig.bands.length
    ? { bridges: bridges ? { name: bridges.name, g: Array.from(bridges.x), eps: Array.from(bridges.y) } : null, bands: fig.bands } : null));
  lazy('overlays', () => res.overlays.map((o) => ({ key: o.key, label: o.label, band: o.band, score: o.score, g: Array.from(o.g), eps: Array.from(o.eps), speeds: o.speeds })));
  Object.assign(s, {
    ready: true,
    gen: req.gen,
    sceneJson: req.scene,
    view: { ...req.page.view },
    critical: res.crit,
    warnings: res.warnings,
    warningDetails: res.warningDetails,
    mapMax: res.map ? res.map.max : null,
    mapNote: res.mapNote,
    figure: { y: fig.y, x: fig.x, series: fig.series.map((x) => x.name), styles: fig.series.map((x) => `${x.color}/${x.stroke}`), widths: fig.series.map((x) => x.width || null), bands: fig.bands.map((b) => b.label), markers: fig.markers.map((m) => m.label), caption: fig.caption },
    tidal: res.tidal,
    tidalIn: app.tidalIn,
    frameErrors: res.errors,
    workerRestarts: app.computer.restarts,
    refinementsStopped: app.computer.stopped,
    refinementPosted: app.computer.refinementPosted,
    history: historySize(),
    pinned: app.pinned ? { g: app.pinned.g, eps: app.pinned.eps, label: app.pinned.label } : null,
    updates: (s.updates || 0) + 1,
    drawnAt: performance.now(),
  });
  drawnEvent(req.gen, false);
}

/** Tells the tests and benchmarks that a preview or frame is on its canvas: an event, not a mark
 *  in the document (a mark cost each frame a rendering update of the page's thread). */
export function drawnEvent(gen, preview) {
  window.dispatchEvent(new CustomEvent('rime:drawn', { detail: { gen, preview } }));
}

/** The normal result at `g` for the drawn scene (main thread; tests). */
export function probe(g, accuracy) {
  if (!app.drawn) throw new Error('nothing drawn yet');
  if (app.probeScene !== app.drawn.scene) {
    app.probeEx.setJson(app.drawn.scene);
    app.probeScene = app.drawn.scene;
  }
  return JSON.parse(app.probeEx.normal(g, accuracy));
}
