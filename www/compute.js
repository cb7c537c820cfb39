// The page's side of the workers: posts requests, drops stale answers by generation, and restarts
// a worker when a newer request waits behind a slow one (a computation cannot be interrupted).
import { gate, happened, later, testHooks } from './test-hooks.js';

/** How long a running request may hold up a newer one before its worker is restarted [ms]. */
const RESTART_AFTER_MS = 150;

/** A frame asked without a preview (one of its kind came quickly) that has not come this long
 *  after the request gets its preview after all, from the other worker [ms]. */
const LATE_MS = 12;

/** A refinement whose last one cost more than this on one worker [ms] is split over the pool's
 *  two workers (splitting has its costs: the plan made twice, the share sent across). */
const SPLIT_ABOVE_MS = 16;

/** Where the browser reports fewer than four cores, a refinement that comes after a preview is
 *  posted once the preview is on screen (previewDrawn): the preview's worker, the page's thread,
 *  the painter and the compositor need the cores until then (issue 26). At most this long after
 *  the request [ms]. */
const HOLD_REFINEMENT = (navigator.hardwareConcurrency || 1) < 4 && new URLSearchParams(location.search).get('hold') !== '0';
const HOLD_AT_MOST_MS = 40;

/** One worker and its requests: one running, the newest one queued (older queued ones are
 *  dropped, so a dragged slider never queues stale work). A running refinement stops by itself at
 *  its next unit once told of a newer request (`newer`, see Computer.request); what cannot stop (a
 *  preview, the ring card) and holds up a newer request for RESTART_AFTER_MS is dropped with its
 *  worker, and the worker is started again. */
class Lane {
  constructor(module, onMessage, onCrash, onSpawn = () => {}) {
    this.module = module;
    this.onMessage = onMessage;
    this.onCrash = onCrash;
    this.onSpawn = onSpawn;
    this.running = null; // {req, since}
    this.queued = null;
    this.restarts = 0;
    this.spawn();
  }

  spawn() {
    const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.worker = worker;
    // (An answer a check holds, www/test-hooks.js, is dropped if its worker was restarted meanwhile.)
    worker.onmessage = (ev) => gate(answerKind(ev.data), () => { if (this.worker === worker) this.answer(ev.data); });
    this.worker.onerror = (ev) => {
      ev.preventDefault();
      const req = this.running && this.running.req;
      this.running = null;
      if (req) this.onCrash(req, `worker: ${ev.message || 'crashed'}`);
      this.restart();
    };
    this.worker.postMessage({ type: 'init', module: this.module });
    this.onSpawn();
  }

  restart() {
    this.worker.terminate();
    this.restarts++;
    happened('restart');
    this.spawn();
    this.pump();
  }

  post(req) {
    this.queued = req;
    const run = this.running;
    if (!run) { this.pump(); return; }
    // The running request is stale: if it is slow, drop it with its worker.
    const wait = Math.max(0, RESTART_AFTER_MS - (performance.now() - run.since));
    later('timer:restart', () => {
      if (this.running === run && this.queued) {
        this.running = null;
        this.restart();
      }
    }, wait);
  }

  pump() {
    if (this.running || !this.queued) return;
    const req = this.queued;
    this.queued = null;
    this.running = { req, since: performance.now() };
    // The page's own bookkeeping (`page`) stays here: the worker needs none of it (cloning it was
    // a good part of posting a request).
    const { page, ...sent } = req;
    this.worker.postMessage(sent);
  }

  answer(msg) {
    if (msg.type === 'ready') return;
    if (msg.type === 'test-paused') { happened('refinement paused'); return; }
    const run = this.running;
    if (msg.type === 'fatal') { this.onMessage({ ...msg, last: true }, run ? run.req : null); return; }
    // A request's last frame frees the worker for the queued one.
    if (msg.last) { this.running = null; this.pump(); }
    if (run) this.onMessage(msg, run.req);
  }
}

/** What a worker's answer is, for a check that holds it (www/test-hooks.js). */
const answerKind = (msg) => `answer:${msg.type === 'frame' && msg.preview ? 'preview' : msg.type}`;

/** Workers the page computes frames with: one where the browser reports one core; else two, one
 *  for the `fast` previews (and frames asked at `fast`) and one for the refinements, so that a
 *  preview never waits behind a stale refinement and restarting one never delays the next preview;
 *  a dear refinement's units are split between the two, the preview's worker helping once its
 *  preview is out (issue 26). */
export function poolSize() {
  // `?workers=1` in the address: the pool of one (the frame benchmark compares the two).
  const asked = Number(new URLSearchParams(location.search).get('workers'));
  if (asked === 1 || asked === 2) return asked;
  return (navigator.hardwareConcurrency || 1) > 1 ? 2 : 1;
}

export class Computer {
  /**
   * @param {WebAssembly.Module} module the compiled wasm module (shared with the workers)
   * @param {(answer: object, request: object) => void} onFrame called with the newest request's
   *   answers: its preview (`answer.preview`), if any and if it comes first, then its frame; and
   *   with an older request's preview or frame that is newer than what is on screen
   * @param {(busy: boolean) => void} onBusy called when computing starts and stops
   * @param {(answer: object) => void} onRing called with the ring card asked for by `ring`, when
   *   no newer request was made meanwhile
   * @param {number} workers 1 or 2 (see poolSize)
   */
  constructor(module, onFrame, onBusy, onRing, workers = poolSize()) {
    this.onFrame = onFrame;
    this.onRing = onRing;
    this.onBusy = onBusy;
    this.gen = 0;
    this.answered = 0; // the newest generation whose requested frame was passed on
    this.shown = 0; // the newest generation whose preview or frame was passed on
    // A crashed worker answers its request's frame with the error (a lost preview is no error).
    const crash = (req, error) => {
      if (req.type === 'ring') this.deliver({ type: 'ring', gen: req.gen, ring: { error }, ms: 0, last: true }, req);
      else if (req.frames.some((f) => !f.preview)) this.deliver({ type: 'frame', gen: req.gen, error, ms: 0, calls: 0, last: true }, req);
    };
    this.helper = null; // the lane asked to help with the newest refinement (previewDrawn)
    this.held = null; // {gen, post}: the newest request's refinement, held until its preview is drawn
    this.refinementPosted = null; // {gen, at, by}: when and why the last refinement after a preview was posted
    this.lanes = [];
    for (let k = 0; k < workers; k++) this.lanes.push(new Lane(module, (m, r) => this.deliver(m, r), crash, () => this.connect()));
    this.connect();
    // What the last refinement cost on one worker [ms] (its own compute and its helper's).
    this.lastWork = 0;
    // Refinements stopped at a unit because a newer request came (no restart needed).
    this.stopped = 0;
    // A refinement paused for a check (testPauseRefinement in its view) goes on.
    testHooks.resumeRefinement = () => { for (const lane of this.lanes) lane.worker.postMessage({ type: 'test-resume' }); };
  }

  /** Gives the two workers of the pool a channel of their own (again after a restart): a dear
   *  refinement's units are split between them (rime_core::explorer::share). */
  connect() {
    if (this.lanes.length !== 2) return;
    const { port1, port2 } = new MessageChannel();
    this.lanes[0].worker.postMessage({ type: 'peer', port: port1 }, [port1]);
    this.lanes[1].worker.postMessage({ type: 'peer', port: port2 }, [port2]);
  }

  /** The preview lane and the refinement lane (the same worker in a pool of one). */
  get fastLane() { return this.lanes[0]; }
  get refineLane() { return this.lanes[this.lanes.length - 1]; }

  /** Worker restarts so far (a stale computation dropped). */
  get restarts() { return this.lanes.reduce((n, l) => n + l.restarts, 0); }

  /** Asks for the frame of `scene` (JSON text) seen through `view`; `page` comes back with the
   *  answer. With `previewView`, that view's frame comes first as a preview (`msg.preview`), drawn
   *  until the requested one arrives. `ring` (or null): the ring card's inputs, computed with the
   *  requested frame (and with the preview when it goes on the chart). `latePreview` (or null),
   *  with no `previewView`: the preview asked for if the frame has not come within LATE_MS (in a
   *  pool of two). Returns the generation. */
  request(scene, view, page, previewView = null, ring = null, latePreview = null) {
    const gen = ++this.gen;
    // Every busy worker hears of it at once: a stale refinement or share stops at its next turn
    // (an idle one learns it from its next request).
    for (const lane of this.lanes) if (lane.running || lane === this.helper) lane.worker.postMessage({ type: 'newer', gen });
    this.helper = null;
    this.held = null;
    const req = { type: 'frame', gen, scene, page, ring };
    const final = { view, preview: false };
    if (previewView) {
      const preview = { view: previewView, preview: true };
      if (this.lanes.length === 1) {
        this.fastLane.post({ ...req, frames: [preview, final] });
      } else {
        // A refinement that cost more than a frame's time is split: the preview's worker computes
        // a share of its units after the preview (issue 26).
        const split = this.lastWork > SPLIT_ABOVE_MS;
        this.fastLane.post({ ...req, frames: [preview], help: split ? { view } : null });
        const refine = (by) => {
          this.refinementPosted = { gen, at: performance.now(), by };
          this.refineLane.post({ ...req, frames: [{ ...final, split }] });
        };
        if (HOLD_REFINEMENT) {
          this.held = { gen, post: refine };
          later('timer:cap', () => this.release(gen, 'cap'), HOLD_AT_MOST_MS);
        } else refine('now');
      }
    } else {
      // A frame at `fast` is computed by the fast lane, another by the refinement lane.
      const lane = view.accuracy === 'fast' ? this.fastLane : this.refineLane;
      lane.post({ ...req, frames: [final] });
      const other = this.lanes.find((l) => l !== lane);
      if (latePreview && other) {
        later('timer:late', () => {
          if (this.gen === gen && this.shown < gen) other.post({ ...req, frames: [{ view: latePreview, preview: true }] });
        }, LATE_MS);
      }
    }
    this.onBusy(true);
    return gen;
  }

  /** Asks for the ring card of the newest request's frame, once that frame is on screen (the
   *  refinement lane, so that the next edit's preview never waits behind it): `r` the card's
   *  inputs, `chart` the frame's speed range, `tidal` the tidal card's input or null. Nothing is
   *  asked for an older request (a newer one asks again when its frame is drawn). */
  ring(gen, scene, r, chart, tidal) {
    if (gen !== this.gen) return;
    this.refineLane.post({ type: 'ring', gen, scene, ring: r, chart, tidal });
  }

  /** Posts request `gen`'s held refinement, if it is still held; `by`: what released it (`preview`
   *  on screen, its `error`, the `cap` of HOLD_AT_MOST_MS). */
  release(gen, by) {
    if (this.held && this.held.gen === gen) {
      const { post } = this.held;
      this.held = null;
      post(by);
    }
  }

  /** The preview of request `gen` is on screen: its held refinement is posted, and its worker may
   *  now help with the refinement. */
  previewDrawn(gen) {
    this.release(gen, 'preview');
    if (gen === this.gen && this.lanes.length === 2) {
      this.fastLane.worker.postMessage({ type: 'help', gen });
      // It may be computing its share until the next request (which tells it to stop).
      this.helper = this.fastLane;
    }
  }

  deliver(msg, req) {
    // A refinement stopped because a newer request was made (its worker is free for that one).
    if (msg.stale) { this.stopped++; return; }
    if (msg.type === 'ring') {
      if (msg.gen === this.gen) this.onRing(msg);
      return;
    }
    if (msg.type === 'fatal') {
      this.onFrame({ gen: this.gen, error: msg.message, ms: 0, calls: 0 }, null);
      return;
    }
    if (!req) return;
    if (msg.preview) {
      if (msg.error) this.release(msg.gen, 'error');
      // A preview newer than anything on screen is drawn even when a newer request waits: while a
      // slider is dragged faster than previews come, the screen follows it (a stale frame is only
      // ever a preview; downloads wait for the newest request's frame).
      if (msg.gen > this.shown && !msg.error) {
        this.shown = msg.gen;
        this.onFrame(msg, req);
      }
      return;
    }
    if (!msg.error && msg.work !== undefined && req.frames.some((f) => !f.preview)) this.lastWork = msg.work;
    if (msg.gen !== this.gen) {
      // An older request's frame, newer than what is on screen, is drawn as it comes, as a preview
      // is: while a slider is dragged faster than frames come, the screen follows it (a quick frame
      // has no preview). It is at the requested level, of the scene it shows.
      if (msg.gen > this.shown && !msg.error) {
        this.shown = msg.gen;
        this.onFrame(msg, req);
      }
      return;
    }
    this.answered = msg.gen;
    this.shown = msg.gen;
    this.onFrame(msg, req);
    this.onBusy(false);
  }

  /** Whether the newest request's frame has not been answered yet. */
  get busy() {
    return this.answered !== this.gen;
  }
}

/** The collision card's worker: one integration at a time, the newest request wins (an older
 *  answer is dropped). Its own worker, so that a frame's restart never drops a collision and a
 *  collision never waits behind a frame. */
export class CollisionComputer {
  constructor(module, onAnswer) {
    this.id = 0;
    this.onAnswer = onAnswer;
    this.worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = (ev) => {
      const m = ev.data;
      if (m.type === 'collision' && m.id === this.id) this.onAnswer(m, this.pending);
    };
    this.worker.onerror = (ev) => {
      ev.preventDefault();
      this.onAnswer({ error: `worker: ${ev.message || 'crashed'}` }, this.pending);
    };
    this.worker.postMessage({ type: 'init', module });
  }

  /** Asks for the collision of `scene` (JSON) at `g` with `points` samples at `accuracy`. */
  request(scene, g, points, accuracy, extra) {
    this.pending = { scene, g, points, accuracy, ...extra };
    this.worker.postMessage({ type: 'collision', id: ++this.id, scene, g, points, accuracy });
  }
}
