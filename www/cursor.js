// The chart's hover cursor and the map's chosen row kept on their speeds from frame to frame.
import { app } from './state.js';

/** Keeps the hover cursor and the map's chosen row on the same speeds when the next frame has
 *  another number of samples (a preview has every other, fourth or eighth one). Each keeps the
 *  speed it was put on (by the user, or kept from the frame before): mapped through a preview's
 *  coarser samples and back, it comes back to the very sample it was on (an index mapped to the
 *  nearest sample and back drifted by a sample or more with every edit). */
const anchors = { chart: null, map: null, row: null }; // {at: index set for the frame, pos: speed or fraction}
export function keepCursor(old, res) {
  if (!old) return;
  // The anchor: where the frame before put it, unless the user has moved it since.
  const anchor = (key, at, pos) => (anchors[key] && anchors[key].at === at ? anchors[key].pos : pos());
  const i = app.hover.chart;
  if (i !== null && i < old.g.length) {
    const g = anchor('chart', i, () => old.g[i]);
    let best = 0;
    for (let k = 1; k < res.g.length; k++) if (Math.abs(Math.log(res.g[k] / g)) < Math.abs(Math.log(res.g[best] / g))) best = k;
    app.hover.chart = best;
    anchors.chart = { at: best, pos: g };
  } else anchors.chart = null;
  if (old.map && res.map) {
    const frac = (k) => k / (old.map.n - 1);
    const to = (f) => Math.round(f * (res.map.n - 1));
    const h = app.hover.map;
    if (h) {
      const at = `${h.i},${h.j}`;
      const f = anchor('map', at, () => [frac(h.i), frac(h.j)]);
      app.hover.map = { i: to(f[0]), j: to(f[1]) };
      anchors.map = { at: `${app.hover.map.i},${app.hover.map.j}`, pos: f };
    } else anchors.map = null;
    if (app.mapRow !== null) {
      const f = anchor('row', app.mapRow, () => frac(app.mapRow));
      app.mapRow = to(f);
      anchors.row = { at: app.mapRow, pos: f };
    } else anchors.row = null;
  }
}
