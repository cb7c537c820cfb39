// The rime web explorer, wired: controls → requests to the computing worker (coalesced per
// animation frame) → the frame it returns, drawn by the chart, map, tidal and compare modules →
// the link. Each part of a frame fails on its own: what succeeded is drawn, the failing part leaves
// a note in its place, the banner names the cause and the console gets the error; controls and
// the link always show the scene actually drawn. No physics, palette, formatting or ranges here.
import { Explorer, calls, counted, qty, speed, start } from './core.js';
import { CollisionComputer, Computer, poolSize } from './compute.js';
import { Painter, canPaintInWorker } from './painter.js';
import { CollisionView } from './collision.js';
import { $, afterPresented, debounced, DESCRIBE_AFTER_MS, errText, linkify, markBusy, median, put, setText } from './dom.js';
import { START_PRESET, app } from './state.js';
import { buildControls, edit, reflectScene, syncControls, wireToolbar, wireView } from './controls.js';
import { drawChartCanvas, familyNote, pinLabel, pinnedForRequest, restorePin, wireChart } from './chart.js';
import { drawLegend, drawMapCanvas, wireMap } from './map.js';
import { buildTidal, showTidal } from './tidal.js';
import { buildRing, reflectRing, ringInputs, ringOverlay, showRing, takeRing } from './ring.js';
import { buildCompare } from './compare.js';
import { intro, showBanner, showNotice, showPartNotes, showWarnings, wireBanner } from './messages.js';
import { loadHash, writeHash } from './url.js';
import { chartSvg, curvesCsv, familyCsv, mapCsv, mapSvg, setVersion, wireDownloads } from './downloads.js';
import { testHooks, testPreview, testView } from './test-hooks.js';
import { PREVIEWS, SLOW_MS, frameCost, frameKind, nextPreviewLevel } from './frame-rule.js';
import { keepCursor } from './cursor.js';
import { decode, readWire } from './wire.js';
import { drawnEvent, probe, publish } from './publish.js';
import { markCollision, onCollision, replayCollision } from './collision-card.js';

// Exposed for tests and curious users (the test hooks, window.rimeTest: www/test-hooks.js).
window.rimeState = { ready: false, errors: [] };

let pending = false;
let previewLevel = 0; // index into PREVIEWS (frame-rule.js)

/** Asks for a frame once the current event is handled: the edits of one event (a preset sets many
 *  fields) make one request, and the request leaves at once, not at the next animation frame
 *  (issue 26: input → first frame within 16 ms). A dragged slider never queues stale work: each
 *  worker keeps only the newest request waiting (compute.js). */
function schedule() {
  if (pending) return;
  pending = true;
  queueMicrotask(() => { pending = false; request(); });
}

/** Asks the worker for the pinned curve of the link (its scene at its level and speeds), before
 *  the frame of the page: the answer becomes the pin, then the page's frame is asked for. */
function requestPinned() {
  const p = app.pinRequest;
  const view = {
    accuracy: p.accuracy, from: p.from, to: p.to, map_n: 2, family: false,
    experiments: false, date: new Date().toISOString().slice(0, 19) + 'Z',
  };
  app.computer.request(p.scene, view, { pin: p, view: { accuracy: p.accuracy }, t0: performance.now(), calls: 0, format: 0 });
}

/** Asks the worker for the frame of the wanted scene and view (a newer request supersedes it). */
function request() {
  secondaryLater.cancel();
  markCollision();
  if (app.pinRequest) { requestPinned(); return; }
  const v = app.view;
  const view = {
    // Points and map side are the core request's defaults (Request::POINTS, Request::MAP_N).
    accuracy: v.accuracy, from: v.from, to: v.to, map_max: v.mapMax,
    tidal: app.tidalIn, overlays: [...v.overlays], y_log: v.yScale === 'log', experiments: v.experiments,
    pinned: pinnedForRequest(app.wantScene), date: new Date().toISOString().slice(0, 19) + 'Z',
  };
  testView(view);
  const kind = frameKind(app.wantScene, view, app.edited);
  app.edited = '';
  // Main-thread calls across the wasm boundary made for this request (edits since the last one).
  const page = { view: { ...v, overlays: [...v.overlays] }, tidal: app.tidalIn, t0: performance.now(), calls: calls.compute, format: calls.format, kind };
  calls.compute = 0;
  calls.format = 0;
  if (testHooks.finestPreview) { previewLevel = 0; testHooks.finestPreview = false; }
  const preview = testPreview({ ...view, accuracy: 'fast', ...PREVIEWS[previewLevel] });
  const cost = frameCost.get(kind);
  const quick = testHooks.noPreview || (!testHooks.alwaysPreview && cost !== undefined && cost <= SLOW_MS);
  // Whether this request asked for a preview first (the end-to-end test checks the rule).
  window.rimeState.previewAsked = !quick;
  // The newest request (tests wait for its frame: `rimeState.gen === rimeState.asked`).
  window.rimeState.asked = app.computer.request(app.wantScene, view, page, quick ? null : preview, ringInputs(), quick ? preview : null);
}

/** Runs `fn` once the chart drawn so far is on its canvas (at once where the page draws it). */
function afterPaint(fn) {
  if (app.painter) app.painter.after(fn);
  else fn();
}

/** The worker's answer to the newest request: draw what succeeded, report what failed. */
function onFrame(msg, req) {
  const t1 = performance.now();
  if (req && req.page.pin) {
    // The link's pinned curve: kept as the pin, then the page's own frame.
    app.pinRequest = null;
    const j = msg.error ? null : readWire(msg.json, msg.numbers, msg.codes);
    if (j && j.curve) restorePin(req.page.pin, j.g, j.curve.eps);
    else {
      const why = msg.error || (j.errors[0] && j.errors[0].message) || 'no curve';
      console.error(`rime: link: pinned: ${why}`);
      showNotice([`pinned: ${why}`]);
    }
    request();
    return;
  }
  if (msg.error || !req) {
    // The request itself was refused (it never is for a scene the page accepted): keep the drawn
    // frame and put the controls back to it.
    showBanner([{ part: 'request', message: msg.error }]);
    if (app.drawn) {
      app.ex.setJson(app.drawn.scene);
      app.wantScene = app.drawn.scene;
      app.view = { ...app.drawn.view };
      syncControls();
    }
    return;
  }
  if (msg.preview) {
    // The fast preview (issue 26): the chart and map drawn now, the rest of the page (warnings,
    // controls, link, collision card, the test's state) waits for the requested level, and so do
    // the downloads.
    const res = decode(msg, req.page);
    res.accuracy = 'fast';
    // Coarser after a slow preview, finer after a quick one (a worker's first frame, slow while
    // its wasm warms up, costs a coarser preview).
    previewLevel = nextPreviewLevel(msg.ms, res.g.length, previewLevel);
    const sceneChanged = !app.drawn || app.drawn.scene !== req.scene;
    keepCursor(app.res, res);
    app.res = res;
    app.preview = true;
    app.drawn = { scene: req.scene, view: req.page.view, tidal: req.page.tidal };
    if (sceneChanged) app.mapRow = null;
    ringOverlay(res, msg.ring);
    draw();
    const t2 = performance.now();
    timingLater(() => setText($('timing'), `preview: ${qty(msg.ms / 1e3, 's', 3)} in the worker at fast, on screen after ${qty((t2 - req.page.t0) / 1e3, 's', 3)} — refining to ${req.page.view.accuracy}…`));
    $('timing').classList.toggle('busy', true); // (toggle with force: no write when unchanged)
    afterPaint(() => {
      const s = window.rimeState;
      s.previewDrawnAt = performance.now();
      // The refinement held for it (two cores) and the helper's share start once the display
      // frame showing the preview is made: started at once, they took the cores that frame needs
      // (the literal reading at `precise`: first frame 17.4–17.7 → 13.7–14.3 ms, pooled medians).
      afterPresented(() => app.computer.previewDrawn(req.gen));
      s.previews = (s.previews || 0) + 1;
      s.previewPoints = res.g.length;
      s.previewWorkerMs = msg.ms;
      s.previewMs = s.previewDrawnAt - req.page.t0;
      drawnEvent(req.gen, true);
    });
    return;
  }
  app.preview = false;
  // Test hook: an input that lands while this (now older) frame was on its way.
  const racing = testHooks.beforeFrame;
  if (racing) { testHooks.beforeFrame = null; racing(); }
  const res = decode(msg, req.page);
  if (frameCost.size > 200) frameCost.clear();
  if (req.page.kind) frameCost.set(req.page.kind, msg.ms);
  const sceneChanged = !app.drawn || app.drawn.scene !== req.scene;
  keepCursor(app.res, res);
  app.res = res;
  app.drawn = { scene: req.scene, view: req.page.view, tidal: req.page.tidal };
  if (sceneChanged) app.mapRow = null;
  ringOverlay(res, msg.ring);
  const tm = [performance.now()];
  draw();
  tm.push(performance.now());
  showWarnings(res);
  showTidal(res);
  // The ring card came with the frame when it is drawn on the chart; else it is asked for once
  // the frame is on screen (issue 26: it never delays a frame), and the card on screen says it
  // is being computed.
  const ringLater = !msg.ring && req.ring;
  if (!ringLater) { showRing(); window.rimeState.ringOf = req.gen; }
  markBusy($('ring'), ringLater);
  showBanner(res.errors);
  tm.push(performance.now());
  syncControls();
  writeHash();
  const t2 = performance.now();
  tm.push(t2);
  window.rimeState.drawBreakdown = { decode: tm[0] - t1, draw: tm[1] - tm[0], text: tm[2] - tm[1], controls: tm[3] - tm[2], wait: t1 - req.page.t0 };
  app.callsPerUpdate.push(req.page.calls + msg.calls);
  app.formatCallsPerUpdate.push(req.page.format);
  // Whether the frame's units were split over the pool's two workers (issue 26).
  window.rimeState.split = Boolean(msg.helped);
  app.timings.push(msg.ms);
  app.totals.push(t2 - req.page.t0);
  if (app.timings.length > 200) for (const a of [app.timings, app.totals, app.callsPerUpdate, app.formatCallsPerUpdate]) a.shift();
  timingLater(() => setText($('timing'), `last frame: ${qty(msg.ms / 1e3, 's', 3)} in the worker (median ${qty(median(app.timings) / 1e3, 's', 3)}), on screen after ${qty((t2 - req.page.t0) / 1e3, 's', 3)}, accuracy ${res.accuracy}`));
  const newest = req.gen === app.computer.gen;
  if (newest) {
    $('timing').classList.toggle('busy', false);
    put($('busy'), 'hidden', true);
  }
  afterPaint(() => {
    publish(req, res);
    // The collision card's trajectory (its own worker) and the ring card follow once the edits
    // pause: while a slider is dragged they would take a core from the next frame's computation
    // and drawing on a two-core machine (issue 26).
    // (Not for an older request's frame, drawn while a newer one is computed.)
    if (newest) afterEdits(() => {
      replayCollision();
      if (ringLater) {
        const fig = res.figures[0];
        app.computer.ring(req.gen, req.scene, req.ring, [fig.x.min, fig.x.max], res.tidal ? res.tidal.input : null);
      }
    });
  });
}

/** The timing line (in the footer, for developers) is written once the frames pause, as the text
 *  alternatives are: formatting it cost each frame about 0.15 ms of the page's thread. */
const timingLater = debounced(DESCRIBE_AFTER_MS, 'timer:describe');

/** How long after the newest frame the secondary cards are computed, if no edit came [ms]. */
const SECONDARY_AFTER_MS = 100;
const secondaryLater = debounced(SECONDARY_AFTER_MS, 'timer:secondary');
/** Runs `fn` SECONDARY_AFTER_MS after now unless a request is made meanwhile (request() cancels). */
function afterEdits(fn) {
  const gen = app.computer.gen;
  secondaryLater(() => { if (app.computer.gen === gen) fn(); });
}

/** The ring card asked for after the newest frame (`Computer.ring`). */
function onRing(msg) {
  takeRing(msg.ring);
  showRing();
  markBusy($('ring'), false);
  window.rimeState.ringOf = msg.gen;
  window.rimeState.ringMs = msg.ms;
}

let busyTimer = null;
function onBusy(busy) {
  clearTimeout(busyTimer);
  if (!busy) { $('timing').classList.toggle('busy', false); put($('busy'), 'hidden', true); return; }
  // Say so only when it takes long enough to notice, in the note floating at the bottom of the
  // screen: a preview on screen (fewer points, at `fast`) is named as one while its refinement is
  // awaited.
  busyTimer = setTimeout(() => {
    if (!app.computer.busy) return;
    setText($('busy'), app.preview ? `a fast preview is shown — refining to ${app.view.accuracy}… the controls stay live` : 'computing… the controls stay live');
    if (!app.preview) {
      $('timing').classList.toggle('busy', true); // (toggle with force: no write when unchanged)
      timingLater.cancel(); // a frame's line not yet written is older than this
      $('timing').textContent = `computing (${app.view.accuracy})…`;
    }
    $('busy').hidden = false;
  }, 120);
}

function draw() {
  if (!app.res) return;
  const t00 = performance.now();
  // The figures' widths as last laid out (a ResizeObserver keeps them): reading them here, after
  // this frame's writes to the page, would force a synchronous layout of the whole page, the
  // biggest part of a redraw's time on the page's thread (issue 26).
  const widths = figureWidths();
  const t = [performance.now()];
  pinLabel();
  drawChartCanvas(widths.chart);
  t.push(performance.now());
  familyNote(app.res);
  drawLegend(app.res);
  t.push(performance.now());
  drawMapCanvas(widths);
  t.push(performance.now());
  showPartNotes(app.res);
  t.push(performance.now());
  // Where a redraw's time goes on the page's thread [ms] (the frame benchmark reads it).
  window.rimeState.drawParts = { layout: t[0] - t00, chart: t[1] - t[0], legend: t[2] - t[1], map: t[3] - t[2], notes: t[4] - t[3] };
}

const widthsSeen = { chart: null, map: null, epsT: null };
let widthsObserver = null;
/** The widths of the figures' boxes [CSS px], read once and then kept by a ResizeObserver. */
function figureWidths() {
  const boxes = { chart: $('chart').parentElement, map: $('map').parentElement, epsT: $('eps-t').parentElement };
  if (!widthsObserver) {
    for (const [k, e] of Object.entries(boxes)) widthsSeen[k] = e.clientWidth;
    widthsObserver = new ResizeObserver((entries) => {
      let changed = false;
      for (const en of entries) {
        const k = Object.keys(boxes).find((x) => boxes[x] === en.target);
        const w = en.target.clientWidth;
        if (k && widthsSeen[k] !== w) { widthsSeen[k] = w; changed = true; }
      }
      if (changed) requestAnimationFrame(draw);
    });
    for (const e of Object.values(boxes)) widthsObserver.observe(e);
  }
  return { ...widthsSeen };
}

async function main() {
  // One compiled module for the page (validation, words, formatting) and the worker (frames).
  const bytes = await (await fetch(new URL('./pkg/rime_wasm_bg.wasm', import.meta.url))).arrayBuffer();
  const module = await WebAssembly.compile(bytes);
  await start(module);
  app.ex = counted(new Explorer());
  app.ex.loadPreset(START_PRESET);
  app.probeEx = counted(new Explorer());
  app.collisionG = 0.01;
  app.collisionView = new CollisionView();
  app.params = JSON.parse(Explorer.parameters());
  app.classes = JSON.parse(Explorer.classes());
  app.statusNames = JSON.parse(Explorer.statusNames());
  const version = Explorer.version();
  $('version').textContent = version;
  $('project-version').textContent = `rime ${version}`;
  setVersion(version);
  app.experiments = JSON.parse(Explorer.experiments());
  app.overlayChoices = JSON.parse(Explorer.overlays());
  intro();
  const validateTidal = (input) => app.ex.tidal(JSON.stringify(input));
  buildCompare({ schedule, edit });
  buildControls({ schedule });
  wireToolbar(JSON.parse(Explorer.presets()));
  wireView();
  buildTidal({ schedule, validate: validateTidal });
  buildRing({ schedule });
  wireChart({ schedule, replay: replayCollision });
  wireMap({ replay: replayCollision });
  wireDownloads((e) => window.rimeState.errors.push(errText(e)));
  linkify(document.body);
  // The skip link moves focus to the parameters without touching the link's hash (which holds the state).
  $('skip').addEventListener('click', (ev) => {
    ev.preventDefault();
    const h = $('parameters-heading');
    h.scrollIntoView();
    h.focus();
  });
  wireBanner();
  // On a phone the intro follows the chart (in the document too, so that the Tab order and a
  // screen reader follow what is seen): the chart is in the first screen.
  const phone = window.matchMedia('(max-width: 480px)');
  const placeIntro = () => {
    const intro = document.querySelector('.intro');
    if (phone.matches) document.querySelector('.chart-card').after(intro);
    else document.querySelector('main').before(intro);
  };
  placeIntro();
  phone.addEventListener('change', placeIntro);
  let resizeQueued = false;
  window.addEventListener('resize', () => {
    if (resizeQueued) return;
    resizeQueued = true;
    requestAnimationFrame(() => { resizeQueued = false; draw(); });
  });
  window.addEventListener('hashchange', () => {
    // Our own replaceState does not fire this; a pasted or edited link does.
    showNotice(loadHash(validateTidal));
    reflectScene();
    reflectRing();
    schedule();
  });
  if (canPaintInWorker()) {
    const elements = Object.fromEntries(['chart', 'chart-fg', 'map', 'eps-t'].map((id) => [id, $(id)]));
    app.painter = new Painter(module, elements, (e) => {
      console.error(`rime: ${e}`);
      window.rimeState.errors.push(e);
    });
  }
  window.rimeState.paint = app.painter ? 'worker' : 'main';
  app.computer = new Computer(module, onFrame, onBusy, onRing);
  window.rimeState.workers = poolSize();
  app.collider = new CollisionComputer(module, onCollision);
  app.wantScene = app.ex.toJson();
  showNotice(loadHash(validateTidal));
  reflectScene();
  reflectRing();
  calls.compute = 0;
  calls.format = 0;
  request();
}

// Exposed for the end-to-end test: the texts the download buttons save, and probes.
window.rimeExports = {
  chartSvg, mapSvg, curvesCsv: () => curvesCsv(), familyCsv: () => familyCsv(), mapCsv: () => mapCsv(),
  probe: (g) => probe(g, app.drawn.view.accuracy),
  speed: (v) => speed(v), qty: (v, u) => qty(v, u),
};

/** Test hook: the pixels of a canvas and of its data layer (`${id}-fg`, when it has one), as
 *  [{width, height, data}], wherever they are drawn. */
testHooks.layers = async (id) => {
  if (app.painter && ['chart', 'map', 'eps-t'].includes(id)) return app.painter.pixels(id === 'chart' ? ['chart', 'chart-fg'] : [id]);
  return [id, `${id}-fg`].map((k) => document.getElementById(k)).filter(Boolean)
    .map((c) => ({ width: c.width, height: c.height, data: c.getContext('2d').getImageData(0, 0, c.width, c.height).data }));
};

main().catch((e) => {
  console.error(`rime: failed to start: ${errText(e)}`);
  window.rimeState.errors.push(errText(e));
  $('timing').textContent = `failed to start: ${errText(e)}`;
});
