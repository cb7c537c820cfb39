// A dragged slider on the page (issue 26), outside `make test`: an `input` event every 50 ms for
// 1 s (20 of them, on Young's modulus) on scenes whose refinement is slow, with one frame worker
// (`?workers=1`, as on a one-core browser) and with the pool of two. Reports the previews and frames
// drawn during the drag, input → the next preview drawn (median, max), the last input → the
// refined frame and the main thread's long tasks over 50 ms; writes target/bench/drag-page.json.
// It is what decided the pool (README).
//
// Usage: scripts/build-www.sh && scripts/setup-npm.sh && node scripts/bench-page-drag.mjs
// (serves www/ itself on a free local port; needs target/release/rime for the scenes' JSON).
import fs from 'node:fs';
import path from 'node:path';
import { chromium, cores, load, root, sceneJson, serveWww } from './bench-page-common.mjs';

// Hang guard for the whole drag and its last frame (the slowest, about 1 s): never a speed check.
const GUARD_MS = 120000;
const CASES = [
  { name: 'ice-frost, layer.reading=literal', scene: sceneJson(['--preset', 'ice-frost', '--set', 'layer.reading=literal']), level: 'precise' },
  { name: 'ice-sticky', scene: sceneJson(['--preset', 'ice-sticky']), level: 'integrated' },
  { name: "ice, the paper's viscosities", scene: sceneJson(['--preset', 'ice-paper-viscosities']), level: 'integrated' },
];

const { url, stop: stopServer } = await serveWww();
const median = (a) => { const s = [...a].sort((x, y) => x - y); return s.length ? s[s.length >> 1] : null; };

const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const records = [];
for (const c of CASES) {
  for (const workers of [1, 2]) {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`${url}?workers=${workers}#s=${encodeURIComponent(c.scene)}&v=${encodeURIComponent(JSON.stringify({ accuracy: c.level }))}`);
    await page.waitForFunction(() => window.rimeState && window.rimeState.ready, null, { timeout: GUARD_MS });
    const loadAvg = load();
    const r = await page.evaluate((guard) => new Promise((resolve, reject) => {
      const s = window.rimeState;
      const slider = document.querySelector('input[type=range][data-path="bulk.youngs_modulus"]');
      const [p0, u0] = [s.previews || 0, s.updates];
      const latency = []; // input → the next preview drawn, for the inputs that waited for one
      let waiting = null;
      let k = 0;
      // The main thread's long tasks (over 50 ms) during the drag and its last frame.
      const tasks = [];
      const lt = new PerformanceObserver((l) => { for (const e of l.getEntries()) tasks.push(e.duration); });
      lt.observe({ type: 'longtask' });
      // The page fires `rime:drawn` for each preview and frame on its canvas.
      const onDrawn = (ev) => {
        if (waiting !== null && ev.detail.preview) { latency.push(performance.now() - waiting.t); waiting = null; }
        if (last && last.gen !== null && !ev.detail.preview && ev.detail.gen === last.gen) {
          window.removeEventListener('rime:drawn', onDrawn);
          lt.disconnect();
          clearTimeout(timer);
          resolve({ previews: (s.previews || 0) - p0, frames: last.u - u0, latency, last: s.drawnAt - last.t, tasks });
        }
      };
      window.addEventListener('rime:drawn', onDrawn);
      const timer = setTimeout(() => { window.removeEventListener('rime:drawn', onDrawn); reject(new Error('no frame within the guard')); }, guard);
      // The last input's time, the frames drawn before it and its request: its own frame ends the
      // run (older requests' frames may be drawn after it, and it may come before the drag's last
      // 50 ms are over).
      let last = null;
      const step = () => {
        if (k === 20) return;
        if (waiting === null) waiting = { t: performance.now(), previews: s.previews || 0 };
        slider.value = String(Number(slider.value) + (k % 2 ? -3 : 4));
        k++;
        if (k === 20) last = { t: performance.now(), u: s.updates, gen: null };
        slider.dispatchEvent(new Event('input', { bubbles: true }));
        if (k === 20) queueMicrotask(() => { last.gen = s.asked; });
        setTimeout(step, 50);
      };
      step();
    }), GUARD_MS);
    const rec = {
      surface: 'page', scene: c.name, level: c.level, workers, inputs: 20, interval_ms: 50,
      previews: r.previews, frames: r.frames, preview_ms_median: median(r.latency),
      preview_ms_max: r.latency.length ? Math.max(...r.latency) : null, last_final_ms: r.last,
      long_tasks: r.tasks.length, max_task_ms: r.tasks.length ? Math.max(...r.tasks) : 0, cores, load: loadAvg,
    };
    records.push(rec);
    console.log(`${c.name.padEnd(34)} ${c.level.padEnd(10)} ${workers} worker(s): ${rec.previews} previews, ${rec.frames} frame(s) in the drag; input → preview median ${rec.preview_ms_median.toFixed(0)} ms (max ${rec.preview_ms_max.toFixed(0)}); last input → frame ${rec.last_final_ms.toFixed(0)} ms; long tasks ${rec.long_tasks}`);
    await page.close();
  }
}
await browser.close();
const out = path.join(root, 'target', 'bench', 'drag-page.json');
fs.mkdirSync(path.dirname(out), { recursive: true });
fs.writeFileSync(out, JSON.stringify(records, null, 2) + '\n');
console.log(`${cores} cores, load average ${load().toFixed(2)} at the end; wrote target/bench/drag-page.json`);
stopServer();
