// The page's side of the worker: posts requests, drops stale answers by generation, and restarts
// the worker when a newer request waits behind a slow one (a computation cannot be interrupted).

/** How long a running request may hold up a newer one before the worker is restarted [ms]. */
const RESTART_AFTER_MS = 150;

export class Computer {
  /**
   * @param {WebAssembly.Module} module the compiled wasm module (shared with the worker)
   * @param {(answer: object, request: object) => void} onFrame called with the newest request's answer
   * @param {(busy: boolean) => void} onBusy called when computing starts and stops
   */
  constructor(module, onFrame, onBusy) {
    this.module = module;
    this.onFrame = onFrame;
    this.onBusy = onBusy;
    this.gen = 0;
    this.running = null; // {req, since}
    this.queued = null;
    this.restarts = 0;
    this.spawn();
  }

  spawn() {
    this.worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = (ev) => this.answer(ev.data);
    this.worker.onerror = (ev) => {
      ev.preventDefault();
      const req = this.running && this.running.req;
      this.running = null;
      if (req) this.onFrame({ gen: req.gen, error: `worker: ${ev.message || 'crashed'}`, ms: 0, calls: 0 }, req);
      this.restart();
    };
    this.worker.postMessage({ type: 'init', module: this.module });
  }

  restart() {
    this.worker.terminate();
    this.restarts++;
    this.spawn();
    this.pump();
  }

  /** Asks for the frame of `scene` (JSON text) seen through `view`; `page` comes back with the
   *  answer; with `preview`, a `fast` preview comes first (`msg.preview`). Returns the request's
   *  generation. */
  request(scene, view, page, preview = false) {
    const req = { type: 'frame', gen: ++this.gen, scene, view, page, preview };
    this.queued = req;
    const run = this.running;
    if (!run) {
      this.pump();
    } else {
      // The running request is stale: if it is slow, drop it with its worker.
      const wait = Math.max(0, RESTART_AFTER_MS - (performance.now() - run.since));
      setTimeout(() => {
        if (this.running === run && this.queued) {
          this.running = null;
          this.restart();
        }
      }, wait);
    }
    return req.gen;
  }

  pump() {
    if (this.running || !this.queued) return;
    const req = this.queued;
    this.queued = null;
    this.running = { req, since: performance.now() };
    this.worker.postMessage(req);
    this.onBusy(true);
  }

  answer(msg) {
    if (msg.type === 'ready') return;
    if (msg.type === 'fatal') {
      this.onFrame({ gen: this.gen, error: msg.message, ms: 0, calls: 0 }, null);
      return;
    }
    const run = this.running;
    if (msg.preview) {
      // The request's fast preview; the worker goes on to the requested level (a newer request
      // still restarts it after RESTART_AFTER_MS).
      if (run && msg.gen === this.gen) this.onFrame(msg, run.req);
      return;
    }
    this.running = null;
    if (run && msg.gen === this.gen) this.onFrame(msg, run.req);
    // else: a stale answer (a newer request exists), dropped.
    if (this.queued) this.pump();
    else this.onBusy(false);
  }

  /** Whether the newest request has not been answered yet. */
  get busy() {
    return this.running !== null || this.queued !== null;
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
