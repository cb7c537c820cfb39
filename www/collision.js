// The "inside one collision" card: two grains approach, deform (the overlap exaggerated so that it
// can be seen), separate or stick, while the force–overlap loop traces along; a scrub slider and a
// replay button; the energy ledger as bars. Draws what the core computed (Explorer.collision) and
// holds no physics of its own. Respects prefers-reduced-motion: no animation, the slider instead.
import { PALETTE, qty, sig, speed } from './core.js';
import { linked } from './dom.js';

const $ = (id) => document.getElementById(id);
// Roles of the core's palette: the collision in the scene's colour, the other model and the
// energy terms in the family's hues, what stays in the bulk in the clean-surface grey.
const C = () => ({
  scene: PALETTE.scene, other: PALETTE.family[2], out: PALETTE.family[1], bulk: PALETTE.scene,
  layer: PALETTE.family[0], kept: PALETTE.clean, grain1: PALETTE.family[0], grain2: PALETTE.series[5],
});
const fmtNum = (v, d) => sig(v, d);
// Animation stages as fractions of the replay: approach, contact, departure.
const APPROACH = 0.2;
const CONTACT = 0.6;
const DURATION_MS = 3000;
/** After a scene edit the replay waits this long for the edits to stop (a slider drag sends many). */
const QUIET_MS = 400;

export class CollisionView {
  constructor() {
    this.data = null;
    this.u = 1; // where the replay stands, 0…1
    this.anim = null;
    this.reduced = window.matchMedia('(prefers-reduced-motion: reduce)').matches;
    this.quiet = null; // the timer of a replay waiting for edits to stop
    // Off screen the card is neither animated nor drawn; it is drawn when it scrolls into view.
    this.visible = true;
    this.stale = false;
    const card = $('collision-card');
    if (card && 'IntersectionObserver' in window) {
      new IntersectionObserver((entries) => {
        this.visible = entries.some((e) => e.isIntersecting);
        if (this.visible && this.stale) { this.stale = false; this.u = 1; this.draw(); }
        if (!this.visible) this.stop();
      }).observe(card);
    }
    $('collision-play').addEventListener('click', () => this.play());
    $('collision-scrub').addEventListener('input', () => {
      this.stop();
      this.u = Number($('collision-scrub').value) / 1000;
      this.draw();
    });
  }

  get animating() { return this.anim !== null || this.quiet !== null; }

  /** Shows a new collision (JSON of Explorer.collision). Asked for (`requested`: a click on the
   *  chart), it replays at once unless motion is reduced; after a scene edit it shows the end state
   *  and replays only once the edits have stopped for QUIET_MS and only while the card is on screen. */
  show(data, requested = false) {
    this.data = data;
    this.error = null;
    this.ledger();
    clearTimeout(this.quiet);
    this.quiet = null;
    if (this.reduced) { this.stop(); this.u = 1; this.draw(); return; }
    if (requested) { this.play(); return; }
    this.stop();
    this.u = 1;
    if (!this.visible) { this.stale = true; return; }
    this.draw();
    this.quiet = setTimeout(() => { this.quiet = null; if (this.visible) this.play(); }, QUIET_MS);
  }

  fail(message) {
    this.stop();
    this.data = null;
    $('collision-title').textContent = `— ${message}`;
    $('collision-ledger').replaceChildren();
    this.draw();
  }

  play() {
    if (!this.data) return;
    this.stop();
    if (this.reduced) { this.u = 1; this.draw(); return; }
    // Its first frame at once (the answer comes from the worker; the animation follows).
    this.u = 0;
    this.draw();
    const t0 = performance.now();
    const step = (now) => {
      this.u = Math.min(1, (now - t0) / DURATION_MS);
      this.draw();
      this.anim = this.u < 1 ? requestAnimationFrame(step) : null;
    };
    this.anim = requestAnimationFrame(step);
  }

  stop() {
    if (this.anim !== null) cancelAnimationFrame(this.anim);
    this.anim = null;
  }

  /** The sample index and the gap between the grains (in radii) at replay position u. */
  state() {
    const d = this.data;
    const n = d.t.length;
    const u = this.u;
    if (u < APPROACH) return { i: -1, gap: 0.5 * (APPROACH - u) / APPROACH };
    if (u <= APPROACH + CONTACT) return { i: Math.round(((u - APPROACH) / CONTACT) * (n - 1)), gap: 0 };
    const stuck = d.status.startsWith('stuck');
    const away = (u - APPROACH - CONTACT) / (1 - APPROACH - CONTACT);
    return { i: n - 1, gap: stuck ? 0 : 0.5 * away * Math.max(d.eps_n, 0.02), after: true };
  }

  ledger() {
    const d = this.data;
    const l = d.ledger;
    const rows = [
      ['kinetic energy out', l.kinetic_out, C().out],
      ['dissipated in the bulk, Eq. (4)', l.dissipated_bulk, C().bulk],
      ['dissipated in the layer, Eq. (8)', l.dissipated_layer, C().layer],
      ['adhesion W_s, Eq. (12)', l.adhesion, C().other],
      ['left in the bulk (force-zero end)', l.elastic_retained, C().kept],
    ];
    // The rows are built once; a new collision writes only their numbers and bars (issue 26:
    // rebuilding the list for every frame's replay was a sizeable part of the page's layout).
    const box = $('collision-ledger');
    if (!this.rows || !box.contains(this.rows[0].li)) {
      this.rows = rows.map(([name]) => {
        const li = document.createElement('li');
        const value = document.createTextNode('');
        const bar = document.createElement('span');
        bar.className = 'bar';
        li.append(...linked(`${name}: `), value, bar);
        return { li, value, bar };
      });
      this.hint = Object.assign(document.createElement('li'), { className: 'hint' });
      box.replaceChildren(...this.rows.map((r) => r.li), this.hint);
    }
    rows.forEach(([, v, color], k) => {
      const pct = l.kinetic_in > 0 ? (100 * v) / l.kinetic_in : 0;
      const { value, bar } = this.rows[k];
      const text = `${sig(pct, 3)} %`;
      if (value.data !== text) value.data = text;
      const width = `${Math.max(0, Math.min(100, pct)).toFixed(1)}%`;
      if (bar.style.width !== width) bar.style.width = width;
      if (bar.dataset.color !== color) { bar.dataset.color = color; bar.style.background = color; }
    });
    const hint = `kinetic energy in ${qty(l.kinetic_in, 'J', 3)} · closure ${sig(l.closure, 2)}${d.resolved ? '' : ' (the slow end of the contact is not sampled)'}`;
    if (this.hint.textContent !== hint) this.hint.textContent = hint;
    const title = `at g_N = ${speed(d.g, 4)}: ε_N = ${fmtNum(d.eps_n, 5)}, ${d.status}` +
      (d.t_c === null ? '' : `, t_c = ${qty(d.t_c, 's', 3)}`) + `, ξ_max = ${qty(d.xi_max, 'm', 3)}`;
    if ($('collision-title').textContent !== title) $('collision-title').textContent = title;
  }

  draw() {
    drawGrains($('collision-grains'), this.data, this.data ? this.state() : null);
    drawLoop($('collision-loop'), this.data, this.data ? this.state() : null);
    if (this.data) {
      $('collision-scrub').value = String(Math.round(this.u * 1000));
      const s = this.state();
      $('collision-time').textContent = s.i < 0 ? 'approaching' : s.after && this.u > APPROACH + CONTACT
        ? (this.data.status.startsWith('stuck') ? 'stuck together' : 'separating')
        : `t = ${qty(this.data.t[s.i], 's', 3)}`;
    }
  }
}

/** The canvas at its layout size; its buffer is reallocated only when that size changes (setting
 *  width or height, even to the same value, reallocates and clears it: not once per animation frame). */
function sized(canvas) {
  const w = Math.max(150, Math.floor(canvas.parentElement.clientWidth / (window.innerWidth < 600 ? 1 : 2) - 8));
  const h = Math.round(w * 0.6);
  const dpr = window.devicePixelRatio || 1;
  const bw = Math.round(w * dpr), bh = Math.round(h * dpr);
  if (canvas.width !== bw || canvas.height !== bh) {
    canvas.width = bw;
    canvas.height = bh;
    canvas.style.width = `${w}px`;
    canvas.style.height = `${h}px`;
  }
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  return { ctx, w, h };
}

/** Two grains side by side; their overlap drawn as a flattened contact (exaggerated). */
function drawGrains(canvas, d, s) {
  const { ctx, w, h } = sized(canvas);
  if (!d) return;
  const rMax = Math.max(d.radius_1, d.radius_2);
  const r1 = (0.32 * h * d.radius_1) / rMax;
  const r2 = (0.32 * h * d.radius_2) / rMax;
  // ξ_max is drawn as 35 % of the smaller radius, whatever its true size (said in the caption).
  const scale = (0.35 * Math.min(r1, r2)) / (d.xi_max || 1);
  const xi = s.i < 0 ? 0 : d.xi[s.i];
  const overlap = xi * scale - s.gap * Math.min(r1, r2);
  const cy = h / 2;
  const c1 = w / 2 - r1 + overlap / 2;
  const c2 = w / 2 + r2 - overlap / 2;
  const plane = (c1 + r1 + c2 - r2) / 2; // the flattened contact lies midway in the overlap
  for (const [c, r, side, color] of [[c1, r1, -1, C().grain1], [c2, r2, 1, C().grain2]]) {
    ctx.save();
    ctx.beginPath();
    if (overlap > 0) ctx.rect(side < 0 ? 0 : plane, 0, side < 0 ? plane : w - plane, h);
    else ctx.rect(0, 0, w, h);
    ctx.clip();
    ctx.beginPath();
    ctx.arc(c, cy, r, 0, 2 * Math.PI);
    ctx.fillStyle = color;
    ctx.fill();
    ctx.restore();
  }
  ctx.fillStyle = '#333';
  ctx.font = '12px sans-serif';
  ctx.fillText(`overlap exaggerated (true ξ_max/R = ${fmtNum(d.xi_max / Math.min(d.radius_1, d.radius_2), 2)})`, 6, h - 8);
}

/** The normal force against the overlap, traced up to the current sample; phase instants marked. */
function drawLoop(canvas, d, s) {
  const { ctx, w, h } = sized(canvas);
  if (!d) return;
  const xs = [...d.xi, ...(d.dynamic ? d.dynamic.xi : [])];
  const fs = [...d.force, ...(d.dynamic ? d.dynamic.force : [])];
  const x0 = Math.min(0, ...xs), x1 = Math.max(...xs) || 1;
  const f0 = Math.min(0, ...fs), f1 = Math.max(...fs) || 1;
  const box = { l: 44, r: w - 8, t: 10, b: h - 28 };
  const X = (x) => box.l + ((x - x0) / (x1 - x0)) * (box.r - box.l);
  const Y = (f) => box.b - ((f - f0) / (f1 - f0)) * (box.b - box.t);
  ctx.strokeStyle = '#777';
  ctx.strokeRect(box.l, box.t, box.r - box.l, box.b - box.t);
  ctx.fillStyle = '#333';
  ctx.font = '11px sans-serif';
  ctx.fillText('overlap ξ', box.r - 80, h - 6);
  ctx.fillText(`F (max ${qty(f1, 'N', 2)})`, box.l + 4, box.t + 12);
  // Tick values at both ends of each axis (issue 37: the plot had none), with their units.
  const ticks = {
    x: [[x0, 'left'], [x1, 'right']].map(([v, align]) => ({ v, text: qty(v, 'm', 3), at: X(v), align })),
    // 0 N only where it does not crowd an end (a small pull below it, -103 mN against 1 N).
    y: [...new Set([f0, f1, ...(Math.min(Y(0) - Y(f1), Y(f0) - Y(0)) >= 12 ? [0] : [])])].map((v) => ({ v, text: qty(v, 'N', 3), at: Y(v) })),
  };
  ctx.fillStyle = '#555';
  ctx.font = '10px sans-serif';
  for (const t of ticks.x) {
    ctx.textAlign = t.align;
    ctx.fillText(t.text, t.at, box.b + 12);
  }
  ctx.textAlign = 'right';
  for (const t of ticks.y) ctx.fillText(t.text, box.l - 3, Math.min(box.b, Math.max(box.t + 8, t.at + 3)));
  ctx.textAlign = 'left';
  window.rimeState.collisionTicks = { x: ticks.x.map((t) => [t.v, t.text]), y: ticks.y.map((t) => [t.v, t.text]) };
  const path = (xa, fa, upto, color, width) => {
    ctx.beginPath();
    for (let k = 0; k <= upto && k < xa.length; k++) {
      const px = X(xa[k]), py = Y(fa[k]);
      if (k === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    }
    ctx.strokeStyle = color;
    ctx.lineWidth = width;
    ctx.stroke();
  };
  if (d.dynamic) {
    path(d.dynamic.xi, d.dynamic.force, d.dynamic.xi.length, C().other, 1.2);
    ctx.fillStyle = C().other;
    ctx.fillText('brilliantov2007 (dynamic JKR)', box.l + 4, box.t + 26);
  }
  path(d.xi, d.force, d.xi.length, C().kept, 1);
  const upto = s.i < 0 ? -1 : s.i;
  if (upto >= 0) {
    path(d.xi, d.force, upto, C().scene, 2.2);
    ctx.beginPath();
    ctx.arc(X(d.xi[upto]), Y(d.force[upto]), 4, 0, 2 * Math.PI);
    ctx.fillStyle = C().scene;
    ctx.fill();
  }
  // Phase instants: a tick at the sample nearest to each.
  ctx.fillStyle = '#333';
  for (const p of d.phases) {
    let k = 0;
    while (k < d.t.length - 1 && d.t[k] < p.t) k++;
    ctx.fillRect(X(d.xi[k]) - 1, Y(d.force[k]) - 6, 2, 12);
  }
}
