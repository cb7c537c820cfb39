// The page's side of the chart's painter (issue 26): where the browser can hand a canvas to a
// worker (`transferControlToOffscreen`), the ε_N chart's two layers are drawn in paint-worker.js
// and the page's thread only posts what to draw; elsewhere (or with `?paint=main` in the address,
// which the end-to-end test uses to check the fallback) they are drawn here, as before. Either way
// the hover and readouts read the frame's numbers on this thread.

/** Whether the chart is drawn in a worker on this browser (and not forced onto this thread). */
export function canPaintInWorker() {
  const forced = new URLSearchParams(location.search).get('paint') === 'main';
  return !forced && typeof OffscreenCanvas !== 'undefined' && 'transferControlToOffscreen' in HTMLCanvasElement.prototype
    && typeof Worker !== 'undefined';
}

/** A typed array's own copy (a view into the frame's array would post the whole array), its
 *  buffer listed in `moved` to be handed over with the message without a second copy; anything
 *  else as it is. */
function ownCopy(a, moved) {
  if (!ArrayBuffer.isView(a)) return a;
  const c = a.slice();
  moved.push(c.buffer);
  return c;
}

export class Painter {
  /** Takes over the canvas elements {chart, 'chart-fg', map, 'eps-t'} (the chart's background
   *  and data layers, the stick map, ε_T along a row); `onError` gets a painter's error. */
  constructor(module, elements, onError) {
    this.seq = 0;
    this.done = 0; // the last drawing acknowledged
    this.waiting = []; // [{seq, fn}]
    this.pixelWaits = new Map();
    this.onError = onError;
    const canvases = Object.fromEntries(Object.entries(elements).map(([id, c]) => [id, c.transferControlToOffscreen()]));
    this.worker = new Worker(new URL('./paint-worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = (ev) => this.answer(ev.data);
    this.worker.onerror = (ev) => { ev.preventDefault(); onError(`painter: ${ev.message || 'crashed'}`); };
    this.worker.postMessage({ type: 'init', module, canvases }, Object.values(canvases));
  }

  /** Draws the chart described by `spec` at `w`×`h` CSS px (the background layer too with `back`). */
  chart(spec, w, h, back) {
    const moved = [];
    const own = (a) => ownCopy(a, moved);
    const sent = {
      ...spec,
      series: spec.series.map((s) => ({ ...s, x: own(s.x), y: own(s.y) })),
      bands: (spec.bands || []).map((b) => ({ ...b, x: own(b.x), y: own(b.y) })),
    };
    this.worker.postMessage({ type: 'chart', seq: ++this.seq, spec: sent, w, h, dpr: window.devicePixelRatio || 1, back }, moved);
  }

  /** Draws the stick map and ε_T along its row ({w, h, spec, lines: {w, h, spec}}), or a note in
   *  its place ({w, h, note}). */
  map(map) {
    const moved = [];
    const own = (a) => ownCopy(a, moved);
    const sent = map.spec ? { ...map, spec: { ...map.spec, codes: own(map.spec.codes) }, lines: { ...map.lines, spec: { ...map.lines.spec, x: own(map.lines.spec.x) } } } : map;
    this.worker.postMessage({ type: 'map', seq: ++this.seq, map: sent, dpr: window.devicePixelRatio || 1 }, moved);
  }

  /** Moves the hover cursor of the last chart drawn. */
  hover(hover) {
    this.worker.postMessage({ type: 'hover', seq: ++this.seq, hover });
  }

  /** Calls `fn` once everything posted so far is drawn. */
  after(fn) {
    if (this.done >= this.seq) fn();
    else this.waiting.push({ seq: this.seq, fn });
  }

  /** The pixels of the canvases `ids` (the end-to-end test reads them): [{width, height, data}]. */
  pixels(ids) {
    const seq = ++this.seq;
    return new Promise((resolve) => { this.pixelWaits.set(seq, resolve); this.worker.postMessage({ type: 'pixels', seq, ids }); });
  }

  answer(msg) {
    if (msg.type === 'fatal') { this.onError(msg.message); return; }
    if (msg.error) this.onError(msg.error);
    if (msg.type === 'pixels') {
      const resolve = this.pixelWaits.get(msg.seq);
      this.pixelWaits.delete(msg.seq);
      if (resolve) resolve(msg.layers);
    }
    this.done = Math.max(this.done, msg.seq);
    const due = this.waiting.filter((w) => w.seq <= this.done);
    this.waiting = this.waiting.filter((w) => w.seq > this.done);
    for (const w of due) w.fn();
  }
}
