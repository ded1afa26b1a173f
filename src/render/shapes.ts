/**
 * The painter's shapes: filled facets, an arrow with its head (and one at the
 * figure's edge pointing at a point off it), a ring, a cross, and a circle of
 * world radius, each cut to the clip rectangle with its ink recorded.
 */
import { circleVisible, clipPolygon, clipPolyline } from './clip';
import type { P, Painter, StrokeStyle } from './painter';

/**
 * Flat facets (a shaded surface's quads, far to near), each its own fill and
 * opacity, in one save and restore; a facet wholly on the canvas skips the
 * clipper.
 */
export function fillFacets(
  painter: Painter,
  facets: readonly { points: readonly P[]; fill: string; alpha: number }[],
): void {
  const c = painter.ctx;
  const r = painter.clip;
  c.save();
  for (const { points, fill, alpha } of facets) {
    if (points.length < 3) continue;
    let screen: number[][] = points.map((p) => painter.view.toScreen(p));
    const inside = screen.every(
      ([x, y]) => x >= r.minX && x <= r.maxX && y >= r.minY && y <= r.maxY,
    );
    if (!inside) screen = clipPolygon(screen, r);
    if (screen.length < 3) continue;
    c.globalAlpha = alpha;
    c.fillStyle = fill;
    c.beginPath();
    screen.forEach(([x, y], i) => (i === 0 ? c.moveTo(x, y) : c.lineTo(x, y)));
    c.closePath();
    c.fill();
  }
  c.restore();
}

/** An arrow from a to b (world), head sized for the theme. */
export function drawArrow(painter: Painter, a: P, b: P, style: StrokeStyle = {}): void {
  const [ax, ay] = painter.view.toScreen(a);
  const [bx, by] = painter.view.toScreen(b);
  const len = Math.hypot(bx - ax, by - ay);
  if (!(len > 1e-6) || !Number.isFinite(len)) return;
  const c = painter.ctx;
  const head = Math.min(len * 0.5, 6 + painter.sizes.line * 3);
  const ux = (bx - ax) / len;
  const uy = (by - ay) / len;
  c.save();
  painter.applyStroke(style, painter.sizes.line, painter.theme.ink);
  c.beginPath();
  const shaft = [ax, ay, bx - ux * head * 0.6, by - uy * head * 0.6];
  const drawn = clipPolyline(shaft, painter.clip, c) > 0;
  painter.ink.polyline([ax, ay, bx, by], (style.width ?? painter.sizes.line) / 2 + head * 0.2);
  if (drawn) c.stroke();
  if (circleVisible(bx, by, head, painter.clip)) {
    c.setLineDash([]);
    c.fillStyle = style.color ?? painter.theme.ink;
    c.beginPath();
    c.moveTo(bx, by);
    c.lineTo(bx - ux * head - uy * head * 0.45, by - uy * head + ux * head * 0.45);
    c.lineTo(bx - ux * head + uy * head * 0.45, by - uy * head - ux * head * 0.45);
    c.closePath();
    c.fill();
  }
  c.restore();
}

/**
 * Where a point the view leaves out lies: an arrow at the figure's edge,
 * pointing at it, named `text` (P(t) carried off by a wild polynomial, say).
 * Draws nothing and returns false for a point on the figure.
 */
export function drawOffView(painter: Painter, p: P, text: string, color: string): boolean {
  const [x, y] = painter.view.toScreen(p);
  if (!Number.isFinite(x) || !Number.isFinite(y) || painter.visible(p)) return false;
  const { width, height } = painter.view;
  const inset = painter.sizes.label * 0.8;
  const tip = [
    Math.min(Math.max(x, inset), width - inset),
    Math.min(Math.max(y, inset), height - inset),
  ];
  const away = Math.hypot(x - tip[0], y - tip[1]);
  const [ux, uy] = [(x - tip[0]) / away, (y - tip[1]) / away];
  const length = painter.sizes.label * 2;
  const tail = [tip[0] - ux * length, tip[1] - uy * length];
  const world = (s: readonly number[]) => painter.view.toWorld(s, p);
  drawArrow(painter, world(tail), world(tip), { color, width: painter.sizes.line * 1.3 });
  painter.label(text, world(tail), { color, halo: true, bold: true });
  return true;
}

/** A ring of `radius` pixels, e.g. a halo whose size shows a weight. */
export function drawRing(
  painter: Painter,
  p: P,
  radius: number,
  style: StrokeStyle = {},
  fill?: string,
  fillAlpha = 0.2,
): void {
  const [x, y] = painter.view.toScreen(p);
  if (!circleVisible(x, y, radius + 4, painter.clip)) return;
  const c = painter.ctx;
  c.save();
  if (fill) {
    c.globalAlpha = fillAlpha;
    c.fillStyle = fill;
    c.beginPath();
    c.arc(x, y, radius, 0, Math.PI * 2);
    c.fill();
  }
  painter.applyStroke(style, painter.sizes.thin, painter.theme.ink);
  c.beginPath();
  c.arc(x, y, radius, 0, Math.PI * 2);
  c.stroke();
  c.restore();
  inkCircle(painter, x, y, radius, (style.width ?? painter.sizes.thin) / 2);
}

/** A circle's ink: its rim as 32 chords (a label may sit inside a ring). */
function inkCircle(painter: Painter, x: number, y: number, r: number, half: number): void {
  const xy: number[] = [];
  for (let i = 0; i <= 32; i++)
    xy.push(x + r * Math.cos((i * Math.PI) / 16), y + r * Math.sin((i * Math.PI) / 16));
  painter.ink.polyline(xy, half);
}

/** A cross of half-width `size` pixels, e.g. a guess placed on the figure. */
export function drawCross(painter: Painter, p: P, size: number, style: StrokeStyle = {}): void {
  const [x, y] = painter.view.toScreen(p);
  if (!circleVisible(x, y, size + 4, painter.clip)) return;
  const c = painter.ctx;
  c.save();
  painter.applyStroke(style, painter.sizes.line, painter.theme.ink);
  c.beginPath();
  c.moveTo(x - size, y - size);
  c.lineTo(x + size, y + size);
  c.moveTo(x + size, y - size);
  c.lineTo(x - size, y + size);
  c.stroke();
  c.restore();
  painter.ink.disc(x, y, size);
}

/**
 * A circle of world radius `radius` about `center` (2D), e.g. an osculating
 * circle. A circle far larger than the screen is drawn as the arc that shows.
 */
export function drawCircle(
  painter: Painter,
  center: P,
  radius: number,
  style: StrokeStyle = {},
): void {
  const [x, y] = painter.view.toScreen(center);
  const r = Math.abs(painter.view.toScreen([center[0] + radius, center[1]])[0] - x);
  if (!Number.isFinite(r) || !Number.isFinite(x) || !Number.isFinite(y)) return;
  const cx = (painter.clip.minX + painter.clip.maxX) / 2;
  const cy = (painter.clip.minY + painter.clip.maxY) / 2;
  const half =
    Math.hypot(painter.clip.maxX - painter.clip.minX, painter.clip.maxY - painter.clip.minY) / 2;
  const d = Math.hypot(cx - x, cy - y);
  // The screen lies wholly inside the circle, or wholly outside it.
  if (d + half < r || d - half > r) return;
  const c = painter.ctx;
  c.save();
  painter.applyStroke(style, painter.sizes.line, painter.theme.ink);
  c.beginPath();
  if (r < 4 * half) {
    c.arc(x, y, r, 0, Math.PI * 2);
    inkCircle(painter, x, y, r, (style.width ?? painter.sizes.line) / 2);
  } else {
    // Only the arc near the screen: its angular width shrinks as the circle grows.
    const toward = Math.atan2(cy - y, cx - x);
    const spread = Math.min(Math.PI, (2 * half) / r);
    const xy: number[] = [];
    for (let i = 0; i <= 64; i++) {
      const a = toward - spread + (2 * spread * i) / 64;
      xy.push(x + r * Math.cos(a), y + r * Math.sin(a));
    }
    clipPolyline(xy, painter.clip, c);
    painter.ink.polyline(xy, (style.width ?? painter.sizes.line) / 2);
  }
  c.stroke();
  c.restore();
}
