// End-to-end check of the page's ring card (issue 24) in headless Chromium: the card prints what
// `rime ring` computes (every printed number reads back as the CLI's value at its printed digits, by
// the core's agreesToPrinted), says the verdict in the CLI's words, names a bad field, and draws the
// ε_cr line, the meeting point and the impact-speed marker on the ε_N chart when asked; its inputs
// are in the link (a reloaded link shows the same card; a bad field is named).
// Usage: node tests/e2e/ring.mjs http://127.0.0.1:PORT/  (RIME_BIN: the rime binary)
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const url = process.argv[2];
if (!url) {
  console.error('usage: node ring.mjs URL');
  process.exit(2);
}
const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const rime = process.env.RIME_BIN || path.join(root, 'target', 'release', 'rime');
// A hang guard, never a speed check (a frame takes well under 1 s on an idle machine).
const GUARD_MS = 60000;
const OMEGA = 1.3143527e-4;

let failures = 0;
async function check(name, fn) {
  try {
    const detail = await fn();
    console.log(`PASS ${name}${detail ? ` — ${detail}` : ''}`);
  } catch (e) {
    failures++;
    console.log(`FAIL ${name} — ${String(e && e.stack ? e.stack.split('\n').slice(0, 3).join(' | ') : e)}`);
  }
}
function assert(cond, msg) {
  if (!cond) throw new Error(msg);
}

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'rime-ring-e2e-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-dev-shm-usage'],
  viewport: { width: 1280, height: 1000 },
});
const problems = [];
const page = await context.newPage();
page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
page.on('pageerror', (e) => problems.push(e.message));
const updates = () => page.evaluate(() => window.rimeState.updates);
// A frame drawn and its ring card in (issue 26: the card is computed once the frame is on screen).
const waitUpdate = (before) => page.waitForFunction((b) => window.rimeState.updates > b && window.rimeState.gen === window.rimeState.asked && window.rimeState.ringOf === window.rimeState.gen, before, { timeout: GUARD_MS });

/** Types τ into the ring card and presses Enter (a refused value draws no frame: no wait here). */
async function enterTau(value) {
  const tau = page.locator('#r-tau');
  await tau.fill(value);
  await tau.press('Enter');
}

/** The page's ring card against `rime ring` for the drawn scene (printed digits, by the core). */
async function agreeWithCli(args) {
  const s = await page.evaluate(() => window.rimeState);
  assert(s.ring, 'no ring card on the page');
  const sceneFile = path.join(os.tmpdir(), `rime-ring-e2e-${process.pid}.json`);
  fs.writeFileSync(sceneFile, s.sceneJson);
  const cli = JSON.parse(execFileSync(rime, ['ring', '--scene', sceneFile, ...args, '--format', 'json'], { encoding: 'utf8' }));
  fs.rmSync(sceneFile);
  assert(s.ring.verdict === cli.verdict_words, `verdict: page "${s.ring.verdict}", rime ring "${cli.verdict_words}"`);
  assert(s.ring.equilibrium === cli.equilibrium, 'equilibrium flag differs');
  const rows = [
    ['velocity dispersion c', 'm/s', 'velocity_dispersion'],
    ['thickness H (rms z)', 'm', 'thickness'],
    ['mean impact speed √π c', 'm/s', 'mean_impact_speed'],
    ['ε_cr at the balance', '1', 'eps_cr'],
    ['ε̄ of the impacts', '1', 'eps_effective'],
  ];
  // The printed rows as the user reads them (the table's cells). A printed "34.16 mm" is compared
  // as 34.16 against the CLI's value in mm (the core's agreesToPrinted): converting the printed
  // text to metres first would add float noise to its digits.
  const lines = [];
  for (const [label, unit, key] of rows) {
    const r = await page.evaluate(async ([lab, u, computed]) => {
      const core = await import(new URL('core.js', location.href).href);
      const tr = [...document.querySelectorAll('#ring tr')].find((x) => x.querySelector('th') && x.querySelector('th').textContent === lab);
      if (!tr) return { missing: true };
      const text = tr.querySelector('td').textContent;
      const [number, shownUnit] = text.split(' (')[0].split(' ');
      const scale = u === '1' ? 1 : core.parseQuantity('printed', `1 ${shownUnit}`, u);
      return { text, ok: core.agrees(computed / scale, Number(number)) };
    }, [label, unit, cli[key]]);
    assert(!r.missing, `row "${label}" missing`);
    assert(r.ok, `${label}: page "${r.text}" vs rime ring ${cli[key]}`);
    lines.push(`${key} ${r.text}`);
  }
  return `${cli.verdict_words}; ${lines.join(', ')}`;
}

try {
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ringOf === window.rimeState.gen, null, { timeout: GUARD_MS });

  await check('issue 24: the opening scene (ice-sticky) at the A ring: the card agrees with `rime ring`', async () =>
    agreeWithCli(['--tau', '0.5', '--omega', String(OMEGA)]));

  await check('issue 24: ice with 2 cm grains prints an equilibrium (at the floor), as `rime ring` does', async () => {
    const u = await updates();
    await page.selectOption('#preset', 'ice');
    await waitUpdate(u);
    const s = await page.evaluate(() => window.rimeState);
    const scene = JSON.parse(s.sceneJson);
    assert(scene.grains.radius_1 === 0.02 && scene.grains.radius_2 === 0.02, `ice preset radii ${scene.grains.radius_1}, ${scene.grains.radius_2}`);
    assert(s.ring.equilibrium === true, `verdict ${s.ring.verdict}`);
    // Read as shown: scrolled to, as a user would (an off-screen card skips its rendering, and
    // its innerText with it, until it is scrolled into view).
    await page.locator('.ring-card').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => document.getElementById('ring').innerText.length > 0, null, { timeout: GUARD_MS });
    const text = await page.locator('#ring').innerText();
    assert(/equilibrium at the monolayer floor/.test(text), `card: ${text}`);
    return agreeWithCli(['--tau', '0.5', '--omega', String(OMEGA)]);
  });

  await check('issue 24: a typed τ applies; a bad τ is named and the card keeps the last good one', async () => {
    const u = await updates();
    await enterTau('0.1');
    await waitUpdate(u);
    const r1 = await agreeWithCli(['--tau', '0.1', '--omega', String(OMEGA)]);
    await enterTau('-1');
    await page.waitForFunction(() => /ring\.tau/.test(document.getElementById('r-tau-err').textContent), null, { timeout: GUARD_MS });
    const kept = await page.evaluate(() => window.rimeState.ring);
    assert(kept && kept.record.tau === 0.1, `the card did not keep τ = 0.1: ${JSON.stringify(kept && kept.record.tau)}`);
    await enterTau('0.5');
    await page.waitForFunction(() => window.rimeState.ring && window.rimeState.ring.record.tau === 0.5, null, { timeout: GUARD_MS });
    return r1;
  });

  await check('issue 24: on the ε_N chart, the ε_cr line (dashed), the meeting point and the mean impact speed', async () => {
    const u = await updates();
    await page.locator('#r-onChart').check();
    await waitUpdate(u);
    const s = await page.evaluate(() => window.rimeState);
    const line = s.figure.series.find((n) => /^ε_cr of the ring/.test(n));
    assert(line, `no ε_cr series in ${JSON.stringify(s.figure.series)}`);
    assert(s.figure.series.some((n) => /meets the ring's ε_cr/.test(n)) === Boolean(s.ring.meeting), 'meeting point and series disagree');
    const marker = s.figure.markers.find((m) => /^ring: mean impact speed/.test(m));
    const v = s.ring.record.rough.mean_impact_speed;
    const inRange = v > s.figure.x.min && v < s.figure.x.max;
    assert(Boolean(marker) === inRange, `impact-speed marker ${marker} (speed ${v}, chart ${s.figure.x.min}–${s.figure.x.max})`);
    return `${line}; ${marker || 'marker off the chart'}`;
  });

  await check("issue 24: Ω from the tidal card's planet and distance, as `rime ring --planet-mass --distance`", async () => {
    const u = await updates();
    await page.locator('#r-planet').check();
    await waitUpdate(u);
    const s = await page.evaluate(() => window.rimeState);
    const t = s.tidal.input;
    const r = await agreeWithCli(['--tau', '0.5', '--planet-mass', String(t.planet_mass), '--distance', String(t.distance)]);
    const omega = Math.sqrt(6.672e-11 * t.planet_mass / t.distance ** 3);
    assert(Math.abs(s.ring.record.omega - omega) <= 1e-15 * omega, `Ω ${s.ring.record.omega} vs √(GM/d³) ${omega}`);
    await page.locator('#ring').scrollIntoViewIfNeeded();
    await page.locator('.ring-card').screenshot({ path: path.join(root, 'target', 'www-ring-card.png') });
    return `Ω = ${s.ring.record.omega} 1/s; ${r}`;
  });

  await check('the ring card\'s inputs are in the link: a reloaded link shows the same τ, Ω source and chart overlay', async () => {
    const u = await updates();
    await enterTau('0.3');
    await waitUpdate(u);
    // The link is written once the edits have stopped (about a second): wait for the one with this
    // τ (the link of the τ before may be there still).
    await page.waitForFunction(() => {
      const r = new URLSearchParams(location.hash.slice(1)).get('r');
      return r !== null && JSON.parse(r).tau === 0.3;
    }, null, { timeout: GUARD_MS });
    const link = await page.evaluate(() => location.href);
    const before = await page.evaluate(() => window.rimeState.ring.record);
    const again = await context.newPage();
    try {
      await again.goto(link, { waitUntil: 'load' });
      await again.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring, null, { timeout: GUARD_MS });
      const shown = await again.evaluate(() => ({
        tau: document.getElementById('r-tau').value,
        planet: document.getElementById('r-planet').checked,
        onChart: document.getElementById('r-onChart').checked,
        record: window.rimeState.ring.record,
        series: window.rimeState.figure.series,
      }));
      assert(shown.tau === '0.3', `τ field shows ${shown.tau}`);
      assert(shown.planet === true && shown.onChart === true, `planet ${shown.planet}, onChart ${shown.onChart}`);
      assert(shown.record.tau === 0.3 && shown.record.omega === before.omega, `reloaded card τ ${shown.record.tau}, Ω ${shown.record.omega} (was ${before.tau}, ${before.omega})`);
      assert(shown.series.some((n) => /^ε_cr of the ring/.test(n)), 'the ε_cr line is not on the reloaded chart');
    } finally {
      await again.close();
    }
    // A bad field is named and left at the page's start; the good ones are kept.
    const bad = link.replace(/([#&])r=[^&]*/, `$1r=${encodeURIComponent(JSON.stringify({ tau: -1, omega: 2e-4, bogus: 1 }))}`);
    const third = await context.newPage();
    try {
      await third.goto(bad, { waitUntil: 'load' });
      await third.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring, null, { timeout: GUARD_MS });
      const s = await third.evaluate(() => ({ notice: window.rimeState.notice || '', record: window.rimeState.ring.record, tau: document.getElementById('r-tau').value }));
      assert(/ring\.tau/.test(s.notice) && /ring\.bogus/.test(s.notice), `notice: ${s.notice}`);
      assert(s.record.tau === 0.5 && s.tau === '0.5', `τ after a bad link: card ${s.record.tau}, field ${s.tau}`);
      assert(s.record.omega === 2e-4, `Ω from the link: ${s.record.omega}`);
      return `${link.length} characters; bad link: ${s.notice.slice(0, 120)}`;
    } finally {
      await third.close();
    }
  });

  await check('issue 38: the card\'s grain sizes R–5R are `rime ring --radii R..5R --q 3` (ν too), shown first, and in the link', async () => {
    const u = await updates();
    await page.selectOption('#r-sizes', 'to_5r');
    await waitUpdate(u);
    const s = await page.evaluate(() => window.rimeState);
    assert(s.ring.sizes && s.ring.sizes.size_bins.length === 3, `sizes: ${JSON.stringify(s.ring.sizes).slice(0, 200)}`);
    const scene = JSON.parse(s.sceneJson);
    const r = scene.grains.radius_1;
    const sceneFile = path.join(os.tmpdir(), `rime-ring-e2e-sizes-${process.pid}.json`);
    fs.writeFileSync(sceneFile, s.sceneJson);
    const cli = JSON.parse(execFileSync(rime, ['ring', '--scene', sceneFile, '--tau', String(s.ring.record.tau), '--omega', String(s.ring.record.omega),
      '--radii', `${r}m..${5 * r}m`, '--q', '3', '--format', 'json'], { encoding: 'utf8' }));
    fs.rmSync(sceneFile);
    // The same core computation on both sides: every digit agrees.
    assert(s.ring.sizes.velocity_dispersion === cli.velocity_dispersion, `c: page ${s.ring.sizes.velocity_dispersion}, rime ring ${cli.velocity_dispersion}`);
    assert(s.ring.viscosity.total === cli.viscosity.total, `ν: page ${s.ring.viscosity.total}, rime ring ${cli.viscosity.total}`);
    assert(s.ring.sizes.size_bins.every((b, i) => b.velocity_dispersion === cli.size_bins[i].velocity_dispersion), 'c per bin differs');
    assert(s.ring.rows[0].label.startsWith('sizes '), `first row: ${s.ring.rows[0].label}`);
    await page.waitForFunction(() => {
      const q = new URLSearchParams(location.hash.slice(1)).get('r');
      return q !== null && JSON.parse(q).sizes === 'to_5r';
    }, null, { timeout: GUARD_MS });
    const link = await page.evaluate(() => location.href);
    const again = await context.newPage();
    try {
      await again.goto(link, { waitUntil: 'load' });
      await again.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring, null, { timeout: GUARD_MS });
      const shown = await again.evaluate(() => ({ sizes: document.getElementById('r-sizes').value, bins: window.rimeState.ring.sizes && window.rimeState.ring.sizes.size_bins.length }));
      assert(shown.sizes === 'to_5r' && shown.bins === 3, `reloaded: ${JSON.stringify(shown)}`);
    } finally {
      await again.close();
    }
    const u2 = await updates();
    await page.selectOption('#r-sizes', 'one');
    await waitUpdate(u2);
    return `c ${cli.velocity_dispersion} m/s, ν ${cli.viscosity.total} m²/s over ${r}–${5 * r} m`;
  });

  await check('issue 37: a ring value in a link gets the card\'s range check (τ = 1e308 is named and not used)', async () => {
    const q = await context.newPage();
    try {
      const link = `${url}#r=${encodeURIComponent(JSON.stringify({ tau: 1e308, omega: 2e-4 }))}`;
      await q.goto(link, { waitUntil: 'load' });
      await q.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring, null, { timeout: GUARD_MS });
      const s = await q.evaluate(() => ({ notice: window.rimeState.notice || '', record: window.rimeState.ring.record, tau: document.getElementById('r-tau').value }));
      assert(/ring\.tau: must lie in \(0, 5\]/.test(s.notice), `notice: ${s.notice}`);
      assert(s.record.tau === 0.5 && s.tau === '0.5' && s.record.omega === 2e-4, `card τ ${s.record.tau}, field ${s.tau}, Ω ${s.record.omega}`);
      return s.notice.slice(0, 140);
    } finally {
      await q.close();
    }
  });

  await check('issue 37: with every comparison on, the ring\'s ε_cr line has a colour and stroke of its own', async () => {
    const q = await context.newPage();
    try {
      const overlays = ['atlas:bridges1984', 'atlas:hatzes1988_frost', 'atlas:hatzes1988_compacted', 'atlas:hatzes1988_compacted_r20', 'atlas:supulver1995', 'atlas:higa1996', 'atlas:borderies1984', 'atlas:heisselmann2010', 'atlas:hill2015', 'model:brilliantov2007', 'model:schwager_poschel2008', 'model:muller_poschel2011'];
      const link = `${url}#v=${encodeURIComponent(JSON.stringify({ accuracy: 'fast', overlays }))}&r=${encodeURIComponent(JSON.stringify({ onChart: true }))}`;
      await q.goto(link, { waitUntil: 'load' });
      await q.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring && window.rimeState.figure.series.some((n) => /^ε_cr of the ring/.test(n)), null, { timeout: GUARD_MS });
      const f = await q.evaluate(() => window.rimeState.figure);
      const palette = await q.evaluate(async () => (await import('./core.js')).PALETTE.series);
      const i = f.series.findIndex((n) => /^ε_cr of the ring/.test(n));
      // As drawn: a line looks like another when its stroke and width are the same and its colour is
      // near (RGB distance under 80: blue #0072B2 and cyan #0098A8 are 39 apart).
      const rgb = (k) => [1, 3, 5].map((j) => parseInt(palette[Number(f.styles[k].split('/')[0])].slice(j, j + 2), 16));
      const dist = (a, b) => Math.hypot(...a.map((v, j) => v - b[j]));
      const width = (k) => f.widths[k] || 1.5; // (the page's width of a comparison)
      const alike = f.series.filter((n, k) => k !== i && f.styles[k].split('/')[1] === f.styles[i].split('/')[1]
        && width(k) === width(i) && dist(rgb(k), rgb(i)) < 80);
      assert(alike.length === 0, `the ε_cr line (${f.styles[i]}, ${width(i)} px) looks like ${alike.join(', ')}`);
      return `ε_cr line ${f.styles[i]}, ${width(i)} px; ${f.series.length - 1} other series, none alike`;
    } finally {
      await q.close();
    }
  });

  await check('issue 37: the all-curves CSV has the measured law the chart draws and, with the ring\'s line on the chart, its ε_cr column on the chart\'s speeds', async () => {
    const q = await context.newPage();
    try {
      const link = `${url}#r=${encodeURIComponent(JSON.stringify({ onChart: true }))}`;
      await q.goto(link, { waitUntil: 'load' });
      await q.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring && window.rimeState.figure.series.some((n) => /^ε_cr of the ring/.test(n)), null, { timeout: GUARD_MS });
      const d = await q.evaluate(() => ({ csv: window.rimeExports.familyCsv(), ring: window.rimeState.ring }));
      const rows = d.csv.split('\n').filter((l) => l && !l.startsWith('#')).map((l) => l.split(','));
      const head = rows[0];
      const law = head.indexOf('eps_n:bridges1984');
      const cr = head.findIndex((h) => /^eps_cr \[ring τ = /.test(h));
      assert(law > 0, `no law column: ${head.join(',')}`);
      assert(cr > 0, `no ring column: ${head.join(',')}`);
      // The law as printed, ε = 0.32 (v / 1 cm/s)^−0.234, over its measured speeds (0.15–20 mm/s).
      const lawRows = rows.slice(1).filter((r) => r[law] !== '');
      assert(lawRows.length >= 20, `${lawRows.length} law cells`);
      for (const r of lawRows) {
        const g = Number(r[0]);
        const want = 0.32 * (g / 0.01) ** -0.234;
        assert(g >= 1.5e-4 * (1 - 1e-12) && g <= 2e-2 * (1 + 1e-12) && Math.abs(Number(r[law]) / want - 1) < 1e-12, `law at ${g}: ${r[law]} vs ${want}`);
      }
      // ε_cr on every row of the chart's own speeds (those with the scene's ε_N).
      const frameRows = rows.slice(1).filter((r) => r[1] !== '');
      const values = new Set(frameRows.map((r) => r[cr]));
      assert(frameRows.length > 50 && values.size === 1 && Number([...values][0]) > 0 && Number([...values][0]) < 1, `ε_cr cells: ${[...values].join(' ')}`);
      return `${head[law]} (${lawRows.length} rows), ${head[cr]} = ${[...values][0]} on ${frameRows.length} rows`;
    } finally {
      await q.close();
    }
  });

  await check('at 375 px the ring card fits the screen (its table does not scroll sideways)', async () => {
    const phone = await context.newPage();
    try {
      await phone.setViewportSize({ width: 375, height: 812 });
      await phone.goto(url, { waitUntil: 'load' });
      await phone.waitForFunction(() => window.rimeState && window.rimeState.ready === true && window.rimeState.ring, null, { timeout: GUARD_MS });
      const [scroll, client] = await phone.evaluate(() => {
        const t = document.querySelector('.ring-card .table-wrap');
        return [t.scrollWidth, t.clientWidth];
      });
      assert(scroll <= client, `the table is ${scroll} px wide in a ${client} px box`);
      return `${scroll} px in ${client} px`;
    } finally {
      await phone.close();
    }
  });

  await check('no console errors', async () => {
    assert(problems.length === 0, problems.join(' | '));
  });
} finally {
  await context.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
process.exit(failures ? 1 : 0);
