// When a frame gets a `fast` preview first, and how coarse it is (issue 26): the preview levels,
// the rule that steps between them, and what the last frame of each kind cost in the worker.

/** The preview's curve points and map side (issue 26): every other point and cell of the default
 *  view's (Request::POINTS = 241, Request::MAP_N = 81), so the preview's samples are samples of the
 *  refined frame, and a quarter of the map's cells; every fourth, eighth or sixteenth point while
 *  previews take longer than PREVIEW_SLOW_MS in the worker (the literal layer reading integrates
 *  every point and its family's; other models compared: their points dominate), so that the
 *  preview is on screen within the frame the edit was made in. Input to a worker's start, the
 *  page's handling and the painter take 4–5 ms of that frame on two cores; the literal reading's
 *  preview takes 5.3 ms in the worker at 31 points, 2.7 ms at 16. */
export const PREVIEWS = [{ points: 121, map_n: 41 }, { points: 61, map_n: 21 }, { points: 31, map_n: 11 }, { points: 16, map_n: 11 }];
/** A preview slower than this in the worker makes the next one coarser [ms]; one quicker than
 *  PREVIEW_QUICK_MS finer (half the points take about half the time, so a preview between the two
 *  stays where it is). */
const PREVIEW_SLOW_MS = 5;
const PREVIEW_QUICK_MS = 2;
/** The preview level after a preview of `points` points took `ms` in the worker: after a slow one,
 *  the finest level coarser than now whose time, scaled by its points, is within PREVIEW_SLOW_MS
 *  (the coarsest if none: a slow scene's previews need not step down one edit at a time); after a
 *  quick one, one level finer (`level`: the level now). */
export function nextPreviewLevel(ms, points, level) {
  const at = PREVIEWS.findIndex((p) => p.points === points);
  const now = at < 0 ? level : at;
  if (ms > PREVIEW_SLOW_MS) {
    for (let k = now + 1; k < PREVIEWS.length; k++) if ((ms * PREVIEWS[k].points) / points <= PREVIEW_SLOW_MS) return k;
    return PREVIEWS.length - 1;
  }
  return ms < PREVIEW_QUICK_MS ? Math.max(now - 1, 0) : now;
}

/** A frame gets a preview first only when the last frame of its kind (`frameKind`) took longer
 *  than this in the worker, or is of a kind not seen yet [ms]: a quicker one is on screen as soon
 *  as its preview would be, and the preview would only cost the page's thread a second frame and
 *  put the refined one a display frame later (issue 26). One that is late after all gets its
 *  preview then (Computer.request). */
export const SLOW_MS = 8;
/** What the last frame of each kind cost in the worker [ms]. */
export const frameCost = new Map();

/** A frame's kind, for the cost its next one will likely have: its level, the compared overlays,
 *  the family's sweep, the parameter whose edit asked for it, and the scene with every number
 *  blanked. The edited parameter counts because the literal layer reading's worker keeps the
 *  outcomes an edit of μ leaves unchanged, and not those an edit of E changes. */
export function frameKind(scene, view, edited) {
  return [view.accuracy, view.overlays.join(','), view.sweep || '', view.experiments, edited, scene.replace(/-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?/g, '#')].join('|');
}
