// The page's input → frame matrix (issue 26), in headless Chromium; outside `make test` (it takes
// minutes). For each profile (desktop 1280×800; phone 375×812 at 4× CPU slowdown) × scene × level it
// opens the page on that scene and view, moves a slider (an `input` event; each step to a value not
// seen before, so no worker's memo of literal outcomes is warm by coming back) `RUNS` times and times,
// inside the page, input → the preview painted (first) and input → the requested level painted
// (final): the first animation frame after the page drew each, and counts the main thread's long
// tasks over 50 ms meanwhile. Then `RUNS` steps with the input dispatched in an animation frame (as
// Chromium dispatches a dragged pointer's events): in which display frame after the input's the
// first frame is shown (`first_frames_each`, their median `first_frames`, `first_next_frame` the
// steps that showed it in the next one, `first_aligned_ms`). Then `RUNS` more steps under a
// Chromium trace (kept apart: its own cost lengthened the latencies) give the main thread's busy
// time per frame drawn (Chromium's
// TaskDuration metric over the edits, divided by the previews and refined frames drawn: input
// handling, drawing, style, layout and paint of the page's thread; `main_cpu_ms_per_frame` the
// same as thread time from a trace, less inflated by a loaded machine; split by what started it into
// `main_cpu_frame_ms_per_frame`, the frames' own handling, and `main_cpu_input_ms_per_edit`, the
// input's). Writes target/bench/frames-page.json (or the file of `--out`): one record per case in
// the shape of `rime bench --frames` (`surface: "page"`), plus `profile`, `long_tasks`,
// `max_task_ms`, `main_ms_per_frame`, the thread times above and `paint` (where the chart is drawn:
// `worker` or `main`).
//
// Usage: scripts/build-www.sh && scripts/setup-npm.sh && node scripts/bench-page-frames.mjs
//   [--quick] [--profile desktop|phone] [--paint main] [--workers 1|2] [--out FILE] [--runs N]
//   [--scene TEXT] [--level LEVEL]
// (serves www/ itself on a free local port; needs target/release/rime for the scenes' JSON).
// `--paint main` forces the page's fallback (the chart drawn on the page's thread, as where a
// browser has no OffscreenCanvas); `--workers 1` a pool of one frame worker (as on a one-core
// browser), to compare with the pool of two.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium, cores, load, root, sceneJson, serveWww } from './bench-page-common.mjs';

const argv = process.argv.slice(2);
const opt = (name) => { const k = argv.indexOf(name); return k >= 0 ? argv[k + 1] : undefined; };
const quick = argv.includes('--quick');
const RUNS = Number(opt('--runs') || (quick ? 3 : 15));
const paintMain = opt('--paint') === 'main';
const workers = opt('--workers');
const onlyProfile = opt('--profile');
const outFile = opt('--out') || path.join(root, 'target', 'bench', 'frames-page.json');
// Hang guard per wait (the slowest frame, the literal reading at precise on the phone profile, takes
// about 1 s): never a speed check.
const GUARD_MS = 120000;

const SCENES = [
  { name: 'ice', scene: sceneJson(['--preset', 'ice']), overlays: [] },
  { name: 'ice-frost', scene: sceneJson(['--preset', 'ice-frost']), overlays: [] },
  { name: 'ice-frost, layer.reading=literal', scene: sceneJson(['--preset', 'ice-frost', '--set', 'layer.reading=literal']), overlays: [] },
  { name: 'ice-sticky', scene: sceneJson(['--preset', 'ice-sticky']), overlays: [] },
  { name: 'ice, compare other models', scene: sceneJson(['--preset', 'ice']), overlays: ['model:brilliantov2007', 'model:muller_poschel2011'] },
  { name: 'ice, compare measured ice', scene: sceneJson(['--preset', 'ice']), overlays: ['atlas:bridges1984', 'atlas:hatzes1988_frost', 'atlas:supulver1995', 'atlas:heisselmann2010', 'atlas:hill2015'] },
  // As `rime bench --frames`: a family swept over the grain radius (the page's family follows the
  // core's default sweep; the bench picks this one through a test hook) and the paper's viscosities.
  { name: 'ice-frost, family over R₁=R₂', scene: sceneJson(['--preset', 'ice-frost']), overlays: [], sweep: 'grains.radius' },
  { name: "ice, the paper's viscosities", scene: sceneJson(['--preset', 'ice-paper-viscosities']), overlays: [] },
];
// `--scene TEXT` keeps the scenes whose name contains TEXT, `--level` one level (for A/B runs of one case).
const onlyScene = opt('--scene');
if (onlyScene) SCENES.splice(0, SCENES.length, ...SCENES.filter((s) => s.name.includes(onlyScene)));
const LEVELS = ['fast', 'precise', 'integrated'].filter((l) => !opt('--level') || l === opt('--level'));
const PROFILES = [
  { name: 'desktop', viewport: { width: 1280, height: 800 }, slowdown: 1 },
  { name: 'phone', viewport: { width: 375, height: 812 }, slowdown: 4, mobile: true },
].filter((p) => (onlyProfile ? p.name === onlyProfile : !quick || p.name === 'desktop'));

const { url, stop: stopServer } = await serveWww();

const median = (a) => {
  const s = [...a].sort((x, y) => x - y);
  const m = s.length >> 1;
  return s.length ? (s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2) : null;
};

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'rime-bench-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-dev-shm-usage'],
});
const records = [];
for (const profile of PROFILES) {
  for (const sc of SCENES) {
    for (const level of LEVELS) {
      // A fresh page per case: nothing of the previous case (its worker, its state) carries over.
      const page = await context.newPage();
      await page.setViewportSize(profile.viewport);
      const cdp = await context.newCDPSession(page);
      if (profile.slowdown > 1) await cdp.send('Emulation.setCPUThrottlingRate', { rate: profile.slowdown });
      await cdp.send('Performance.enable');
      const view = { accuracy: level, overlays: sc.overlays };
      const query = [paintMain ? 'paint=main' : '', workers ? `workers=${workers}` : ''].filter(Boolean).join('&');
      await page.goto(`${url}${query ? `?${query}` : ''}#s=${encodeURIComponent(sc.scene)}&v=${encodeURIComponent(JSON.stringify(view))}`);
      await page.waitForFunction(() => window.rimeState && window.rimeState.ready, null, { timeout: GUARD_MS });
      if (sc.sweep) {
        // The swept family: asked for by every edit from here on (the first one included).
        await page.evaluate((sweep) => { window.rimeTest.sweep = sweep; }, sc.sweep);
      }
      const loadAvg = load();
      const taskSeconds = async () => (await cdp.send('Performance.getMetrics')).metrics.find((m) => m.name === 'TaskDuration').value;
      // One slider step, timed inside the page: input → the animation frame after each draw. With
      // `aligned`, the input is dispatched in an animation frame's callback, as Chromium dispatches
      // a dragged pointer's events (rAF-aligned input), and `frames` counts the display frames from
      // that one to the one after the first frame is drawn (1: the next display frame).
      const step = (aligned = false) => page.evaluate(({ guard, step, aligned }) => new Promise((resolve, reject) => {
        const s = window.rimeState;
        const p0 = s.previews || 0;
        const slider = document.querySelector('input[type=range][data-path="bulk.youngs_modulus"]')
          || document.querySelector('input[type=range]');
        const tasks = [];
        const obs = new PerformanceObserver((l) => { for (const e of l.getEntries()) tasks.push(e.duration); });
        obs.observe({ type: 'longtask' });
        let first = null;
        let t0 = performance.now();
        let frame0 = null; // the input's animation frame time (aligned)
        let frames = null;
        // No polling loop (it would cost the page's thread a task every frame, counted in its busy
        // time): the page fires `rime:drawn` on window for each preview and frame once it is on
        // its canvas, and the animation frame after that is when it is painted.
        const done = (fn) => { obs.disconnect(); window.removeEventListener('rime:drawn', onDrawn); clearTimeout(timer); fn(); };
        const timer = setTimeout(() => done(() => reject(new Error('no frame within the guard'))), guard);
        let asked = null; // this step's request (it leaves in a microtask after the input)
        // The first frame is painted in the animation frame at `ts` (once; `first` is -1 until then).
        const firstPainted = (ts) => {
          if (first !== -1) return;
          first = performance.now() - t0;
          if (frame0 !== null) frames = Math.round((ts - frame0) / (1000 / 60));
        };
        const onDrawn = (ev) => {
          if (first === null) {
            first = -1;
            requestAnimationFrame(firstPainted);
          }
          if (!ev.detail.preview && ev.detail.gen === asked) {
            requestAnimationFrame((ts) => {
              firstPainted(ts);
              const final = performance.now() - t0;
              // Let the observer deliver the tasks of this edit before reporting.
              const drawnFirst = ((s.previews || 0) > p0 ? Math.min(s.previewDrawnAt, s.drawnAt) : s.drawnAt) - t0;
              setTimeout(() => done(() => resolve({ first, final, drawnFirst, drawnFinal: s.drawnAt - t0, tasks, previews: (s.previews || 0) - p0, frames })), 0);
            });
          }
        };
        window.addEventListener('rime:drawn', onDrawn);
        const input = () => {
          slider.value = String(Number(slider.value) + step);
          slider.dispatchEvent(new Event('input', { bubbles: true }));
          queueMicrotask(() => { asked = s.asked; });
        };
        if (aligned) {
          requestAnimationFrame((ts) => { frame0 = ts; t0 = performance.now(); input(); });
        } else input();
      }), { guard: GUARD_MS, step: 7, aligned });
      // The latencies: RUNS steps with no trace running (a trace's own cost, which grows with the
      // workers' tasks, once put up to 5 ms on the literal reading's first frames).
      const runs = [];
      for (let i = 0; i < RUNS; i++) runs.push(await step());
      // The same steps with the input in an animation frame (as a dragged pointer's): in which
      // display frame after the input's the first frame is shown.
      const alignedRuns = [];
      for (let i = 0; i < RUNS; i++) alignedRuns.push(await step(true));
      // The main thread's time: RUNS more steps, traced. Its own time in its tasks (thread time,
      // which a loaded machine inflates far less than the wall time of TaskDuration): Chromium's
      // top-level task events.
      const busy0 = await taskSeconds();
      const traced = [];
      const onData = (d) => traced.push(...d.value);
      cdp.on('Tracing.dataCollected', onData);
      await cdp.send('Tracing.start', { categories: 'toplevel', transferMode: 'ReportEvents' });
      const traceRuns = [];
      for (let i = 0; i < RUNS; i++) traceRuns.push(await step());
      const busyMs = (await taskSeconds() - busy0) * 1e3;
      const traceDone = new Promise((r) => cdp.once('Tracing.tracingComplete', r));
      await cdp.send('Tracing.end');
      await traceDone;
      cdp.off('Tracing.dataCollected', onData);
      const mains = new Set(traced.filter((e) => e.name === 'thread_name' && e.args && e.args.name === 'CrRendererMain').map((e) => `${e.pid}:${e.tid}`));
      const cpuBy = new Map();
      for (const e of traced) {
        const k = `${e.pid}:${e.tid}`;
        if (e.ph === 'X' && mains.has(k) && /RunTask$/.test(e.name)) cpuBy.set(k, (cpuBy.get(k) || 0) + (e.tdur || 0) / 1e3);
      }
      // The page's renderer: the busiest main thread (a closed page's renderer is idle).
      const cpuMs = Math.max(0, ...cpuBy.values());
      const framesDrawn = traceRuns.reduce((n, r) => n + r.previews + 1, 0);
      // The same thread time split by what started it (the task's origin in the trace): the edit
      // (the benchmark's call into the page, which dispatches the input event: the input's handling
      // and the request to the workers, with the call's own cost) and the frames (the workers' and
      // the painter's messages and their timers); each rendering update (style, layout, paint)
      // counts with the task before it, whose changes it draws.
      const main = [...cpuBy.entries()].sort((a, b) => b[1] - a[1])[0];
      let inputMs = 0;
      let frameMs = 0;
      let lastKind = 'frame';
      if (main) {
        const tasksOf = traced.filter((e) => e.ph === 'X' && `${e.pid}:${e.tid}` === main[0] && /RunTask$/.test(e.name)).sort((a, b) => a.ts - b.ts);
        for (const e of tasksOf) {
          const src = (e.args && e.args.src_func) || '';
          const ms = (e.tdur || 0) / 1e3;
          if (src === 'ScheduledActionSendBeginMainFrame') {
            if (lastKind === 'input') inputMs += ms; else frameMs += ms;
          } else if (src === 'Accept') {
            inputMs += ms;
            lastKind = 'input';
          } else {
            frameMs += ms;
            if (ms > 0.05) lastKind = 'frame';
          }
        }
      }
      const paint = await page.evaluate(() => window.rimeState.paint || 'main');
      const tasks = [...runs, ...alignedRuns, ...traceRuns].flatMap((r) => r.tasks);
      const rec = {
        surface: 'page', scene: sc.name, level, size: `${profile.viewport.width}x${profile.viewport.height}`,
        profile: profile.name, cpu_slowdown: profile.slowdown,
        first_ms: median(runs.map((r) => r.first)), final_ms: median(runs.map((r) => r.final)),
        // Input → on its canvas (before the animation frame that paints it).
        first_drawn_ms: median(runs.map((r) => r.drawnFirst)), final_drawn_ms: median(runs.map((r) => r.drawnFinal)),
        first_each_ms: runs.map((r) => r.first), final_each_ms: runs.map((r) => r.final), previews: runs.map((r) => r.previews),
        // Input in an animation frame: the display frames to the first frame shown (each step,
        // their median, and how many steps showed it in the next one) and input → first [ms].
        first_frames_each: alignedRuns.map((r) => r.frames), first_frames: median(alignedRuns.map((r) => r.frames)),
        first_next_frame: alignedRuns.filter((r) => r.frames === 1).length, first_aligned_ms: median(alignedRuns.map((r) => r.first)),
        long_tasks: tasks.filter((d) => d > 50).length, max_task_ms: tasks.length ? Math.max(...tasks) : 0,
        main_ms_per_frame: busyMs / framesDrawn, main_cpu_ms_per_frame: cpuMs / framesDrawn,
        main_cpu_frame_ms_per_frame: frameMs / framesDrawn, main_cpu_input_ms_per_edit: inputMs / RUNS, paint,
        workers: await page.evaluate(() => window.rimeState.workers || 1),
        runs: RUNS, cores, load: loadAvg,
      };
      records.push(rec);
      console.log(`${profile.name.padEnd(8)} ${sc.name.padEnd(34)} ${level.padEnd(10)} first ${rec.first_ms.toFixed(1).padStart(7)} ms (drawn ${rec.first_drawn_ms.toFixed(1).padStart(6)}; next frame ${rec.first_next_frame}/${RUNS})  final ${rec.final_ms.toFixed(1).padStart(7)} ms  main ${rec.main_ms_per_frame.toFixed(1).padStart(5)} ms/frame (cpu ${rec.main_cpu_ms_per_frame.toFixed(1).padStart(5)}: frames ${rec.main_cpu_frame_ms_per_frame.toFixed(1)}/frame, input ${rec.main_cpu_input_ms_per_edit.toFixed(1)}/edit)  long tasks ${rec.long_tasks} (max ${rec.max_task_ms.toFixed(0)} ms)`);
      await page.close();
    }
  }
}
await context.close();
fs.mkdirSync(path.dirname(outFile), { recursive: true });
fs.writeFileSync(outFile, JSON.stringify(records, null, 2) + '\n');
console.log(`${cores} cores, load average ${load().toFixed(2)} at the end; wrote ${path.relative(root, outFile)}`);
stopServer();
