// The computing half of the page: a module worker holding the wasm module. It answers each request
// {gen, scene, frames: [{view, preview, split}], ring, help} with one message per frame, in order
// (a preview in one computeFrame call; the requested frame a few units at a time, see `refine`; the
// last message marked `last`; a refinement stopped for a newer request marked `stale`), or with the
// request's error, so that no level of accuracy ever blocks the page's input. A preview (issue 26) is a
// frame the page draws until the requested one arrives. The ring card (issue 24) is computed here
// too: on the literal layer reading it takes longer than a frame, and on the page's thread it was
// a long task. With a frame only when it is drawn on the chart (`ring.onChart`); otherwise the page
// asks for it ({type: 'ring', gen, scene, ring, chart, tidal}) once the frame is on screen, so that
// it never delays a frame (issue 26).
import init, { Explorer, FrameShare, PendingFrame, computeFrame, ringCard } from './pkg/rime_wasm.js';

let ready = null;
// The other frame worker of the pool (a MessagePort the page hands over): a refinement's units are
// split between the two when the refinement is dear (issue 26; rime_core::explorer::share). This worker
// helps with a share after its preview, and takes the other's share for its own refinements.
let peer = null;
let latestGen = 0; // the newest request this worker was asked for: a stale share stops
let helpLater = null; // {gen, scene, view}: the share to compute when the page says 'help'
let doneGen = 0; // the newest refinement the peer finished: a share for it is no longer wanted
const inbox = new Map(); // gen -> the peer's share that came before it was waited for
let waiter = null; // {gen, resolve} while a refinement waits for the peer's share
// A turn of the event loop (without setTimeout's clamp), so that a newer request's note or the
// peer's share is read between two units; several loops may wait at once (first in, first out).
const yielder = new MessageChannel();
const yielded = [];
yielder.port1.onmessage = () => { const resolve = yielded.shift(); if (resolve) resolve(); };
const yieldNow = () => new Promise((resolve) => { yielded.push(resolve); yielder.port2.postMessage(0); });
/** A refinement computes this long between two turns of the event loop [ms] (a cheap frame never
 *  waits for one). */
const SLICE_MS = 4;
/** The end-to-end test's pause (www/test-hooks.js `pauseRefinement`): a refinement waits after its
 *  first unit, as at a turn of the event loop, until the page says `test-resume`. */
let resumeTest = null;
const pausedForTest = (gen) => new Promise((resolve) => {
  resumeTest = resolve;
  self.postMessage({ type: 'test-paused', gen });
});

function onPeer(m) {
  if (m.type === 'done') { doneGen = Math.max(doneGen, m.gen); return; }
  if (m.type !== 'share') return;
  if (waiter && waiter.gen === m.gen) waiter.resolve(m);
  else if (m.gen >= latestGen) { inbox.clear(); inbox.set(m.gen, m); }
}

/** The peer's share of request `gen`, or null if it has not come within `waitMs`. */
function takeShare(gen, waitMs) {
  const got = inbox.get(gen);
  inbox.clear();
  if (got) return Promise.resolve(got);
  return new Promise((resolve) => {
    // null: a check waits for the share however long it takes (www/test-hooks.js `waitForShare`).
    const timer = waitMs === null ? null : setTimeout(() => { waiter = null; resolve(null); }, waitMs);
    waiter = { gen, resolve: (m) => { if (timer !== null) clearTimeout(timer); waiter = null; resolve(m); } };
  });
}

/** The requested frame of `scene` through `view` (JSON): this worker's units a few milliseconds
 *  at a time, stopping (null) when a newer request is announced (issue 26: a stale refinement is
 *  cancelled when the next edit arrives, and the worker keeps its memo); with `split`, the peer's
 *  share, waited for as long as this worker's own units took (computing the rest here takes about
 *  that long); then whatever did not come. The frame `computeFrame` gives, bit for bit. */
async function refine(gen, scene, view, split, pause, waitShare) {
  const p = new PendingFrame(scene, view, split ? 2 : 1);
  try {
    const t0 = performance.now();
    let slice = t0;
    // Time spent waiting (turns of the event loop, the peer's share), not computing.
    let waited = 0;
    while (p.runNext()) {
      // (A check's pause, www/test-hooks.js, stands for a long slice: it ends at this turn.)
      if (pause || performance.now() - slice > SLICE_MS) {
        const tw = performance.now();
        if (pause) { pause = false; await pausedForTest(gen); } else await yieldNow();
        waited += performance.now() - tw;
        if (latestGen > gen) return null;
        slice = performance.now();
      }
    }
    let helped = 0;
    if (split) {
      const tw = performance.now();
      const share = await takeShare(gen, waitShare ? null : Math.max(2, tw - t0 - waited));
      waited += performance.now() - tw;
      // A share that has not come is computed here: the peer may stop.
      if (!share && peer) peer.postMessage({ type: 'done', gen });
      if (latestGen > gen) return null;
      if (share && p.accept(share.numbers, share.codes, share.meta)) helped = share.ms;
    }
    return { f: p.finish(), helped, waited };
  } finally {
    p.free();
  }
}

/** After the preview: share 1 of 2 of request `gen`'s refinement (`view`, JSON), a unit per turn
 *  of the event loop, dropped when a newer request comes; sent to the peer. */
async function help(gen, scene, view) {
  if (!peer) return;
  let run = null;
  try {
    run = new FrameShare(scene, view, 1, 2);
    const t0 = performance.now();
    let ms = 0;
    for (;;) {
      const t = performance.now();
      const more = run.step();
      ms += performance.now() - t;
      if (!more) break;
      await yieldNow();
      if (latestGen > gen || doneGen >= gen) return;
    }
    // The share in the core's wire form (rime_core::wire): its JSON and two flat arrays.
    const numbers = run.numbers();
    const codes = run.codes();
    peer.postMessage({ type: 'share', gen, numbers, codes, meta: run.meta(), ms, wall: performance.now() - t0 }, [numbers.buffer, codes.buffer]);
  } catch (e) {
    // The refinement computes the share itself.
  } finally {
    if (run) run.free();
  }
}

let explorer = null; // the collision card's scene (one per worker)
const ringMemo = { key: '', out: null };

/** An exception's message for the page. */
const message = (e) => String(e && e.message ? e.message : e);
/** A view without the end-to-end test's stand-ins (`testPreviewExtraMs`, `testPauseRefinement`, `testWaitShare`;
 *  www/test-hooks.js), and them. */
const splitTestKeys = ({ testPreviewExtraMs, testPauseRefinement, testWaitShare, ...view }) => ({ view, testPreviewExtraMs, testPauseRefinement, testWaitShare });

/** The ring card of `scene` for the inputs `r` over the chart's speeds `chart` ([from, to]),
 *  with the tidal card's planet and distance `tidal` (or null; memoised). */
function ring(scene, r, chart, tidal) {
  const input = { tau: r.tau, chart, sizes: r.sizes };
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
    try { out = { json: ringCard(scene, text) }; } catch (e) { out = { error: message(e) }; }
    Object.assign(ringMemo, { key, out });
  }
  return ringMemo.out;
}

self.onmessage = async (ev) => {
  const msg = ev.data;
  if (msg.type === 'newer') {
    // A newer request was made: a stale refinement or share stops at its next turn.
    latestGen = Math.max(latestGen, msg.gen);
    return;
  }
  if (msg.type === 'help') {
    const h = helpLater;
    helpLater = null;
    if (h && h.gen === msg.gen && h.gen >= latestGen && h.gen > doneGen) help(h.gen, h.scene, h.view);
    return;
  }
  if (msg.type === 'test-resume') {
    const r = resumeTest;
    resumeTest = null;
    if (r) r();
    return;
  }
  if (msg.type === 'peer') {
    peer = msg.port;
    peer.onmessage = (e) => onPeer(e.data);
    return;
  }
  if (msg.type === 'init') {
    ready = init({ module_or_path: msg.module }).then(() => self.postMessage({ type: 'ready' }));
    try { await ready; } catch (e) { self.postMessage({ type: 'fatal', message: `worker: ${message(e)}` }); }
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
      self.postMessage({ type: 'collision', id: msg.id, error: message(e), ms: performance.now() - t0 });
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
  latestGen = Math.max(latestGen, msg.gen);
  await ready;
  const n = msg.frames.length;
  for (let k = 0; k < n; k++) {
    const { view: full, preview, split } = msg.frames[k];
    const last = k === n - 1;
    const t0 = performance.now();
    try {
      // The end-to-end test's stand-in: a preview's time counted longer (a test clock, no wait).
      const { view, testPreviewExtraMs, testPauseRefinement, testWaitShare } = splitTestKeys(full);
      const t1 = performance.now();
      // A preview is never exported: it goes without records (issue 26).
      const viewJson = JSON.stringify(preview ? { ...view, records: false } : view);
      let f;
      let helped = 0;
      let waited = 0;
      if (preview) f = computeFrame(msg.scene, viewJson);
      else {
        const done = await refine(msg.gen, msg.scene, viewJson, Boolean(split && peer), Boolean(testPauseRefinement), Boolean(testWaitShare));
        if (!done) {
          self.postMessage({ type: 'frame', gen: msg.gen, preview, last: true, stale: true, ms: performance.now() - t0 });
          return;
        }
        ({ f, helped, waited } = done);
      }
      const json = f.json();
      const numbers = f.numbers();
      const codes = f.codes();
      // The records (the CSV of the downloads) as UTF-8 bytes, handed over without a copy and
      // read only when a download asks for them (issue 26).
      const records = f.records();
      f.free();
      const ms = performance.now() - t1 + (preview && testPreviewExtraMs > 0 ? testPreviewExtraMs : 0);
      // The ring card when it is drawn on the chart (with a preview too); else the page asks.
      let r = null;
      if (msg.ring && msg.ring.onChart) {
        const j = JSON.parse(json);
        const fig = j.figures[0];
        r = ring(msg.scene, msg.ring, [fig.x.min, fig.x.max], j.tidal && !j.tidal.error ? j.tidal.input : null);
      }
      // `work`: the frame's compute time on one worker (its own, without its waits, and its
      // helper's), which decides whether the next refinement is split.
      self.postMessage({ type: 'frame', gen: msg.gen, preview, last, json, records, numbers, codes, ring: r, ms, work: ms - waited + helped, helped: helped > 0, calls: preview ? 0 : 5 }, [numbers.buffer, codes.buffer, records.buffer]);
      // This worker's share of the refinement (when the page asked for help) starts once the page
      // has drawn the preview ('help'): before, it took a core from the preview's drawing.
      if (last && msg.help) {
        helpLater = { gen: msg.gen, scene: msg.scene, view: JSON.stringify(splitTestKeys(msg.help.view).view) };
      }
    } catch (e) {
      // A refused preview is dropped by the page (the requested frame, refused alike, says why).
      self.postMessage({ type: 'frame', gen: msg.gen, preview, last, error: message(e), ms: performance.now() - t0, calls: 1 });
    }
  }
};
