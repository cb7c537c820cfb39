// The two surfaces every figure is painted on: a canvas (the screen and PNG downloads, scaled by
// devicePixelRatio) and an SVG text (downloads), with the same drawing calls, so that a download
// shows what the screen shows. Coordinates are CSS pixels.

const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const INK = '#222222';

/** Sets a canvas element's CSS size (only when it changes: a write invalidates the layout). */
export function sizeElement(canvas, width, height) {
  if (canvas.style.height !== `${height}px`) canvas.style.height = `${height}px`;
  if (canvas.style.width !== `${width}px`) canvas.style.width = `${width}px`;
}

export class CanvasPainter {
  /** `scale`: device pixels per CSS pixel (the screen's by default; 2 for PNG exports). */
  constructor(canvas, width, height, scale = globalThis.devicePixelRatio || 1) {
    // Resizing a canvas reallocates it: only when the size changes.
    const cw = Math.round(width * scale), ch = Math.round(height * scale);
    if (canvas.width !== cw) canvas.width = cw;
    if (canvas.height !== ch) canvas.height = ch;
    // An OffscreenCanvas (drawn in a worker) has no style: the page sizes its element.
    if (canvas.style) sizeElement(canvas, width, height);
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.ctx.setTransform(scale, 0, 0, scale, 0, 0);
    this.ctx.clearRect(0, 0, width, height);
    this.width = width;
    this.height = height;
  }
  rect(x, y, w, h, { fill, stroke, width = 1, alpha = 1 } = {}) {
    const c = this.ctx;
    c.globalAlpha = alpha;
    if (fill) { c.fillStyle = fill; c.fillRect(x, y, w, h); }
    c.globalAlpha = 1;
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
  text(x, y, s, { size = 11, color = INK, align = 'left', baseline = 'alphabetic', rotate = 0, bg = null, bold = false } = {}) {
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
  /** The stick-map grid: n×n class codes (index i·n + j), code i (g_N) up, j (g_T) across. */
  grid(x, y, w, h, n, codes, colors) {
    // In the painter worker there is no document: an OffscreenCanvas there.
    const off = typeof document === 'undefined' ? new OffscreenCanvas(n, n) : document.createElement('canvas');
    off.width = n; off.height = n;
    const octx = off.getContext('2d');
    const img = octx.createImageData(n, n);
    const rgb = colors.map((c) => [1, 3, 5].map((k) => parseInt(c.slice(k, k + 2), 16)));
    const d = img.data;
    for (let i = 0; i < n; i++) {
      const row = (n - 1 - i) * n;
      for (let j = 0; j < n; j++) {
        const col = rgb[codes[i * n + j]] || [0, 0, 0];
        const p = (row + j) * 4;
        d[p] = col[0]; d[p + 1] = col[1]; d[p + 2] = col[2]; d[p + 3] = 255;
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
  rect(x, y, w, h, { fill, stroke, width = 1, alpha = 1 } = {}) {
    this.parts.push(`<rect x="${r2(x)}" y="${r2(y)}" width="${r2(w)}" height="${r2(h)}" fill="${fill || 'none'}"${alpha !== 1 ? ` fill-opacity="${alpha}"` : ''}${stroke ? ` stroke="${stroke}" stroke-width="${width}"` : ''}/>`);
  }
  line(pts, { color = '#000', width = 1, dash = null } = {}) {
    if (pts.length < 2) return;
    const d = pts.map((p, i) => `${i ? 'L' : 'M'}${r2(p[0])} ${r2(p[1])}`).join('');
    this.parts.push(`<path d="${d}" fill="none" stroke="${color}" stroke-width="${width}" stroke-linejoin="round"${dash ? ` stroke-dasharray="${dash.join(' ')}"` : ''}/>`);
  }
  circle(x, y, r, { fill = '#000' } = {}) {
    this.parts.push(`<circle cx="${r2(x)}" cy="${r2(y)}" r="${r}" fill="${fill}"/>`);
  }
  text(x, y, s, { size = 11, color = INK, align = 'left', baseline = 'alphabetic', rotate = 0, bold = false } = {}) {
    const anchor = { left: 'start', center: 'middle', right: 'end' }[align];
    const dy = baseline === 'middle' ? ' dominant-baseline="middle"' : baseline === 'top' ? ' dominant-baseline="hanging"' : '';
    const tr = rotate ? ` transform="rotate(${(rotate * 180) / Math.PI} ${r2(x)} ${r2(y)})"` : '';
    this.parts.push(`<text x="${r2(x)}" y="${r2(y)}" font-size="${size}"${bold ? ' font-weight="600"' : ''} fill="${color}" text-anchor="${anchor}"${dy}${tr}>${esc(s)}</text>`);
  }
  grid(x, y, w, h, n, codes, colors) {
    const c = w / n;
    for (let i = 0; i < n; i++) {
      const top = y + (n - 1 - i) * c;
      let start = 0;
      for (let j = 1; j <= n; j++) {
        if (j === n || codes[i * n + j] !== codes[i * n + start]) {
          this.parts.push(`<rect x="${r2(x + start * c)}" y="${r2(top)}" width="${r2((j - start) * c + 0.3)}" height="${r2(c + 0.3)}" fill="${colors[codes[i * n + start]] || '#000'}"/>`);
          start = j;
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
  /** A comment-free metadata block (title and description) for the file. */
  meta(title, desc) {
    this.parts.unshift(`<title>${esc(title)}</title><desc>${esc(desc)}</desc>`);
  }
  svg() {
    return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="${this.width}" height="${this.height}" viewBox="0 0 ${this.width} ${this.height}" font-family="${FONT.replace(/"/g, "'")}">\n<rect width="100%" height="100%" fill="#fff"/>\n${this.parts.join('\n')}\n</svg>\n`;
  }
}

/** Approximate width of `text` at `size` px in the page's sans-serif (the SVG has no measure). */
