// What the page benchmarks share (scripts/bench-page-frames.mjs, scripts/bench-page-drag.mjs): the
// repository's root, playwright-core from the e2e tests, the scenes' JSON from `rime scene`, and
// www/ (or $RIME_WWW) served on a free local port.
import { spawn, execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const { chromium } = createRequire(path.join(root, 'tests', 'e2e', 'package.json'))('playwright-core');
const rime = process.env.RIME_BIN || path.join(root, 'target', 'release', 'rime');

/** The scene `rime scene ARGS` writes, as one line of JSON. */
export const sceneJson = (args) => JSON.stringify(JSON.parse(execFileSync(rime, ['scene', ...args], { encoding: 'utf8' })));

/** The machine's 1-minute load average and its core count. */
export const load = () => Number(fs.readFileSync('/proc/loadavg', 'utf8').split(' ')[0]);
export const cores = os.availableParallelism ? os.availableParallelism() : os.cpus().length;

/** Serves www/ (or $RIME_WWW) on a free local port; returns its URL and a stop function (also run
 *  when the process exits). */
export async function serveWww() {
  const port = await new Promise((resolve) => {
    const s = net.createServer();
    s.listen(0, '127.0.0.1', () => { const { port: p } = s.address(); s.close(() => resolve(p)); });
  });
  const server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', process.env.RIME_WWW || path.join(root, 'www')], { stdio: 'ignore' });
  const stop = () => server.kill();
  process.on('exit', stop);
  await new Promise((r) => setTimeout(r, 500));
  return { url: `http://127.0.0.1:${port}/`, stop };
}
