// Small plotting library for the explorer: one drawing description, two painters (canvas, SVG).
// Coordinates are CSS pixels; the canvas painter scales by devicePixelRatio.

export const CLASS_COLORS = [
  '#4e79a7', // rolling
  '#f28e2b', // sliding
  '#59a14f', // rolling_stop
  '#e15759', // sliding_gap
  '#8e5ea2', // aggregation
  '#e9c84a', // normal_stick_only
  '#c9c3bf', // undefined
];
export const SERIES_COLORS = ['#d1495b', '#edae49', '#00798c', '#66a182', '#8d6a9f', '#2e4057'];
const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const SUP = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };

/** 10^k with superscript digits ("10⁻⁶"). */
export function decadeLabel(k) {
  if (k === 0) return '1';
  if (k === 1) return '10';
  return '10' + String(k).split('').map((c) => SUP[c] ?? c).join('');
}

/** A number with `digits` significant digits, trailing zeros removed. */
export function fmtNum(v, digits = 4) {
  if (v === null || v === undefined || Number.isNaN(v)) return '—';
  if (!Number.isFinite(v)) return v > 0 ? '∞' : '−∞';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e-3 && a < 1e5) return String(Number(v.toPrecision(digits)));
  const [m, e] = v.toExponential(digits - 1).split('e');
  return `${Number(m)}e${Number(e)}`;
}

const PREFIXES = [[1e-12, 'p'], [1e-9, 'n'], [1e-6, 'µ'], [1e-3, 'm'], [1, ''], [1e3, 'k']];

/** The SI prefix that suits magnitude `a`: [factor, prefix]. */
export function prefixFor(a) {
  let best = PREFIXES[0];
  for (const p of PREFIXES) if (a >= p[0] * 0.9999) best = p;
  return best;
}

/** A speed with an SI prefix ("6.61 µm/s"). */
export function fmtSpeed(v, digits = 3) {
  if (!Number.isFinite(v)) return fmtNum(v);
  if (v === 0) return '0 m/s';
  const [f, p] = prefixFor(Math.abs(v));
  return `${Number((v / f).toPrecision(digits))} ${p}m/s`;
}

/** "Nice" linear ticks from lo to hi, about `count` of them. */
export function niceTicks(lo, hi, count) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / Math.max(1, count);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? 10 * mag;
  const out = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi * (1 + 1e-9); v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

export class CanvasPainter {
  /** `scale`: device pixels per CSS pixel (the screen's by default; 2 for PNG exports). */
  constructor(canvas, width, height, scale = window.devicePixelRatio || 1) {
    const dpr = scale;
    canvas.width = Math.round(width * dpr);
    canvas.height = Math.round(height * dpr);
    canvas.style.height = `${height}px`;
    this.ctx = canvas.getContext('2d');
    this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.ctx.clearRect(0, 0, width, height);
    this.width = width;
    this.height = height;
  }
  rect(x, y, w, h, { fill, stroke, width = 1 } = {}) {
    const c = this.ctx;
    if (fill) { c.fillStyle = fill; c.fillRect(x, y, w, h); }
    if (stroke) { c.strokeStyle = stroke; c.lineWidth = width; c.setLineDash([]); c.strokeRect(x, y, w, h); }
  }
  line(pts, { color = '#000', width = 1, dash = null } = {}) {
    if (pts.length < 2) return;
    const c = this.ctx;
    c.beginPath();
    c.moveTo(pts[0][0], pts[0][1]);
    for (let i = 1; i < pts.length; i++) c.lineTo(pts[i][0], pts[i][1]);
    c.strokeStyle = color; c.lineWidth = width; c.lineJoin = 'round';
    c.setLineDash(dash || []);
    c.stroke();
    c.setLineDash([]);
  }
  circle(x, y, r, { fill = '#000' } = {}) {
    const c = this.ctx;
    c.beginPath(); c.arc(x, y, r, 0, 2 * Math.PI); c.fillStyle = fill; c.fill();
  }
  text(x, y, s, { size = 11, color = '#222', align = 'left', baseline = 'alphabetic', rotate = 0, bg = null, bold = false } = {}) {
    const c = this.ctx;
    c.save();
    c.translate(x, y);
    if (rotate) c.rotate(rotate);
    c.font = `${bold ? '600 ' : ''}${size}px ${FONT}`;
    c.textAlign = align; c.textBaseline = baseline;
    if (bg) {
      const w = c.measureText(s).width + 4;
      const x0 = align === 'center' ? -w / 2 : align === 'right' ? -w + 2 : -2;
      c.fillStyle = bg;
      c.fillRect(x0, baseline === 'top' ? -1 : -size, w, size + 3);
    }
    c.fillStyle = color;
    c.fillText(s, 0, 0);
    c.restore();
  }
  /** An n×n grid of class codes, cell (i, j) at column i, row n−1−j, filling the box. */
  cells(x, y, w, h, n, codes, colors) {
    const off = document.createElement('canvas');
    off.width = n; off.height = n;
    const octx = off.getContext('2d');
    const img = octx.createImageData(n, n);
    const rgb = colors.map((c) => [1, 3, 5].map((k) => parseInt(c.slice(k, k + 2), 16)));
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        const col = rgb[codes[i * n + j]] || [0, 0, 0];
        const p = ((n - 1 - j) * n + i) * 4;
        img.data[p] = col[0]; img.data[p + 1] = col[1]; img.data[p + 2] = col[2]; img.data[p + 3] = 255;
      }
    }
    octx.putImageData(img, 0, 0);
    this.ctx.imageSmoothingEnabled = false;
    this.ctx.drawImage(off, x, y, w, h);
  }
  clip(x, y, w, h, body) {
    const c = this.ctx;
    c.save(); c.beginPath(); c.rect(x, y, w, h); c.clip(); body(); c.restore();
  }
}

const esc = (s) => String(s).replace(/[&<>"]/g, (ch) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[ch]);
const r2 = (v) => Math.round(v * 100) / 100;

export class SvgPainter {
  constructor(width, height) {
    this.width = width; this.height = height; this.parts = []; this.clips = 0;
  }
  rect(x, y, w, h, { fill, stroke, width = 1 } = {}) {
    this.parts.push(`<rect x="${r2(x)}" y="${r2(y)}" width="${r2(w)}" height="${r2(h)}" fill="${fill || 'none'}"${stroke ? ` stroke="${stroke}" stroke-width="${width}"` : ''}/>`);
  }
  line(pts, { color = '#000', width = 1, dash = null } = {}) {
    if (pts.length < 2) return;
    const d = pts.map((p, i) => `${i ? 'L' : 'M'}${r2(p[0])} ${r2(p[1])}`).join('');
    this.parts.push(`<path d="${d}" fill="none" stroke="${color}" stroke-width="${width}" stroke-linejoin="round"${dash ? ` stroke-dasharray="${dash.join(' ')}"` : ''}/>`);
  }
  circle(x, y, r, { fill = '#000' } = {}) {
    this.parts.push(`<circle cx="${r2(x)}" cy="${r2(y)}" r="${r}" fill="${fill}"/>`);
  }
  text(x, y, s, { size = 11, color = '#222', align = 'left', baseline = 'alphabetic', rotate = 0, bold = false } = {}) {
    const anchor = { left: 'start', center: 'middle', right: 'end' }[align];
    const dy = baseline === 'middle' ? ' dominant-baseline="middle"' : baseline === 'top' ? ' dominant-baseline="hanging"' : '';
    const tr = rotate ? ` transform="rotate(${(rotate * 180) / Math.PI} ${r2(x)} ${r2(y)})"` : '';
    this.parts.push(`<text x="${r2(x)}" y="${r2(y)}" font-size="${size}"${bold ? ' font-weight="600"' : ''} fill="${color}" text-anchor="${anchor}"${dy}${tr}>${esc(s)}</text>`);
  }
  cells(x, y, w, h, n, codes, colors) {
    const cw = w / n, ch = h / n;
    for (let j = 0; j < n; j++) {
      let start = 0;
      for (let i = 1; i <= n; i++) {
        if (i === n || codes[i * n + j] !== codes[start * n + j]) {
          const row = n - 1 - j;
          this.parts.push(`<rect x="${r2(x + start * cw)}" y="${r2(y + row * ch)}" width="${r2((i - start) * cw + 0.3)}" height="${r2(ch + 0.3)}" fill="${colors[codes[start * n + j]] || '#000'}"/>`);
          start = i;
        }
      }
    }
  }
  clip(x, y, w, h, body) {
    const id = `c${this.clips++}`;
    this.parts.push(`<clipPath id="${id}"><rect x="${x}" y="${y}" width="${w}" height="${h}"/></clipPath><g clip-path="url(#${id})">`);
    body();
    this.parts.push('</g>');
  }
  svg() {
    return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="${this.width}" height="${this.height}" viewBox="0 0 ${this.width} ${this.height}" font-family="${FONT.replace(/"/g, "'")}">\n<rect width="100%" height="100%" fill="#fff"/>\n${this.parts.join('\n')}\n</svg>\n`;
  }
}

/** Legend rows: entries laid out left to right, wrapping at `width` (approximate text widths). */
function legendLayout(entries, x0, width) {
  const rows = [[]];
  let x = x0;
  for (const e of entries) {
    const w = 26 + e.label.length * 6.1 + 14;
    if (x + w > x0 + width && rows[rows.length - 1].length) { rows.push([]); x = x0; }
    rows[rows.length - 1].push({ ...e, x });
    x += w;
  }
  return rows;
}

/**
 * The ε_N(g_N) chart on log–log axes.
 * spec: {xMin, xMax, yMin, yMax (decades as numbers), xLabel, yLabel, series: [{x, y, color, width, dash, label}],
 *        bands: [{x: [lo, hi], y: [lo, hi], fill, stroke, label, short}], markers: [{x, label}], hover: {x, y} | null}
 * Returns the plot box and the coordinate transforms (for hover).
 */
export function drawChart(p, spec) {
  const { width: W, height: H } = p;
  const entries = spec.series.filter((s) => s.label).map((s) => ({ label: s.label, color: s.color, dash: s.dash, width: s.width }));
  for (const b of spec.bands || []) entries.push({ label: b.label, color: b.stroke, fill: b.fill, box: true });
  const rows = legendLayout(entries, 60, W - 72);
  const box = { l: 60, r: W - 12, t: 10 + rows.length * 16 + 6, b: H - 42 };
  const lx = [Math.log10(spec.xMin), Math.log10(spec.xMax)];
  const ly = [Math.log10(spec.yMin), Math.log10(spec.yMax)];
  const X = (v) => box.l + ((Math.log10(v) - lx[0]) / (lx[1] - lx[0])) * (box.r - box.l);
  const Y = (v) => box.b - ((Math.log10(v) - ly[0]) / (ly[1] - ly[0])) * (box.b - box.t);
  const inv = (px) => 10 ** (lx[0] + ((px - box.l) / (box.r - box.l)) * (lx[1] - lx[0]));

  p.rect(0, 0, W, H, { fill: '#fff' });
  // Legend.
  rows.forEach((row, r) => row.forEach((e) => {
    const y = 10 + r * 16 + 6;
    if (e.box) p.rect(e.x + 4, y - 5, 14, 10, { fill: e.fill, stroke: e.color });
    else p.line([[e.x, y], [e.x + 22, y]], { color: e.color, width: Math.max(1.5, e.width || 1.5), dash: e.dash });
    p.text(e.x + 26, y + 4, e.label, { size: 11 });
  }));
  // Grid and ticks.
  const decadesX = lx[1] - lx[0];
  const stepX = Math.max(1, Math.ceil(46 / ((box.r - box.l) / decadesX)));
  for (let k = Math.ceil(lx[0] - 1e-9); k <= lx[1] + 1e-9; k++) {
    const x = X(10 ** k);
    p.line([[x, box.t], [x, box.b]], { color: '#e6e6e6' });
    for (let m = 2; m < 10 && k + Math.log10(m) < lx[1]; m++) {
      const xm = X(m * 10 ** k);
      if (xm > box.l) p.line([[xm, box.b], [xm, box.b - 4]], { color: '#999' });
    }
    p.line([[x, box.b], [x, box.b + 5]], { color: '#333' });
    if (((k % stepX) + stepX) % stepX === 0) p.text(x, box.b + 17, decadeLabel(k), { size: 11, align: 'center' });
  }
  const stepY = Math.max(1, Math.ceil(18 / ((box.b - box.t) / (ly[1] - ly[0]))));
  for (let k = Math.ceil(ly[0] - 1e-9); k <= ly[1] + 1e-9; k++) {
    const y = Y(10 ** k);
    p.line([[box.l, y], [box.r, y]], { color: '#e6e6e6' });
    for (let m = 2; m < 10 && k + Math.log10(m) < ly[1]; m++) {
      const ym = Y(m * 10 ** k);
      if (ym < box.b) p.line([[box.l, ym], [box.l + 4, ym]], { color: '#999' });
    }
    p.line([[box.l - 5, y], [box.l, y]], { color: '#333' });
    if (((k % stepY) + stepY) % stepY === 0) p.text(box.l - 8, y + 4, decadeLabel(k), { size: 11, align: 'right' });
  }
  p.text((box.l + box.r) / 2, H - 8, spec.xLabel, { size: 12, align: 'center' });
  p.text(16, (box.t + box.b) / 2, spec.yLabel, { size: 12, align: 'center', rotate: -Math.PI / 2 });

  p.clip(box.l, box.t, box.r - box.l, box.b - box.t, () => {
    // Experimental ranges (translucent boxes, under everything else).
    for (const b of spec.bands || []) {
      const x0 = X(b.x[0]), x1 = X(b.x[1]), y0 = Y(b.y[1]), y1 = Y(b.y[0]);
      p.rect(x0, y0, x1 - x0, y1 - y0, { fill: b.fill, stroke: b.stroke });
      if (x1 - x0 > 18) p.text(x0 + 3, y0 + 12, b.short || '', { size: 10, color: b.stroke });
    }
    // Critical-velocity markers.
    (spec.markers || []).forEach((m, i) => {
      if (!(m.x > spec.xMin && m.x < spec.xMax)) return;
      const x = X(m.x);
      p.line([[x, box.t], [x, box.b]], { color: '#555', width: 1, dash: [2, 3] });
      // Label beside the marker, on whichever side it fits (approximate text width).
      let label = m.label;
      const fits = (t) => t.length * 5.9 + 6;
      let right = x + fits(label) <= box.r || x - fits(label) < box.l;
      if (x + fits(label) > box.r && x - fits(label) < box.l) {
        label = m.short || label;
        right = x + fits(label) <= box.r;
      }
      p.text(x + (right ? 4 : -4), box.b - 8 - i * 15, label, { size: 10.5, color: '#333', align: right ? 'left' : 'right', bg: 'rgba(255,255,255,0.85)' });
    });
    // Series: broken where ε_N is 0 or outside the axes (stuck, overdamped).
    for (const s of spec.series) {
      let seg = [];
      const flush = () => { if (seg.length > 1) p.line(seg, { color: s.color, width: s.width || 1.5, dash: s.dash }); seg = []; };
      for (let i = 0; i < s.x.length; i++) {
        const v = s.y[i];
        if (v > 0 && Number.isFinite(v) && v >= spec.yMin * 0.5) seg.push([X(s.x[i]), Y(Math.max(v, spec.yMin * 0.5))]);
        else flush();
      }
      flush();
    }
    if (spec.hover) {
      const x = X(spec.hover.x);
      p.line([[x, box.t], [x, box.b]], { color: '#888', width: 1 });
      if (spec.hover.y > 0 && spec.hover.y >= spec.yMin) p.circle(x, Y(spec.hover.y), 3.5, { fill: '#111' });
    }
  });
  p.rect(box.l, box.t, box.r - box.l, box.b - box.t, { stroke: '#333' });
  return { box, X, Y, inv };
}

/**
 * The stick map over (g_N, g_T) on linear axes, g_N to the right, g_T up.
 * spec: {n, codes, max, colors, hover: {i, j} | null}
 */
export function drawMap(p, spec) {
  const { width: W, height: H } = p;
  const size = Math.min(W - 70, H - 50);
  const box = { l: 58, t: 10, r: 58 + size, b: 10 + size };
  const [f, prefix] = prefixFor(spec.max);
  p.rect(0, 0, W, H, { fill: '#fff' });
  p.cells(box.l, box.t, size, size, spec.n, spec.codes, spec.colors);
  const ticks = niceTicks(0, spec.max / f, size < 260 ? 4 : 6);
  for (const t of ticks) {
    const frac = (t * f) / spec.max;
    const x = box.l + frac * size;
    const y = box.b - frac * size;
    p.line([[x, box.b], [x, box.b + 5]], { color: '#333' });
    p.text(x, box.b + 17, fmtNum(t, 3), { size: 11, align: 'center' });
    p.line([[box.l - 5, y], [box.l, y]], { color: '#333' });
    p.text(box.l - 8, y + 4, fmtNum(t, 3), { size: 11, align: 'right' });
  }
  p.rect(box.l, box.t, size, size, { stroke: '#333' });
  p.text(box.l + size / 2, box.b + 34, `normal speed g_N [${prefix}m/s]`, { size: 12, align: 'center' });
  p.text(16, box.t + size / 2, `tangential speed g_T [${prefix}m/s]`, { size: 12, align: 'center', rotate: -Math.PI / 2 });
  if (spec.hover) {
    const c = size / spec.n;
    p.rect(box.l + spec.hover.i * c, box.t + (spec.n - 1 - spec.hover.j) * c, c, c, { stroke: '#000', width: 1.5 });
  }
  return { box, size };
}
