// Test hooks of the page, in one place (`window.rimeTest`): how an end-to-end check
// (tests/e2e/*.mjs) or a benchmark sets up a case, and how it controls the order of the page's
// events instead of waiting for time. Inert until a check sets one.
//
// Holding an event. The page passes each event a check may want to order through a named gate
// (`gate`, `later` below). A check holds a name, makes its edits, waits for what it wants to see,
// then releases it:
//
//   await page.evaluate(() => rimeTest.hold('answer:frame'));    // park every requested frame
//   ...edit, then wait for the preview: it is on screen and the refined frame cannot overtake it
//   await page.evaluate(() => rimeTest.release('answer:frame')); // deliver what was parked, in order
//
//   names            what is held
//   answer:preview   a frame worker's preview answer (compute.js Lane; a held answer keeps its
//   answer:frame     worker busy for the page, as a slow computation would; the answers of a
//   answer:ring      worker restarted meanwhile are dropped with it); answer:frame: a requested
//                    frame, refined or stopped as stale
//   timer:restart    compute.js RESTART_AFTER_MS: a worker held up by a stale request restarted
//   timer:cap        compute.js HOLD_AT_MOST_MS: a held refinement posted without its preview
//   timer:late       compute.js LATE_MS: a late frame's preview asked from the other worker
//   timer:describe   dom.js DESCRIBE_AFTER_MS: text alternatives, notes, legend and timing line
//   timer:secondary  app.js SECONDARY_AFTER_MS: the collision and ring cards after the edits pause
//   timer:hash       url.js writeHash: the link written a second after the last edit
//
// A held timer never starts: it is parked at once, and `fire(name)` runs it now (a debounce fired
// at once), `release(name)` runs it and stops holding; a cancelled one (a debounce called again)
// leaves the queue. `parked(name)` counts what waits; `releaseAll()` lets go of every hold (the
// end-to-end test does after each check, so that a failed one leaves nothing held). `events`
// lists what happened that a check may wait for (`restart`: a frame worker restarted;
// `refinement paused`, see `pauseRefinement`).
//
// Other hooks: parts of a frame to fail on purpose (`fail`, see the view's `fail` in
// rime_core::explorer::page); the family's swept parameter (`sweep`, a path of the core's sweeps: the
// frame benchmark's swept family); frames asked without a preview whatever they cost
// (`noPreview`) or always with one (`alwaysPreview`); the next request's preview at the finest
// level (`finestPreview`); a preview's time in the worker counted `previewExtraMs` longer (a test
// clock, no wait: it counts as slow on any machine, and the check reads the time the page read);
// the next refinement paused in its worker after its first unit, where it would look for a newer
// request, until `resumeRefinement()` (`pauseRefinement`, once); a split refinement waiting for its
// peer's share however long the share takes (`waitForShare`: on a busy machine the share may come
// after the refining worker stopped waiting and computed it itself); an input landing just before a
// frame is drawn (`beforeFrame`); and a canvas's pixels wherever it is drawn (`layers`, set by
// app.js).

const held = new Map(); // name -> parked entries [{run}], while the name is held

export const testHooks = {
  fail: [],
  sweep: null,
  noPreview: false,
  alwaysPreview: false,
  finestPreview: false,
  previewExtraMs: 0,
  beforeFrame: null,
  pauseRefinement: false,
  waitForShare: false,
  events: [],
  /** Parks every later event of `name` until `fire` or `release`. */
  hold(name) { if (!held.has(name)) held.set(name, []); },
  /** Runs the parked events of `name` in order and keeps holding it; returns how many ran. */
  fire(name) {
    const q = held.get(name);
    if (!q) return 0;
    const now = q.splice(0);
    for (const e of now) e.run();
    return now.length;
  },
  /** Stops holding `name` and runs what was parked, in order; returns how many ran. */
  release(name) {
    const q = held.get(name) || [];
    held.delete(name);
    for (const e of q) e.run();
    return q.length;
  },
  /** Stops every hold, running what was parked (a check's cleanup). */
  releaseAll() { for (const name of [...held.keys()]) testHooks.release(name); },
  /** How many events of `name` are parked. */
  parked(name) { return (held.get(name) || []).length; },
};
window.rimeTest = testHooks;

/** Runs `fn` now, or parks it while a check holds `name`. */
export function gate(name, fn) {
  const q = held.get(name);
  if (q) q.push({ run: fn });
  else fn();
}

/** `setTimeout(fn, ms)` unless a check holds `name` (then parked at once, see `fire`); returns
 *  `{cancel()}`. */
export function later(name, fn, ms) {
  const q = held.get(name);
  if (q) {
    const e = { run: fn };
    q.push(e);
    return { cancel() { const i = q.indexOf(e); if (i >= 0) q.splice(i, 1); } };
  }
  const t = setTimeout(fn, ms);
  return { cancel() { clearTimeout(t); } };
}

/** Notes that `name` happened (a check may wait for it). */
export function happened(name) {
  testHooks.events.push(name);
  if (testHooks.events.length > 1000) testHooks.events.splice(0, 500);
}

/** A request's `view` with the check's stand-ins: parts to fail, the swept family, the next
 *  refinement paused after its first unit (`pauseRefinement`, once; the worker posts
 *  `test-paused`, noted as the event `refinement paused`, and waits for `resumeRefinement()`, set
 *  by compute.js). */
export function testView(view) {
  if (testHooks.fail.length) view.fail = [...testHooks.fail];
  if (testHooks.sweep) view.sweep = testHooks.sweep;
  if (testHooks.pauseRefinement) { view.testPauseRefinement = true; testHooks.pauseRefinement = false; }
  if (testHooks.waitForShare) view.testWaitShare = true;
  return view;
}

/** A preview's view with the check's stand-in: its time in the worker counted `previewExtraMs` longer. */
export function testPreview(view) {
  delete view.testPauseRefinement;
  delete view.testWaitShare;
  if (testHooks.previewExtraMs > 0) view.testPreviewExtraMs = testHooks.previewExtraMs;
  return view;
}
