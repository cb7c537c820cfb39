// The computing half of the page: a module worker holding the wasm module. It answers each request
// {gen, scene, frames: [{view, preview}], ring} with one message per frame, in order (one
// computeFrame call, then its four parts; the last one marked `last`), or with the request's
// error, so that no level of accuracy ever blocks the page's input. A preview (issue 26) is a
// frame the page draws until the requested one arrives. The ring card (issue 24) is computed here
// too: on the literal layer reading it takes longer than a frame, and on the page's thread it was
// a long task. With a frame only when it is drawn on the chart (`ring.onChart`); otherwise the page
// asks for it ({type: 'ring', gen, scene, ring, chart, tidal}) once the frame is on screen, so that
// it never delays a frame (issue 26).
import init, { Explorer, computeFrame, ringCard } from './pkg/rime_wasm.js';

let ready = null;
let explorer = null; // the collision card's scene (one per worker)
const ringMemo = { key: '', out: null };

const busyWait = (ms) => { const until = performance.now() + ms; while (performance.now() < until) { /* busy */ } };

/** The ring card of `scene` for the inputs `r` over the chart's speeds `chart` ([from, to]),
 *  with the tidal card's planet and distance `tidal` (or null; memoised). */
function ring(scene, r, chart, tidal) {
  const input = { tau: r.tau, chart };
  if (r.planet && tidal) {
    input.planet_mass = tidal.planet_mass;
    input.distance = tidal.distance;
  } else {
    input.omega = r.omega;
  }
  const text = JSON.stringify(input);
  const key = `${scene}|${text}`;
  if (key !== ringMemo.key) {
    let out;
    try { out = { json: ringCard(scene, text) }; } catch (e) { out = { error: String(e && e.message ? e.message : e) }; }
    Object.assign(ringMemo, { key, out });
  }
  return ringMemo.out;
}

self.onmessage = async (ev) => {
  const msg = ev.data;
  if (msg.type === 'init') {
    ready = init({ module_or_path: msg.module }).then(() => self.postMessage({ type: 'ready' }));
    try { await ready; } catch (e) { self.postMessage({ type: 'fatal', message: `worker: ${e && e.message ? e.message : e}` }); }
    return;
  }
  if (msg.type === 'collision') {
    // The collision card's integration (up to ~12 ms at the precise levels, several times that on
    // a slow phone): here, never on the page's thread (issue 22).
    await ready;
    const t0 = performance.now();
    try {
      explorer ||= new Explorer();
      explorer.setJson(msg.scene);
      const json = explorer.collision(msg.g, msg.points, msg.accuracy);
      self.postMessage({ type: 'collision', id: msg.id, json, ms: performance.now() - t0 });
    } catch (e) {
      self.postMessage({ type: 'collision', id: msg.id, error: String(e && e.message ? e.message : e), ms: performance.now() - t0 });
    }
    return;
  }
  if (msg.type === 'ring') {
    await ready;
    const t0 = performance.now();
    const r = ring(msg.scene, msg.ring, msg.chart, msg.tidal);
    self.postMessage({ type: 'ring', gen: msg.gen, last: true, ring: r, ms: performance.now() - t0 });
    return;
  }
  if (msg.type !== 'frame') return;
  await ready;
  const n = msg.frames.length;
  for (let k = 0; k < n; k++) {
    const { view: full, preview } = msg.frames[k];
    const last = k === n - 1;
    const t0 = performance.now();
    try {
      // The end-to-end test's stand-ins: a slow computation (the worker is busy, the page is
      // not) and a slow refinement (the preview stays on screen).
      const { testDelayMs, testRefineDelayMs, ...view } = full;
      if (testDelayMs > 0 && (k === 0 || !preview)) busyWait(testDelayMs);
      if (testRefineDelayMs > 0 && !preview) busyWait(testRefineDelayMs);
      const t1 = performance.now();
      // A preview is never exported: it goes without records (issue 26).
      const f = computeFrame(msg.scene, JSON.stringify(preview ? { ...view, records: false } : view));
      const json = f.json();
      const numbers = f.numbers();
      const codes = f.codes();
      // The records (the CSV of the downloads) as UTF-8 bytes, handed over without a copy and
      // read only when a download asks for them (issue 26).
      const records = f.records();
      f.free();
      const ms = performance.now() - t1;
      // The ring card when it is drawn on the chart (with a preview too); else the page asks.
      let r = null;
      if (msg.ring && msg.ring.onChart) {
        const j = JSON.parse(json);
        const fig = j.figures[0];
        r = ring(msg.scene, msg.ring, [fig.x.min, fig.x.max], j.tidal && !j.tidal.error ? j.tidal.input : null);
      }
      self.postMessage({ type: 'frame', gen: msg.gen, preview, last, json, records, numbers, codes, ring: r, ms, calls: preview ? 0 : 5 }, [numbers.buffer, codes.buffer, records.buffer]);
    } catch (e) {
      // A refused preview is dropped by the page (the requested frame, refused alike, says why).
      self.postMessage({ type: 'frame', gen: msg.gen, preview, last, error: String(e && e.message ? e.message : e), ms: performance.now() - t0, calls: 1 });
    }
  }
};
