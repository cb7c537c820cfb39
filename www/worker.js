// The computing half of the page: a module worker holding the wasm module. It answers each request
// {gen, scene, view} with one whole frame (one computeFrame call, then its three arrays) or with the
// request's error, so that no level of accuracy ever blocks the page's input. With `preview` it
// first sends the frame at `fast`, marked `preview: true` (issue 26).
import init, { Explorer, computeFrame } from './pkg/rime_wasm.js';

let ready = null;
let explorer = null; // the collision card's scene (one per worker)

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
  if (msg.type !== 'frame') return;
  await ready;
  const t0 = performance.now();
  let calls = 0;
  try {
    // The end-to-end test's stand-in for a slow computation: the worker is busy, the page is not.
    const { testDelayMs, testRefineDelayMs, ...view } = msg.view;
    if (testDelayMs > 0) { const until = performance.now() + testDelayMs; while (performance.now() < until) { /* busy */ } }
    // A preview first (issue 26): the same view at `fast`, drawn while the requested level computes.
    if (msg.preview && view.accuracy !== 'fast') {
      const p = computeFrame(msg.scene, JSON.stringify({ ...view, accuracy: 'fast' }));
      const [pjson, pnumbers, pcodes] = [p.json(), p.numbers(), p.codes()];
      p.free();
      calls += 5;
      self.postMessage({ type: 'frame', gen: msg.gen, preview: true, json: pjson, numbers: pnumbers, codes: pcodes, ms: performance.now() - t0, calls: 0 }, [pnumbers.buffer, pcodes.buffer]);
      // The end-to-end test's stand-in for a slow refinement (the preview stays on screen).
      if (testRefineDelayMs > 0) { const until = performance.now() + testRefineDelayMs; while (performance.now() < until) { /* busy */ } }
    }
    const t1 = performance.now();
    const f = computeFrame(msg.scene, JSON.stringify(view));
    const json = f.json();
    const numbers = f.numbers();
    const codes = f.codes();
    f.free();
    calls += 5;
    const ms = performance.now() - t1;
    self.postMessage({ type: 'frame', gen: msg.gen, json, numbers, codes, ms, calls }, [numbers.buffer, codes.buffer]);
  } catch (e) {
    calls += 1;
    self.postMessage({ type: 'frame', gen: msg.gen, error: String(e && e.message ? e.message : e), ms: performance.now() - t0, calls });
  }
};
