// Shared by the shelfdock pages: a pan-and-zoom 2D view of a metric frame on a canvas (x right,
// y up, metres) and small time plots. Plain JavaScript, no dependencies.
"use strict";

class View2D {
  constructor(canvas, onChange) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.cx = 0; this.cy = 0; this.scale = 80;  // world point at the canvas centre, pixels per metre
    this.onChange = onChange;
    let drag = null;
    canvas.addEventListener("mousedown", (e) => { drag = [e.clientX, e.clientY]; });
    window.addEventListener("mouseup", () => { drag = null; });
    canvas.addEventListener("mousemove", (e) => {
      if (!drag) return;
      this.cx -= (e.clientX - drag[0]) / this.scale; this.cy += (e.clientY - drag[1]) / this.scale;
      drag = [e.clientX, e.clientY]; this.onChange();
    });
    canvas.addEventListener("wheel", (e) => {
      e.preventDefault();
      // Zoom about the pointer: the world point under it stays put.
      const r = canvas.getBoundingClientRect();
      const [wx, wy] = this.toWorld(e.clientX - r.left, e.clientY - r.top);
      this.scale *= e.deltaY < 0 ? 1.2 : 1 / 1.2;
      const [nx, ny] = this.toWorld(e.clientX - r.left, e.clientY - r.top);
      this.cx += wx - nx; this.cy += wy - ny;
      this.onChange();
    }, { passive: false });
  }
  resize() {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    if (this.canvas.width !== w || this.canvas.height !== h) { this.canvas.width = w; this.canvas.height = h; }
  }
  toPx(x, y) { return [this.canvas.width / 2 + (x - this.cx) * this.scale, this.canvas.height / 2 - (y - this.cy) * this.scale]; }
  toWorld(px, py) { return [this.cx + (px - this.canvas.width / 2) / this.scale, this.cy - (py - this.canvas.height / 2) / this.scale]; }
  // Frames the points [[x, y], ...] with a margin.
  fit(points, margin = 0.5) {
    this.resize();
    if (!points.length) return;
    const xs = points.map((p) => p[0]), ys = points.map((p) => p[1]);
    const minx = Math.min(...xs), maxx = Math.max(...xs), miny = Math.min(...ys), maxy = Math.max(...ys);
    this.cx = (minx + maxx) / 2; this.cy = (miny + maxy) / 2;
    this.scale = Math.min(this.canvas.width / (maxx - minx + 2 * margin), this.canvas.height / (maxy - miny + 2 * margin));
  }
  clear() { this.resize(); this.ctx.clearRect(0, 0, this.canvas.width, this.canvas.height); }
  points(pts, color, size = 2) {
    const c = this.ctx; c.fillStyle = color;
    for (const p of pts) { const [x, y] = this.toPx(p[0], p[1]); c.fillRect(x - size / 2, y - size / 2, size, size); }
  }
  polyline(pts, color, width = 1, dash = []) {
    if (pts.length < 2) return;
    const c = this.ctx; c.strokeStyle = color; c.lineWidth = width; c.setLineDash(dash); c.beginPath();
    pts.forEach((p, k) => { const [x, y] = this.toPx(p[0], p[1]); k ? c.lineTo(x, y) : c.moveTo(x, y); });
    c.stroke(); c.setLineDash([]);
  }
  // A rectangle of `length` x `width` centred on pose {x, y, yaw}, with a heading tick.
  box(p, length, width, color, lineWidth = 2, dash = []) {
    const co = Math.cos(p.yaw), si = Math.sin(p.yaw);
    const corners = [[length / 2, width / 2], [-length / 2, width / 2], [-length / 2, -width / 2], [length / 2, -width / 2], [length / 2, width / 2]]
      .map(([u, v]) => [p.x + co * u - si * v, p.y + si * u + co * v]);
    this.polyline(corners, color, lineWidth, dash);
    this.polyline([[p.x, p.y], [p.x + co * length / 2, p.y + si * length / 2]], color, lineWidth, dash);
  }
  // Leg centres of a shelf of `length` x `width` at pose p, counter-clockwise from (-L/2, -W/2).
  static legCentres(p, length, width) {
    const co = Math.cos(p.yaw), si = Math.sin(p.yaw);
    return [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([a, b]) => {
      const u = a * length / 2, v = b * width / 2; return [p.x + co * u - si * v, p.y + si * u + co * v];
    });
  }
  disc(x, y, radiusPx, fill, stroke) {
    const c = this.ctx, [px, py] = this.toPx(x, y);
    c.beginPath(); c.arc(px, py, radiusPx, 0, 2 * Math.PI);
    if (fill) { c.fillStyle = fill; c.fill(); }
    if (stroke) { c.strokeStyle = stroke; c.lineWidth = 1.5; c.stroke(); }
  }
  circle(x, y, r, color, dash = []) {
    const c = this.ctx, [px, py] = this.toPx(x, y);
    c.strokeStyle = color; c.lineWidth = 1; c.setLineDash(dash); c.beginPath();
    c.arc(px, py, r * this.scale, 0, 2 * Math.PI); c.stroke(); c.setLineDash([]);
  }
  cross(x, y, sizePx, color) {
    const c = this.ctx, [px, py] = this.toPx(x, y);
    c.strokeStyle = color; c.lineWidth = 2; c.beginPath();
    c.moveTo(px - sizePx, py - sizePx); c.lineTo(px + sizePx, py + sizePx);
    c.moveTo(px - sizePx, py + sizePx); c.lineTo(px + sizePx, py - sizePx); c.stroke();
  }
  label(x, y, text, color) {
    const [px, py] = this.toPx(x, y);
    this.ctx.fillStyle = color; this.ctx.font = "12px system-ui, sans-serif"; this.ctx.fillText(text, px + 6, py - 6);
  }
}

// A time plot: series [{name, color, t: [...], v: [...]}] on one axis, a cursor at `cursorT`.
function drawPlot(canvas, title, unit, series, cursorT) {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  const c = canvas.getContext("2d");
  c.clearRect(0, 0, w, h);
  const left = 44, right = 6, top = 14, bottom = 16;
  let t0 = Infinity, t1 = -Infinity, v0 = Infinity, v1 = -Infinity;
  // The time axis spans all samples, so plots of one run line up even where a series has gaps.
  for (const s of series) s.t.forEach((t, k) => {
    t0 = Math.min(t0, t); t1 = Math.max(t1, t);
    const v = s.v[k]; if (v === null || !isFinite(v)) return;
    v0 = Math.min(v0, v); v1 = Math.max(v1, v);
  });
  c.font = "11px system-ui, sans-serif"; c.fillStyle = "#333";
  const heading = unit ? `${title} [${unit}]` : title;
  c.fillText(heading, left, 11);
  if (!isFinite(v0)) { c.fillStyle = "#888"; c.fillText("no data", left, h / 2); return; }
  if (v1 - v0 < 1e-9) { v0 -= 1; v1 += 1; }
  if (t1 - t0 < 1e-9) t1 = t0 + 1;
  const X = (t) => left + (t - t0) / (t1 - t0) * (w - left - right);
  const Y = (v) => top + (v1 - v) / (v1 - v0) * (h - top - bottom);
  c.strokeStyle = "#ccc"; c.lineWidth = 1; c.strokeRect(left, top, w - left - right, h - top - bottom);
  if (v0 < 0 && v1 > 0) { c.beginPath(); c.moveTo(left, Y(0)); c.lineTo(w - right, Y(0)); c.stroke(); }
  c.fillStyle = "#666";
  c.fillText(v1.toPrecision(3), 2, top + 8); c.fillText(v0.toPrecision(3), 2, h - bottom);
  c.fillText(`${t0.toFixed(1)} s`, left, h - 3); c.fillText(`${t1.toFixed(1)} s`, w - right - 40, h - 3);
  let lx = left + c.measureText(heading).width + 16;
  for (const s of series) {
    c.strokeStyle = s.color; c.lineWidth = 1.5; c.beginPath();
    let pen = false;
    s.t.forEach((t, k) => {
      const v = s.v[k];
      if (v === null || !isFinite(v)) { pen = false; return; }
      pen ? c.lineTo(X(t), Y(v)) : c.moveTo(X(t), Y(v)); pen = true;
    });
    c.stroke();
    c.fillStyle = s.color; c.fillText(s.name, lx, 11); lx += 8 + c.measureText(s.name).width;
  }
  if (cursorT !== undefined) {
    c.strokeStyle = "#000"; c.setLineDash([3, 3]); c.beginPath();
    c.moveTo(X(cursorT), top); c.lineTo(X(cursorT), h - bottom); c.stroke(); c.setLineDash([]);
  }
}

// The data a CLI-written page carries (null for the bare page in web/).
function embeddedData() {
  const el = document.getElementById("shelfdock-data");
  const text = el ? el.textContent.trim() : "";
  return text ? JSON.parse(text) : null;
}
