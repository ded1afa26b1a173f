/**
 * Axes and grids: the light grid of a geometry figure (visible lines only,
 * about 60 px apart at any zoom) and the labelled axes of a function plot.
 * Lines are counted by an integer index, never by adding a step to a large
 * coordinate (which stops moving once the step is below its precision).
 */
import { labelWidth } from './labelWidth';
import type { Painter } from './painter';
import { type Bounds, niceStep } from './projection';

/** Most lines a grid or an axis draws, whatever the numbers say. */
const MAX_LINES = 400;

/** The multiples k·step from `min` to `max` (at most MAX_LINES of them). */
export function ticks(min: number, max: number, step: number): number[] {
  if (!(step > 0) || !Number.isFinite(min) || !Number.isFinite(max)) return [];
  const first = Math.ceil(min / step - 1e-9);
  const last = Math.floor(max / step + 1e-9);
  const values: number[] = [];
  for (let k = first; k <= last && values.length < MAX_LINES; k++) values.push(k * step);
  return values;
}

export function drawGrid(painter: Painter): void {
  const v = painter.view;
  if (v.dimension !== 2) return;
  const a = v.toWorld([0, v.height]);
  const b = v.toWorld([v.width, 0]);
  const unitX = v.toScreen([1, 0])[0] - v.toScreen([0, 0])[0];
  const unitY = v.toScreen([0, 0])[1] - v.toScreen([0, 1])[1];
  const c = painter.ctx;
  c.save();
  c.strokeStyle = painter.theme.grid;
  c.lineWidth = 1;
  c.setLineDash([]);
  c.globalAlpha = 1;
  c.beginPath();
  for (const x of ticks(a[0], b[0], niceStep(60 / unitX))) {
    const sx = Math.round(v.toScreen([x, 0])[0]) + 0.5;
    c.moveTo(sx, 0);
    c.lineTo(sx, v.height);
  }
  for (const y of ticks(a[1], b[1], niceStep(60 / unitY))) {
    const sy = Math.round(v.toScreen([0, y])[1]) + 0.5;
    c.moveTo(0, sy);
    c.lineTo(v.width, sy);
  }
  c.stroke();
  c.strokeStyle = painter.theme.axis;
  c.beginPath();
  const axes = gridAxes(painter);
  for (const [x0, y0, x1, y1] of axes) {
    c.moveTo(x0, y0);
    c.lineTo(x1, y1);
    // Drawn here with the figure (headless, export): labels keep off them too.
    painter.ink.rule(x0, y0, x1, y1);
  }
  c.stroke();
  c.restore();
}

/**
 * The x- and y-axes of a geometry figure's grid, as screen segments (those
 * in view): darker than the grid, 1 px wide, across the whole figure.
 */
function gridAxes(painter: Painter): [number, number, number, number][] {
  const v = painter.view;
  if (v.dimension !== 2) return [];
  const [ox, oy] = v.toScreen([0, 0]);
  const axes: [number, number, number, number][] = [];
  if (ox >= 0 && ox <= v.width)
    axes.push([Math.round(ox) + 0.5, 0, Math.round(ox) + 0.5, v.height]);
  if (oy >= 0 && oy <= v.height)
    axes.push([0, Math.round(oy) + 0.5, v.width, Math.round(oy) + 0.5]);
  return axes;
}

/**
 * The grid's axes as lines no label may sit on ("P₀" struck through by the
 * x-axis): the grid is drawn under the canvas, once per view, so the figure's
 * own painter is told where its axes run. Its faint lines may be written over.
 */
export function gridAxesAsInk(painter: Painter): void {
  for (const [x0, y0, x1, y1] of gridAxes(painter)) painter.ink.rule(x0, y0, x1, y1);
}

/** Label every k-th tick (k = 1, 2, 4, 5, 10, …) so that labelled ticks are `room` pixels apart. */
export function labelEvery(spacing: number, room: number): number {
  if (!(spacing > 0)) return 1;
  for (const k of [1, 2, 4, 5, 10, 20, 50, 100]) if (spacing * k >= room) return k;
  return 100;
}

export function drawPlotAxes(
  painter: Painter,
  bounds: Bounds,
  xStep: number,
  yStep: number,
  xName = '',
  yName = '',
): void {
  const c = painter.ctx;
  const v = painter.view;
  const theme = painter.theme;
  const small = theme.sizes.small;
  const xs = ticks(bounds.minX, bounds.maxX, xStep);
  const ys = ticks(bounds.minY, bounds.maxY, yStep);
  c.save();
  c.setLineDash([]);
  c.globalAlpha = 1;
  c.strokeStyle = theme.grid;
  c.lineWidth = 1;
  c.beginPath();
  for (const y of ys) {
    const [x0, sy] = v.toScreen([bounds.minX, y]);
    const [x1] = v.toScreen([bounds.maxX, y]);
    c.moveTo(x0, sy);
    c.lineTo(x1, sy);
  }
  for (const x of xs) {
    const [sx, y0] = v.toScreen([x, bounds.minY]);
    const [, y1] = v.toScreen([x, bounds.maxY]);
    c.moveTo(sx, y0);
    c.lineTo(sx, y1);
  }
  c.stroke();
  c.strokeStyle = theme.axis;
  c.lineWidth = Math.max(1, theme.sizes.thin);
  const axisY = bounds.minY <= 0 && bounds.maxY >= 0 ? 0 : bounds.minY;
  c.beginPath();
  const [ax0, ay] = v.toScreen([bounds.minX, axisY]);
  const [ax1] = v.toScreen([bounds.maxX, axisY]);
  c.moveTo(ax0, ay);
  c.lineTo(ax1, ay);
  const [lx, ly0] = v.toScreen([bounds.minX, bounds.minY]);
  const [, ly1] = v.toScreen([bounds.minX, bounds.maxY]);
  c.moveTo(lx, ly0);
  c.lineTo(lx, ly1);
  c.stroke();
  c.restore();
  // The axes are lines a label must not sit on ("C²" on the zero line reads
  // as a struck-out C); the grid under them is faint and may be written over.
  const half = Math.max(1, theme.sizes.thin) / 2;
  painter.ink.segment(ax0, ay, ax1, ay, half);
  painter.ink.segment(lx, ly0, lx, ly1, half);
  // A negative number with a minus sign, as the formulas write it (not a hyphen).
  const fmt = (n: number) => String(Number(n.toFixed(6))).replace('-', '−');
  const muted = { size: small, color: theme.muted };
  // A number stays at its tick, or is left out where a handle or a curve covers it.
  const tick = { ...muted, fixed: true };
  // A short plot (a phone's strip) keeps every grid line but labels every
  // k-th tick, so no two numbers overlap: each label at its own tick still.
  const xEvery = labelEvery(
    Math.abs(v.toScreen([xStep, 0])[0] - v.toScreen([0, 0])[0]),
    small * (0.62 * Math.max(...xs.map((x) => fmt(x).length), 1) + 0.8),
  );
  const yEvery = labelEvery(
    Math.abs(v.toScreen([0, yStep])[1] - v.toScreen([0, 0])[1]),
    small * 1.4,
  );
  const numbersFrom = painter.labels.length;
  for (const x of xs) {
    if (Math.round(x / xStep) % xEvery !== 0) continue;
    const [sx, sy] = v.toScreen([x, bounds.minY]);
    painter.screenLabel(fmt(x), sx, sy + small * 0.9, { ...tick, align: 'center' });
  }
  // The tick numbers as placed (a number under a curve is left out).
  const numbers = painter.labels.slice(numbersFrom).sort((a, b) => a.x - b.x);
  for (const y of ys) {
    if (Math.round(y / yStep) % yEvery !== 0) continue;
    const [sx, sy] = v.toScreen([bounds.minX, y]);
    painter.screenLabel(fmt(y), sx - small * 0.5, sy, { ...tick, align: 'right' });
  }
  if (xName) {
    // On the row of the tick numbers, midway in the gap between the last two
    // numbers, where it has a space's room on each side (inside the figure:
    // below the numbers it would fall off it). Squeezed beside a number it
    // reads as part of it ("u10" for u and 10, or u₁₀): then it goes above the
    // axis at its right end.
    const nameStyle = { ...muted, size: small * 1.1 };
    const width = labelWidth(painter, xName, nameStyle);
    const [sx, sy] = v.toScreen([bounds.maxX, bounds.minY]);
    const [left, right] = numbers.slice(-2);
    const gap = left && right ? right.x - (left.x + left.width) : 0;
    if (gap >= width + small)
      painter.screenLabel(xName, left.x + left.width + gap / 2, sy + small * 0.9, {
        ...nameStyle,
        align: 'center',
      });
    else
      painter.screenLabel(xName, sx - small * 0.3, v.toScreen([0, axisY])[1] - small * 0.9, {
        ...nameStyle,
        align: 'right',
      });
  }
  if (yName) {
    const [sx, sy] = v.toScreen([bounds.minX, bounds.maxY]);
    painter.screenLabel(yName, sx + small * 0.4, sy - small * 0.2, { ...muted, size: small * 1.1 });
  }
}
