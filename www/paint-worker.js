// The page's painter (issue 26): a module worker that draws the ε_N chart's two layers, the stick
// map and ε_T along its row into the OffscreenCanvases the page handed over
// (`transferControlToOffscreen`), so that a frame's redraw costs the page's thread only the posting
// of what to draw. The same painters and layout as on the page's thread (plot.js); the formatters
// are the core's (its own wasm instance).
import { start } from './core.js';
import { CanvasPainter, chartGeometry, drawChartBack, drawChartFront, drawLines, drawMap, drawNote } from './plot.js';

let ready = null;
let canvases = null; // {chart, 'chart-fg', map, 'eps-t'}
let last = null; // the last drawing: {spec, w, h, dpr}

function draw(back) {
  const { spec, w, h, dpr } = last;
  const front = new CanvasPainter(canvases['chart-fg'], w, h, dpr);
  const g = chartGeometry(front, spec);
  if (back) drawChartBack(new CanvasPainter(canvases.chart, w, h, dpr), spec, g);
  drawChartFront(front, spec, g);
}

self.onmessage = async (ev) => {
  const msg = ev.data;
  if (msg.type === 'init') {
    canvases = msg.canvases;
    ready = start(msg.module);
    try { await ready; } catch (e) { self.postMessage({ type: 'fatal', message: `painter: ${e && e.message ? e.message : e}` }); }
    return;
  }
  await ready;
  try {
    if (msg.type === 'chart') {
      last = { spec: msg.spec, w: msg.w, h: msg.h, dpr: msg.dpr };
      draw(msg.back);
    } else if (msg.type === 'hover' && last) {
      last.spec.hover = msg.hover;
      draw(false);
    } else if (msg.type === 'map') {
      const { map, dpr } = msg;
      const p = new CanvasPainter(canvases.map, map.w, map.h, dpr);
      if (map.note) drawNote(p, map.note);
      else {
        drawMap(p, map.spec);
        drawLines(new CanvasPainter(canvases['eps-t'], map.lines.w, map.lines.h, dpr), map.lines.spec);
      }
    } else if (msg.type === 'pixels') {
      // Test hook: the canvases' pixels (the page cannot read a canvas it handed over).
      const layers = msg.ids.map((id) => canvases[id]).map((c) => {
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height);
        return { width: c.width, height: c.height, data: d.data };
      });
      self.postMessage({ type: 'pixels', seq: msg.seq, layers });
      return;
    }
    self.postMessage({ type: 'painted', seq: msg.seq });
  } catch (e) {
    self.postMessage({ type: 'painted', seq: msg.seq, error: `painter: ${e && e.message ? e.message : e}` });
  }
};
